"""robosuite's way of doing things: ElementTree trees edited by ``mjcf_utils``.

Shared by the corpus and the synthetic cases, so that every row naming
robosuite does the same work on its inputs.
"""

from __future__ import annotations

import copy
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path
from types import ModuleType

from benchmarks.harness import OURS, Contender

__all__ = [
    "MISSING_ROBOSUITE",
    "etree_inlined",
    "robosuite_scaled",
    "robosuite_utils",
    "scale_contenders",
]

#: The note of a robosuite row that cannot run.
MISSING_ROBOSUITE = "robosuite is not installed"


def robosuite_utils() -> ModuleType | None:
    """robosuite's ``mjcf_utils`` module, or ``None`` when robosuite is not installed.

    Example:
        >>> robosuite_utils() is None or hasattr(robosuite_utils(), "add_prefix")
        True

    """
    try:
        import robosuite.utils.mjcf_utils as utils
    except ImportError:
        return None
    module: ModuleType = utils
    return module


def _inline(element: ET.Element, here: Path, main_dir: Path) -> None:
    for index in reversed(range(len(element))):
        child = element[index]
        if child.tag != "include":
            _inline(child, here, main_dir)
            continue
        name = child.get("file", "")
        found = main_dir / name if (main_dir / name).is_file() else here / name
        included = ET.parse(found).getroot()
        _inline(included, found.parent, main_dir)
        element[index : index + 1] = list(included)


def etree_inlined(path: Path) -> ET.Element:
    """``path`` parsed by ElementTree, each ``<include>`` replaced by the content of its file.

    robosuite has no include support; this is what its users would write so that
    ``add_prefix`` reaches the included names too. Files are looked up as MuJoCo
    does: beside the main file first, then beside the including file.

    Example:
        >>> import tempfile
        >>> folder = Path(tempfile.mkdtemp())
        >>> part = "<mujoco><worldbody><geom size='1'/></worldbody></mujoco>"
        >>> _ = (folder / "part.xml").write_text(part)
        >>> _ = (folder / "main.xml").write_text("<mujoco><include file='part.xml'/></mujoco>")
        >>> [child.tag for child in etree_inlined(folder / "main.xml")]
        ['worldbody']

    """
    root = ET.parse(path).getroot()
    _inline(root, path.parent, path.parent)
    return root


def robosuite_scaled(root: ET.Element, factor: float = 2.0) -> ET.Element:
    """A copy of ``root`` scaled by robosuite's ``scale_mjcf_model`` (as its objects call it).

    robosuite scales the geoms, bodies, joints and sites under ``<worldbody>`` and
    the meshes of ``<asset>``, in place: hence the ``copy.deepcopy`` first.

    Example:
        >>> root = ET.fromstring("<mujoco><worldbody><body pos='1 0 0'/></worldbody></mujoco>")
        >>> scaled = None if robosuite_utils() is None else robosuite_scaled(root)
        >>> scaled is None or scaled.find("worldbody/body").get("pos") == "2.0 0.0 0.0"
        True

    """
    utils = robosuite_utils()
    assert utils is not None, MISSING_ROBOSUITE
    root = copy.deepcopy(root)
    world = root.find("worldbody")
    if world is None:
        return root
    asset = root.find("asset")
    utils.scale_mjcf_model(
        world,
        asset if asset is not None else ET.Element("asset"),
        factor,
        utils.get_elements,
        worldbody=world,
    )
    return root


def scale_contenders(
    ours: Callable[[], object], robosuite: Callable[[], object] | None
) -> list[Contender]:
    """The two sides of a uniform-scale row (``robosuite`` is ``None`` when it is missing).

    Example:
        >>> [c.name for c in scale_contenders(lambda: None, None)]
        ['mjcf-model', 'robosuite scale_mjcf_model (on a deepcopy)']

    """
    return [
        Contender(OURS, ours, note="scaled(model, 2): every length of the model, masses kept"),
        Contender(
            "robosuite scale_mjcf_model (on a deepcopy)",
            robosuite,
            MISSING_ROBOSUITE,
            note="factor 2: geoms, bodies, joints, sites of the worldbody, meshes",
        ),
    ]
