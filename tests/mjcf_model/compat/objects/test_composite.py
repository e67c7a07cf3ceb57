"""Tests of ``mjcf_model.compat.objects.composite``."""

from __future__ import annotations

import copy
import xml.etree.ElementTree as ET
from typing import Any

import numpy as np
import pytest
import robosuite.models.objects as rs
import robosuite.models.objects.generated_objects as rs_generated
import robosuite.models.objects.objects as rs_objects

from mjcf_model import MjcfValueError
from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_object,
    assert_same_tree,
    assert_same_value,
    assert_view_matches_model,
)

# -- Generated objects (primitives, composites) of ``mjcf_model.compat.objects`` against
#    robosuite.


# -- composite objects ----------------------------------------------------------------


COMPOSITE = {
    "name": "co",
    "total_size": [0.1, 0.1, 0.05],
    "geom_types": ["box", "cylinder", "sphere", "capsule"],
    "geom_sizes": [[0.1, 0.1, 0.01], [0.02, 0.05], [0.03], [0.01, 0.02]],
    "geom_locations": [[0, 0, 0], [0.01, 0.02, 0.03], [0, 0, 0], [0.05, 0.05, 0]],
    "geom_quats": [None, [1, 0, 0, 0], None, None],
    "geom_names": [None, "cyl", None, None],
    "geom_rgbas": [None, [0, 1, 0, 1], None, None],
    "geom_materials": [None, None, "m", None],
    "geom_frictions": [None, [1, 0.1, 0.01], None, None],
    "geom_condims": [None, 4, None, None],
    "rgba": [1, 0, 0, 1],
    "sites": [{"pos": "0 0 0.1", "size": "0.01"}, {"name": "top", "pos": [0, 0, 0.2]}],
    "joints": [{"type": "free"}, {"name": "h", "type": "hinge"}],
}
COMPOSITE_CASES = [
    {},
    {"obj_types": ["all", "collision", "visual", "all"], "locations_relative_to_center": True},
    {"density": [1, 2, 3, 4], "solref": [[0.02, 1]] * 4, "solimp": [[0.9, 0.95, 0.001]] * 4},
    {"joints": "default", "sites": None, "geom_names": None, "rgba": None},
    {"joints": None, "obj_types": "visual", "density": None},
]


@pytest.mark.parametrize("case", range(len(COMPOSITE_CASES)))
def test_composite_matches(case: int) -> None:
    """CompositeObject with per-geom lists, centred locations and broadcasts is robosuite's."""
    kwargs = {**COMPOSITE, **COMPOSITE_CASES[case]}
    theirs = rs.CompositeObject(**copy.deepcopy(kwargs))
    mine = ours.CompositeObject(**copy.deepcopy(kwargs))
    assert_same_object(mine, theirs)
    position, inside = np.array([0.0, 0.0, 0.5]), np.array([0.05, 0.0, 0.46])
    assert mine.in_box(position, inside) == theirs.in_box(position, inside)


RECORDED = ["Bin", "Lid", "ConeObject", "HollowCylinderObject", "HookFrame", "StandWithMount"]
RECORDED += ["PotWithHandlesObject", "HammerObject"]


@pytest.mark.parametrize("cls", RECORDED)
def test_composite_replays_robosuite_subclasses(cls: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Given the arguments and materials robosuite's composites use, the result is theirs."""
    calls: list[dict[str, Any]] = []
    materials: list[Any] = []
    build, append = (
        rs_generated.CompositeObject.__init__,
        rs_objects.MujocoGeneratedObject.append_material,
    )

    def recording_init(self: Any, **kwargs: Any) -> None:
        calls.append(copy.deepcopy(kwargs))
        build(self, **kwargs)

    def recording_append(self: Any, material: Any) -> None:
        materials.append(copy.deepcopy(material))
        append(self, material)

    monkeypatch.setattr(rs_generated.CompositeObject, "__init__", recording_init)
    monkeypatch.setattr(rs_objects.MujocoGeneratedObject, "append_material", recording_append)
    theirs = getattr(rs, cls)("part")
    (kwargs,) = calls
    mine = ours.CompositeObject(**kwargs)
    for material in materials:
        mine.append_material(material)
    assert_same_tree(mine.get_obj(), theirs.get_obj())
    assert_same_tree(mine.asset, theirs.asset)
    for name in ("root_body", "bodies", "joints", "sites", "contact_geoms", "visual_geoms"):
        assert_same_value(getattr(mine, name), getattr(theirs, name), name)
    assert_view_matches_model(mine)


def test_composite_numpy_density() -> None:
    """A numpy density (robosuite: TypeError) works like a float; per-geom solimp stays per geom."""
    kwargs = {**COMPOSITE, "density": np.float64(100.0)}
    with pytest.raises(TypeError):
        rs.CompositeObject(**copy.deepcopy(kwargs))
    mine = ours.CompositeObject(**copy.deepcopy(kwargs))
    reference = ours.CompositeObject(**copy.deepcopy(COMPOSITE))
    assert ET.tostring(mine.get_obj()) == ET.tostring(reference.get_obj())
    per_geom = [[0.9, 0.95, 0.001], [0.8, 0.9, 0.01], [0.9, 0.95, 0.001], [0.9, 0.95, 0.001]]
    typed = ours.CompositeObject(**{**COMPOSITE, "solimp": per_geom})
    solimps = [g.get("solimp") for g in typed.get_obj().iter("geom") if g.get("solimp")]
    assert solimps == ["0.9 0.95 0.001", "0.8 0.9 0.01", "0.9 0.95 0.001", "0.9 0.95 0.001"]


@pytest.mark.parametrize("scale", [2, [1, 2, 3]])
def test_composite_scaling_matches(scale: Any) -> None:
    """set_scale on a composite scales its geoms as robosuite's does; sites stay."""
    theirs = rs.CompositeObject(**copy.deepcopy(COMPOSITE))
    mine = ours.CompositeObject(**copy.deepcopy(COMPOSITE))
    theirs.set_scale(scale)
    mine.set_scale(scale)
    assert_same_object(mine, theirs)


@pytest.mark.parametrize("geom_type", ["mesh", "plane", "hfield"])
def test_composite_unsupported_geom_type_raises(geom_type: str) -> None:
    """A geom type robosuite cannot place raises there (an Exception) and a MjcfValueError here."""
    kwargs = {**COMPOSITE, "geom_types": [geom_type, "cylinder", "sphere", "capsule"]}
    with pytest.raises(Exception, match="unsupported geom type"):
        rs.CompositeObject(**kwargs)
    with pytest.raises(MjcfValueError, match=f"unsupported geom type '{geom_type}'"):
        ours.CompositeObject(**kwargs)
