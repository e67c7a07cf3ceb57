"""Cases over the corpus: load + prefix + dump, load + dump, prefix alone, scale alone."""

from __future__ import annotations

import copy
import warnings
import xml.etree.ElementTree as ET
from collections.abc import Callable, Sequence
from pathlib import Path

from benchmarks.etree_path import (
    MISSING_ROBOSUITE,
    etree_inlined,
    robosuite_scaled,
    robosuite_utils,
    scale_contenders,
)
from benchmarks.harness import OURS, Case, Contender

__all__ = ["corpus_cases"]

#: What mjcf-model's corpus rows that rename do with ``<include>``.
_INLINED = "includes inlined (load(..., inline_includes=True)), as on the robosuite row"
#: What the robosuite rows do with ``<include>`` (robosuite itself has no include support).
_SPLICED = "includes inlined: each replaced by its file's elements (etree_inlined)"


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


def _scales(tree: ET.Element) -> bool:
    try:
        robosuite_scaled(tree)
    except Exception:
        return False
    return True


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


def _everyone(_name: str) -> bool:
    return True


def corpus_cases(
    files: Sequence[Path], peer_wanted: Callable[[str], bool] = _everyone
) -> list[Case]:
    """The corpus cases, on the files every available contender can read.

    ``peer_wanted`` tells which of the slow peers (dm_control, MjSpec) to set up at all:
    finding the files they read costs as much as measuring them.
    """
    from mjcf_model import prefixed, scaled
    from mjcf_model.serializers import dumps, load

    utils = robosuite_utils()
    common = list(files)
    peers: dict[str, Callable[[Path], object]] = {}
    try:
        import dm_control.mjcf  # noqa: F401

        peers["dm_control.mjcf"] = _dm_control
    except ImportError:
        pass
    peers["MjSpec"] = _mjspec
    peers = {name: work for name, work in peers.items() if peer_wanted(f"{name} (load")}
    for work in peers.values():
        common = _working(common, work)

    def ours_all(path: Path) -> str:
        return dumps(prefixed(load(path, inline_includes=True), "p_"))

    def robosuite_all(path: Path) -> str:
        root = etree_inlined(path)
        utils.add_prefix(root, "p_")  # type: ignore[union-attr]
        return ET.tostring(root, encoding="unicode")

    def lxml_io(path: Path) -> bytes:
        import lxml.etree

        return bytes(lxml.etree.tostring(lxml.etree.parse(str(path))))

    inputs = f"{len(common)} corpus files (sum over files)"
    cases = [
        Case(
            "corpus: load + prefix + dump",
            [
                Contender(OURS, _each(common, ours_all), note=_INLINED),
                Contender(
                    "robosuite (ElementTree + add_prefix)",
                    _each(common, robosuite_all) if utils else None,
                    MISSING_ROBOSUITE,
                    note=_SPLICED,
                ),
                *[
                    Contender(
                        f"{name} (load + attach + write)",
                        _each(common, work),
                        note="includes read by the tool itself",
                    )
                    for name, work in peers.items()
                ],
                Contender("lxml parse + serialize (floor, no prefix)", _each(common, lxml_io)),
            ],
            inputs,
        ),
        Case(
            "corpus: load",
            [
                Contender(OURS, _each(common, load)),
                Contender("ElementTree parse", _each(common, ET.parse)),
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
    trees = [etree_inlined(p) for p in common]
    cases.append(
        Case(
            "corpus: prefix alone",
            [
                Contender(OURS, lambda: [prefixed(m, "p_") for m in models], note=_INLINED),
                Contender(
                    "robosuite add_prefix (in place)",
                    (lambda: [utils.add_prefix(copy.deepcopy(t), "p_") for t in trees])
                    if utils
                    else None,
                    MISSING_ROBOSUITE,
                    note=_SPLICED + "; on a deepcopy",
                ),
                Contender(
                    "ElementTree deepcopy alone (part of the line above)",
                    lambda: [copy.deepcopy(t) for t in trees],
                ),
            ],
            inputs,
        )
    )
    pairs = [(m, t) for m, t in zip(models, trees, strict=True) if utils is None or _scales(t)]
    cases.append(
        Case(
            "corpus: uniform scale alone",
            scale_contenders(
                lambda: [scaled(m, 2) for m, _ in pairs],
                (lambda: [robosuite_scaled(t) for _, t in pairs]) if utils else None,
            ),
            f"{len(pairs)} corpus files robosuite can scale",
        )
    )
    return cases
