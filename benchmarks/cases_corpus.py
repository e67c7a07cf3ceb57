"""Cases over the corpus: load + prefix + dump, load + dump, prefix alone, scale alone."""

from __future__ import annotations

import copy
import warnings
import xml.etree.ElementTree as ET
from collections.abc import Callable, Sequence
from pathlib import Path

from benchmarks.harness import OURS, Case, Contender

__all__ = ["corpus_cases"]


def _robosuite_utils() -> object | None:
    try:
        import robosuite.utils.mjcf_utils as utils
    except ImportError:
        return None
    return utils


def _each(files: Sequence[Path], work: Callable[[Path], object]) -> Callable[[], object]:
    def run() -> object:
        for path in files:
            work(path)
        return None

    return run


def _dm_control(path: Path) -> str:
    from dm_control import mjcf

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        model = mjcf.from_path(str(path))
        root = mjcf.RootElement(model="world")
        root.attach(model)
        return str(root.to_xml_string())


def _mjspec(path: Path) -> str:
    import mujoco

    spec = mujoco.MjSpec.from_file(str(path))
    parent = mujoco.MjSpec()
    parent.attach(spec, prefix="p_", frame=parent.worldbody.add_frame())
    return str(parent.to_xml())


def _working(files: Sequence[Path], work: Callable[[Path], object]) -> list[Path]:
    """The files a peer handles at all (dm_control lags MuJoCo's schema)."""
    fine = []
    for path in files:
        try:
            work(path)
        except Exception:
            continue
        fine.append(path)
    return fine


def corpus_cases(files: Sequence[Path]) -> list[Case]:
    """The corpus cases, on the files every available contender can read."""
    from mjcf_model import prefixed, scaled
    from serializers import dumps, load

    utils = _robosuite_utils()
    common = list(files)
    peers: dict[str, Callable[[Path], object]] = {}
    try:
        import dm_control.mjcf  # noqa: F401

        peers["dm_control.mjcf"] = _dm_control
    except ImportError:
        pass
    peers["MjSpec"] = _mjspec
    for work in peers.values():
        common = _working(common, work)

    def ours_all(path: Path) -> str:
        return dumps(prefixed(load(path, inline_includes=True), "p_"))

    def robosuite_all(path: Path) -> str:
        root = ET.parse(path).getroot()
        utils.add_prefix(root, "p_")  # type: ignore[union-attr]
        return ET.tostring(root, encoding="unicode")

    def lxml_io(path: Path) -> bytes:
        import lxml.etree

        return bytes(lxml.etree.tostring(lxml.etree.parse(str(path))))

    missing_robosuite = "robosuite is not installed"
    inputs = f"{len(common)} corpus files (sum over files)"
    cases = [
        Case(
            "corpus: load + prefix + dump",
            [
                Contender(OURS, _each(common, ours_all)),
                Contender(
                    "robosuite (ElementTree + add_prefix)",
                    _each(common, robosuite_all) if utils else None,
                    missing_robosuite,
                ),
                *[
                    Contender(f"{name} (load + attach + write)", _each(common, work))
                    for name, work in peers.items()
                ],
                Contender("lxml parse + serialize (floor, no prefix)", _each(common, lxml_io)),
            ],
            inputs,
        ),
        Case(
            "corpus: load + dump",
            [
                Contender(OURS, _each(common, lambda p: dumps(load(p)))),
                Contender(
                    "ElementTree parse + tostring",
                    _each(common, lambda p: ET.tostring(ET.parse(p).getroot(), encoding="unicode")),
                ),
                Contender("lxml parse + serialize", _each(common, lxml_io)),
            ],
            inputs,
        ),
    ]
    models = [load(p, inline_includes=True) for p in common]
    trees = [ET.parse(p).getroot() for p in common]
    cases.append(
        Case(
            "corpus: prefix alone",
            [
                Contender(OURS, lambda: [prefixed(m, "p_") for m in models]),
                Contender(
                    "robosuite add_prefix (in place)",
                    (lambda: [utils.add_prefix(copy.deepcopy(t), "p_") for t in trees])
                    if utils
                    else None,  # type: ignore[union-attr]
                    missing_robosuite,
                ),
                Contender(
                    "ElementTree deepcopy alone (part of the line above)",
                    lambda: [copy.deepcopy(t) for t in trees],
                ),
            ],
            inputs,
        )
    )

    def robosuite_scale(tree: ET.Element) -> None:
        tree = copy.deepcopy(tree)
        world = tree.find("worldbody")
        asset = tree.find("asset")
        if world is None:
            return
        utils.scale_mjcf_model(  # type: ignore[union-attr]
            world,
            asset if asset is not None else ET.Element("asset"),
            2.0,
            utils.get_elements,
            worldbody=world,  # type: ignore[union-attr]
        )

    scalable = [i for i, t in enumerate(trees) if utils is None or _working([t], robosuite_scale)]  # type: ignore[list-item]
    cases.append(
        Case(
            "corpus: uniform scale alone",
            [
                Contender(OURS, lambda: [scaled(models[i], 2) for i in scalable]),
                Contender(
                    "robosuite scale_mjcf_model (on a deepcopy)",
                    (lambda: [robosuite_scale(trees[i]) for i in scalable]) if utils else None,
                    missing_robosuite,
                ),
            ],
            f"{len(scalable)} corpus files robosuite can scale",
        )
    )
    return cases
