"""``CompositeBodyObject`` and ``HingedBoxObject`` of ``mjcf_model.compat`` against robosuite."""

from __future__ import annotations

import copy
import xml.etree.ElementTree as ET
from collections.abc import Callable
from typing import Any

import mujoco
import numpy as np
import pytest
import robosuite.models.objects as rs
from robosuite.utils.mjcf_utils import CustomMaterial as TheirMaterial

from mjcf_model import MjcfLookupError, MjcfValueError
from mjcf_model.compat import CustomMaterial
from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_composite,
    composite_world,
    text_of,
)

#: Each library with its own ``CustomMaterial``.
LIBRARIES = {"robosuite": (rs, TheirMaterial), "ours": (ours, CustomMaterial)}

_WOOD = {
    "texture": "WoodGreen",
    "tex_name": "green",
    "mat_name": "green_mat",
    "tex_attrib": {"type": "cube"},
    "mat_attrib": {"texrepeat": "2 2", "specular": "0.3"},
}
_METAL = {"texture": "Metal", "tex_name": "metal", "mat_name": "metal_mat", "shared": True}

Case = Callable[[Any, Any], dict[str, Any]]


def _two_boxes(m: Any, material: Any) -> dict[str, Any]:
    boxes = [m.BoxObject("a", size=[0.02, 0.03, 0.04]), m.BoxObject("b", size=[0.01] * 3)]
    return {"objects": boxes, "object_locations": [[0, 0, 0], [0.1, 0, 0]]}


def _placed(m: Any, material: Any) -> dict[str, Any]:
    boxes = [
        m.BoxObject("base", size=[0.05, 0.04, 0.02], rgba=[0, 1, 0, 1]),
        m.BoxObject("lid", size=[0.05, 0.04, 0.005], material=material(**_WOOD)),
        m.BoxObject("knob", size=[0.01, 0.01, 0.01], material=material(**_METAL)),
    ]
    return {
        "objects": boxes,
        "object_locations": [[0, 0, 0], [0.0, 0.0, 0.025], [-0.03, -0.02, 0.015]],
        "object_quats": [None, [0.707, 0, 0.707, 0], np.array([1.0, 0.0, 0.0, 0.0])],
        "object_parents": [None, "base_main", "lid_main"],
        "joints": [{"type": "slide", "axis": "1 0 0"}, {"name": "h", "type": "hinge"}, {}],
        "body_joints": {
            "lid_main": [{"type": "hinge", "axis": "0 1 0", "pos": "0.05 0 -0.005"}],
            "knob_main": "default",
            "base_main": [{"name": "spin", "type": "hinge"}, {"type": "slide", "damping": 0.1}],
        },
        "sites": [{"pos": "0 0 0.1", "size": "0.01"}, {"name": "top", "pos": [0, 0, 0.2]}, {}],
    }


def _corner(m: Any, material: Any) -> dict[str, Any]:
    return {
        "objects": (m.BoxObject("a", size=[0.02, 0.03, 0.04]), m.BallObject("b", size=[0.02])),
        "object_locations": [[0, 0, 0], [0.06, 0.01, 0.0]],
        "total_size": [0.1, 0.1, 0.05],
        "locations_relative_to_corner": True,
        "joints": None,
    }


def _sized(m: Any, material: Any) -> dict[str, Any]:
    kwargs = _corner(m, material)
    return {**kwargs, "locations_relative_to_corner": False, "joints": "default"}


def _negative(m: Any, material: Any) -> dict[str, Any]:
    """Children at negative x and y: ``max(x, y)`` (not a norm) decides the radius."""
    parts = [m.CylinderObject("c", size=[0.02, 0.03]), m.CapsuleObject("p", size=[0.01, 0.02])]
    return {
        "objects": parts,
        "object_locations": [[-0.2, -0.3, -0.1], [0.05, -0.4, 0.2]],
        "object_parents": ["root", "root"],
    }


def _single(m: Any, material: Any) -> dict[str, Any]:
    box = m.BoxObject("only", size=[0.03, 0.02, 0.01], material=material(**_WOOD))
    return {"objects": box, "object_locations": [[0.01, 0.02, 0.03]], "object_quats": None}


def _shared_twice(m: Any, material: Any) -> dict[str, Any]:
    """The same shared material in two children: the asset is merged once."""
    boxes = [m.BoxObject(n, size=[0.02] * 3, material=material(**_METAL)) for n in ("x", "y")]
    return {
        "objects": boxes,
        "object_locations": np.array([[0, 0, 0], [0, 0, 0.04]]),
        "body_joints": {None: [{"type": "slide", "axis": "0 0 1"}]},
    }


def _mixed(m: Any, material: Any) -> dict[str, Any]:
    """An XML object, a composite, and a hinged box nested as children."""
    composite = m.CompositeObject(
        "plate",
        total_size=[0.05, 0.05, 0.005],
        geom_types=["box"],
        geom_sizes=[[0.05, 0.05, 0.005]],
        geom_locations=[[0, 0, 0]],
    )
    return {
        "objects": [composite, m.CanObject("can"), m.HingedBoxObject("hb", use_texture=False)],
        "object_locations": [[0, 0, 0], [0.02, 0.0, 0.08], [0, 0, 0.01]],
        "object_parents": [None, "plate_root", "plate_root"],
        "total_size": [0.1, 0.1, 0.15],
        "locations_relative_to_corner": True,
    }


CASES: dict[str, Case] = {
    "two_boxes": _two_boxes,
    "placed": _placed,
    "corner": _corner,
    "sized": _sized,
    "negative": _negative,
    "single": _single,
    "shared_twice": _shared_twice,
    "mixed": _mixed,
}


def _build(library: str, case: str, name: str = "cb") -> tuple[Any, dict[str, Any]]:
    module, material = LIBRARIES[library]
    kwargs = CASES[case](module, material)
    return module.CompositeBodyObject(name, **kwargs), kwargs


def _specs(kwargs: dict[str, Any]) -> tuple[Any, Any]:
    """The joint and body joint arguments, as the constructor left them (it names them)."""
    return kwargs.get("joints"), kwargs.get("body_joints")


def test_hinged_box_golden() -> None:
    """HingedBoxObject("hb") is robosuite's: body, assets, names, offsets (golden check 10)."""
    theirs, mine = rs.HingedBoxObject("hb"), ours.HingedBoxObject("hb")
    assert_same_composite(mine, theirs)
    assert ET.tostring(mine.get_obj()) == ET.tostring(theirs.get_obj())
    assert ET.tostring(mine.asset) == ET.tostring(theirs.asset)
    assert mine.bodies == ["hb_root", "hb_box1_main", "hb_box2_main", "hb_hinge_main"]
    assert mine.joints == ["hb_joint0", "hb_box_hinge"]
    assert [c.get("name") for c in mine.asset] == [
        *["hb_box1_tex", "hb_box1_mat", "hb_box2_tex", "hb_box2_mat"]
    ]
    assert mine.horizontal_radius == theirs.horizontal_radius == np.linalg.norm([0.025, 0.025])


def test_horizontal_radius_quirk() -> None:
    """As robosuite's, the radius adds max(x, y) of a child's position, not its distance."""
    theirs, mine = _build("robosuite", "negative")[0], _build("ours", "negative")[0]
    assert mine.horizontal_radius == theirs.horizontal_radius == pytest.approx(0.05 + 0.01)
    assert mine.get_bounding_box_half_size()[0] == pytest.approx(0.06)  # the parts reach 0.42


HINGED_CASES = [
    {"use_texture": False},
    {"box1_size": (0.04, 0.03, 0.02), "box2_size": (0.03, 0.03, 0.01)},
    {"box1_size": [0.02, 0.05, 0.03], "box2_size": np.array([0.05, 0.05, 0.04])},
    {"box1_size": (0.03, 0.03, 0.01), "box2_size": (0.01, 0.02, 0.03), "use_texture": False},
]


@pytest.mark.parametrize("case", range(len(HINGED_CASES)))
def test_hinged_box_arguments_match(case: int) -> None:
    """Other box sizes and colours instead of wood give robosuite's object."""
    kwargs = HINGED_CASES[case]
    theirs, mine = rs.HingedBoxObject("hinged", **kwargs), ours.HingedBoxObject("hinged", **kwargs)
    assert_same_composite(mine, theirs)
    assert (mine.box1_rgba, mine.box2_rgba) == (theirs.box1_rgba, theirs.box2_rgba)


@pytest.mark.parametrize("case", CASES)
def test_composite_body_matches(case: str) -> None:
    """Composites of robosuite's objects and of this library's give the same object."""
    theirs, their_kwargs = _build("robosuite", case)
    mine, my_kwargs = _build("ours", case)
    assert_same_composite(mine, theirs)
    assert _specs(my_kwargs) == _specs(their_kwargs)  # unnamed joints named in the caller's dicts


@pytest.mark.parametrize("case", ["placed", "corner", "negative"])
def test_composite_body_of_robosuite_children(case: str) -> None:
    """With robosuite's own objects as children, this library's composite is robosuite's."""
    theirs = _build("robosuite", case)[0]
    kwargs = CASES[case](rs, TheirMaterial)
    assert_same_composite(ours.CompositeBodyObject("cb", **kwargs), theirs)


def test_children_are_left_unchanged() -> None:
    """Unlike robosuite's, the children keep their joints, place and names (their models)."""
    kwargs = _placed(ours, CustomMaterial)
    before = [(text_of(o.get_obj()), text_of(o.asset), o.joints) for o in kwargs["objects"]]
    ours.CompositeBodyObject("cb", **kwargs)
    after = [(text_of(o.get_obj()), text_of(o.asset), o.joints) for o in kwargs["objects"]]
    assert after == before
    their_lid = _build("robosuite", "placed")[1]["objects"][1]
    assert their_lid.get_obj().get("name") == "cb_lid_main"  # robosuite renamed its child


@pytest.mark.parametrize("scale", [2, [1, 2, 0.5]])
def test_composite_body_scaling_matches(scale: Any) -> None:
    """set_scale scales the children's geoms and body positions as robosuite does."""
    theirs, mine = rs.HingedBoxObject("hb"), ours.HingedBoxObject("hb")
    theirs.set_scale(scale)
    mine.set_scale(scale)
    assert_same_composite(mine, theirs)


def test_isinstance_robosuite_twins() -> None:
    """Instances pass robosuite's isinstance checks for their twins and bases."""
    mine, hinged = _build("ours", "two_boxes")[0], ours.HingedBoxObject("hb")
    for base in (rs.CompositeBodyObject, rs.MujocoGeneratedObject, rs.MujocoObject):
        assert isinstance(mine, base) and isinstance(hinged, base)
    assert isinstance(hinged, rs.HingedBoxObject) and not isinstance(mine, rs.HingedBoxObject)
    assert not isinstance(mine, rs.CompositeObject)


def _names(model: Any, kind: Any, count: int) -> list[str]:
    return [mujoco.mj_id2name(model, kind, i) for i in range(count)]


def test_world_with_composites_compiles() -> None:
    """A robosuite world with the hinged box and a composite compiles and steps as robosuite's."""
    runs = []
    for library in ("robosuite", "ours"):
        module, _ = LIBRARIES[library]
        objects = [module.HingedBoxObject("hb"), _build(library, "two_boxes")[0]]
        objects.append(_build(library, "negative", name="neg")[0])
        objects[1].get_obj().set("pos", "0.3 0 0.2")
        world = composite_world(objects)
        model = world.get_model(mode="mujoco")
        data = mujoco.MjData(model)
        for _ in range(50):
            mujoco.mj_step(model, data)
        runs.append((world, model, data))
    (their_world, their_model, their_data), (my_world, my_model, my_data) = runs
    assert text_of(my_world.root) == text_of(their_world.root)
    for kind, count in ((mujoco.mjtObj.mjOBJ_BODY, "nbody"), (mujoco.mjtObj.mjOBJ_JOINT, "njnt")):
        mine = _names(my_model, kind, getattr(my_model, count))
        assert mine == _names(their_model, kind, getattr(their_model, count))
    hinge = mujoco.mj_name2id(my_model, mujoco.mjtObj.mjOBJ_JOINT, "hb_box_hinge")
    assert hinge >= 0 and my_model.jnt_type[hinge] == mujoco.mjtJoint.mjJNT_HINGE
    np.testing.assert_array_equal(my_data.qpos, their_data.qpos)
    assert np.all(np.isfinite(my_data.qpos))


ERROR_CASES: list[tuple[dict[str, Any], type[Exception], type[Exception]]] = [
    ({"objects": "box"}, ValueError, MjcfValueError),
    ({"object_parents": ["nowhere"]}, AssertionError, MjcfLookupError),
    ({"locations_relative_to_corner": True}, AssertionError, MjcfValueError),
    ({"body_joints": {"nowhere": "default"}}, AssertionError, MjcfLookupError),
]


@pytest.mark.parametrize("case", range(len(ERROR_CASES)))
def test_bad_arguments_raise(case: int) -> None:
    """Where robosuite asserts, a MjcfValueError or MjcfLookupError says what was wrong."""
    change, their_error, my_error = ERROR_CASES[case]
    for module, error in ((rs, their_error), (ours, my_error)):
        kwargs = {"objects": [module.BoxObject("a", size=[0.02] * 3)], "object_locations": [None]}
        with pytest.raises(error):
            module.CompositeBodyObject("cb", **(kwargs | copy.deepcopy(change)))


def test_parent_inside_a_child_is_a_key_error() -> None:
    """A parent body that is not a child's root body: KeyError in both (no offsets known)."""
    for module in (rs, ours):
        inner = module.CompositeBodyObject(
            "in", objects=[module.BoxObject("a", size=[0.02] * 3)], object_locations=[[0, 0, 0]]
        )
        with pytest.raises(KeyError):
            module.CompositeBodyObject(
                "cb",
                objects=[inner, module.BoxObject("b", size=[0.01] * 3)],
                object_locations=[[0, 0, 0], [0, 0, 0.1]],
                object_parents=[None, "in_a_main"],
            )
