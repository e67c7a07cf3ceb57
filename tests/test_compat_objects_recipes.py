"""The composite recipes (``Bin``, ``Lid``, ``ConeObject``, ``HammerObject``...) against robosuite.

Each case builds robosuite's object and ours from the same arguments and compares
the body, the assets, every property, the recipe's own attributes and the
arguments it gives ``CompositeObject``; hypothesis draws the parameters over their
ranges; MuJoCo compiles and steps a world holding all nine.
"""

from __future__ import annotations

import copy
import inspect
from typing import Any

import mujoco
import numpy as np
import pytest
import robosuite.models.objects as rs
from hypothesis import given
from hypothesis import strategies as st
from robosuite.models.world import MujocoWorldBase
from robosuite.utils.mjcf_utils import CustomMaterial as TheirMaterial

from mjcf_model import MjcfValueError
from mjcf_model.bridge.compare import model_differences
from mjcf_model.compat import CustomMaterial
from mjcf_model.compat import objects as ours
from tests.conftest import PER_CLASS
from tests.support.compat_objects import assert_same_object, assert_same_value, text_of
from tests.test_compat_objects_composite_body import _world as composite_world
from tests.test_compat_objects_composite_body import assert_same_composite

#: A material given to cones and hollow cylinders, in each library's class.
_STEEL = {
    "texture": "SteelScratched",
    "tex_name": "steel",
    "mat_name": "steel_mat",
    "tex_attrib": {"type": "cube"},
    "mat_attrib": {"texrepeat": "3 3", "specular": "0.4"},
}

#: The arguments robosuite's environments build these objects with.
TOOL_HANG_STAND = {
    "size": (12.0 / 100.0, 14.0 / 100.0, 16.0 / 100.0),
    "mount_location": (0.0, 4.5 / 100.0),
    "mount_width": 1.2 / 100.0,
    "wall_thickness": 0.1 / 100.0,
    "base_thickness": 1 / 100.0,
    "initialize_on_side": False,
    "add_hole_vis": True,
    "density": 50000.0,
    "solref": (0.02, 1.0),
    "solimp": (0.998, 0.998, 0.001),
}
TOOL_HANG_FRAME = {
    "frame_length": 9.5 / 100.0,
    "frame_height": 18.0 / 100.0,
    "frame_thickness": 0.75 / 100.0,
    "hook_height": 1.2 / 100.0,
    "grip_location": ((9.0 - 3.0) / 100.0) - (0.75 / 200.0),
    "grip_size": (2.54 / 200.0, 6.35 / 200.0),
    "tip_size": (2.54 / 200.0, 0.2 / 200.0, 0.65 / 200.0, 1.905 / 100.0),
    "density": 500.0,
    "solref": (0.02, 1.0),
    "solimp": (0.998, 0.998, 0.001),
}
TOOL_HANG_WRENCH = {
    "handle_size": (16.5 / 200.0, 1.75 / 200.0, 0.32 / 200.0),
    "outer_radius_1": 3.5 / 200.0,
    "inner_radius_1": 2.1 / 200.0,
    "height_1": 0.7 / 200.0,
    "outer_radius_2": 3.0 / 200.0,
    "inner_radius_2": 2.0 / 200.0,
    "height_2": 0.7 / 200.0,
    "ngeoms": 8,
    "grip_size": (3 / 200.0, 8.0 / 200.0),
    "density": 2000.0,
    "solref": (0.02, 1.0),
    "solimp": (0.998, 0.998, 0.001),
    "friction": (0.95, 0.3, 0.1),
}
TRANSPORT_PAYLOAD = {
    "handle_radius": 0.015,
    "handle_length": 0.20,
    "handle_density": 150.0,
    "handle_friction": 4.0,
    "head_density_ratio": 1.5,
}

#: Cases per class: the defaults, every option, and the arguments environments use.
CASES: dict[str, list[dict[str, Any]]] = {
    "Bin": [
        {},
        {"bin_size": (0.3, 0.3, 0.15), "density": 10000.0},
        {"use_texture": False, "transparent_walls": False, "rgba": (0.5, 0.5, 0.5, 1)},
        {"transparent_walls": False, "friction": (1, 0.1, 0.01), "density": 500},
    ],
    "Lid": [
        {},
        {"lid_size": (0.3, 0.3, 0.01)},
        {"transparent": False, "use_texture": False, "density": 300, "friction": [2, 0, 0]},
        {"transparent": False, "handle_size": (0.05, 0.02, 0.01)},
    ],
    "ConeObject": [
        {},
        {"material": _STEEL, "ngeoms": 5},
        {"ngeoms": 9, "use_box": True},
        {"ngeoms": 4, "rgba": (1, 0, 0, 1), "friction": (1, 0.1, 0.01), "density": 10},
        {"outer_radius": 0.05, "inner_radius": 0.001, "height": 0.1, "solref": (0.01, 0.5)},
    ],
    "HollowCylinderObject": [
        {},
        {"material": _STEEL, "make_half": True},
        {"make_half": True},
        {"ngeoms": 5, "rgba": (0, 0, 1, 1), "friction": (2, 0.1, 0.1)},
        {"ngeoms": 12, "make_half": True, "height": 0.01, "solimp": (0.99, 0.99, 0.001)},
    ],
    "HammerObject": [
        {},
        {"handle_shape": "cylinder"},
        TRANSPORT_PAYLOAD,
        {"use_texture": False, "rgba_head": (1, 1, 0, 1), "handle_radius": [0.01, 0.011]},
        {"handle_shape": "cylinder", "use_texture": False, "rgba_handle": (0, 0, 0, 1)},
    ],
    "HookFrame": [
        {},
        {"hook_height": 0.03},
        {"grip_location": 0.05, "grip_size": (0.01, 0.03)},
        {"grip_location": 0.05},
        {"tip_size": (0.01, 0.001, 0.005, 0.05), "friction": (1, 0.1, 0.1)},
        TOOL_HANG_FRAME,
        {**TOOL_HANG_FRAME, "use_texture": False, "rgba": (1, 0, 0, 1)},
    ],
    "StandWithMount": [
        {},
        TOOL_HANG_STAND,
        {"add_hole_vis": True, "mount_location": (0.05, -0.02), "use_texture": False},
        {"initialize_on_side": False, "friction": (1, 0.1, 0.1), "density": 10},
    ],
    "PotWithHandlesObject": [
        {},
        {"solid_handle": True},
        {"use_texture": False, "rgba_body": (1, 1, 0, 1), "rgba_handle_1": [0, 1, 1, 1]},
        {"density": 1000.0, "handle_friction": 2.0, "body_half_size": (0.05, 0.08, 0.04)},
    ],
    "RatchetingWrenchObject": [
        {},
        TOOL_HANG_WRENCH,
        {"ngeoms": 12, "friction": (1, 0.1, 0.1), "density": 100},
    ],
}

#: Each recipe's own attributes, compared beside the properties every object has.
EXTRAS: dict[str, tuple[str, ...]] = {
    "Bin": ("base_geoms", "bin_size", "wall_thickness", "transparent_walls", "bin_mat_name"),
    "Lid": ("handle_geoms", "lid_size", "handle_size", "lid_mat_name"),
    "ConeObject": ("n", "r1", "r2", "height", "unit_height", "unit_r", "use_box", "has_material"),
    "HollowCylinderObject": (
        "n", "unit_box_width", "unit_box_height", "unit_box_depth", "int_r", "make_half",
    ),
    "HammerObject": (
        "handle_geoms", "head_geoms", "face_geoms", "claw_geoms", "all_geoms", "handle_radius",
        "handle_length", "handle_density", "handle_friction", "head_halfsize", "rgba_handle",
        "rgba_head", "rgba_face", "rgba_claw", "handle_shape",
    ),
    "HookFrame": ("init_quat", "size", "grip_size", "tip_size", "mat_name", "tip_mat_name"),
    "StandWithMount": ("base_geoms", "init_quat", "size", "mount_location", "mat_name"),
    "PotWithHandlesObject": (
        "handle0_geoms", "handle1_geoms", "handle_geoms", "handle_distance", "pot_base",
        "total_size", "rgba_body", "rgba_handle_0", "rgba_handle_1",
    ),
    "RatchetingWrenchObject": ("handle_size", "outer_radii", "inner_radii", "heights", "grip_size"),
}  # fmt: skip

#: Classes made of other objects' bodies (the others are ``CompositeObject`` recipes).
_BODY_RECIPES = {"RatchetingWrenchObject"}


def _pair(cls: str, kwargs: dict[str, Any], seed: int = 0) -> tuple[Any, Any]:
    """Our object and robosuite's from the same arguments (a hammer from generators of ``seed``).

    A ``material`` given as a dict of ``CustomMaterial`` arguments becomes each library's own.
    """
    made = []
    for module, material_class in ((ours, CustomMaterial), (rs, TheirMaterial)):
        arguments = copy.deepcopy(kwargs)
        if cls == "HammerObject":
            arguments["rng"] = np.random.default_rng(seed)
        if isinstance(arguments.get("material"), dict):
            arguments["material"] = material_class(**arguments["material"])
        made.append(getattr(module, cls)("obj", **arguments))
    return made[0], made[1]


def assert_same_arguments(ours_value: Any, theirs_value: Any, label: str) -> None:
    """Equal ``CompositeObject`` arguments: lists and dicts item by item, the rest as values."""
    if isinstance(theirs_value, dict):
        assert list(ours_value) == list(theirs_value) or set(ours_value) == set(theirs_value), label
        for key, value in theirs_value.items():
            assert_same_arguments(ours_value[key], value, f"{label}.{key}")
    elif isinstance(theirs_value, (list, tuple)) and type(ours_value) is type(theirs_value):
        assert len(ours_value) == len(theirs_value), label
        for i, (mine, theirs) in enumerate(zip(ours_value, theirs_value, strict=True)):
            assert_same_arguments(mine, theirs, f"{label}[{i}]")
    else:
        assert_same_value(ours_value, theirs_value, label)


def assert_same_recipe(cls: str, mine: Any, theirs: Any) -> None:
    """Same object as robosuite's, the recipe's attributes and its ``CompositeObject`` arguments."""
    if cls in _BODY_RECIPES:
        assert_same_composite(mine, theirs)
    else:
        assert_same_object(mine, theirs)
        assert text_of(mine.get_obj()) == text_of(theirs.get_obj())
        mine_arguments, their_arguments = mine._get_geom_attrs(), theirs._get_geom_attrs()
        assert_same_arguments(mine_arguments, their_arguments, cls)
    for name in EXTRAS[cls]:
        assert_same_value(getattr(mine, name), getattr(theirs, name), name)


CASE_IDS = [(cls, i) for cls, cases in CASES.items() for i in range(len(cases))]


@pytest.mark.parametrize(("cls", "index"), CASE_IDS, ids=[f"{c}-{i}" for c, i in CASE_IDS])
def test_recipe_is_robosuites(cls: str, index: int) -> None:
    """Body, assets, names, offsets, attributes and arguments are robosuite's, for each case."""
    mine, theirs = _pair(cls, CASES[cls][index])
    assert_same_recipe(cls, mine, theirs)
    my_model, their_model = (_world([obj]).get_model(mode="mujoco") for obj in (mine, theirs))
    assert model_differences(my_model, their_model) == []
    assert my_model.ngeom == len(mine.contact_geoms) + len(mine.visual_geoms) > 0


@pytest.mark.parametrize("cls", ["ConeObject", "HollowCylinderObject"])
@pytest.mark.parametrize("material_class", [CustomMaterial, TheirMaterial], ids=["ours", "theirs"])
def test_shell_materials_of_either_library_give_robosuites_shell(
    cls: str, material_class: type
) -> None:
    """A cone or ring takes this library's material or robosuite's; robosuite takes its own."""
    mine = getattr(ours, cls)("obj", material=material_class(**copy.deepcopy(_STEEL)))
    theirs = getattr(rs, cls)("obj", material=TheirMaterial(**copy.deepcopy(_STEEL)))
    assert_same_recipe(cls, mine, theirs)
    assert {g.get("material") for g in mine.get_obj().iter("geom") if g.get("group") == "1"} == {
        "obj_steel_mat"
    }


@pytest.mark.parametrize("seed", [0, 1, 7])
@pytest.mark.parametrize("kwargs", CASES["HammerObject"], ids=range(len(CASES["HammerObject"])))
def test_hammer_draws_what_robosuite_draws(seed: int, kwargs: dict[str, Any]) -> None:
    """Five draws, then one per ``init_quat`` read: the generators stay in step with robosuite's."""
    mine, theirs = _pair("HammerObject", kwargs, seed)
    assert_same_recipe("HammerObject", mine, theirs)
    assert mine.rng.bit_generator.state == theirs.rng.bit_generator.state
    for read in range(5):
        assert_same_value(mine.init_quat, theirs.init_quat, f"init_quat {read}")
    assert mine.rng.bit_generator.state == theirs.rng.bit_generator.state
    assert mine.rng.random() == theirs.rng.random()


def test_only_the_hammer_frame_and_stand_have_an_initial_orientation() -> None:
    """Placement samplers turn an object by ``init_quat`` when it has one: only these three."""
    for cls in CASES:
        mine, theirs = _pair(cls, {})
        assert hasattr(mine, "init_quat") == hasattr(theirs, "init_quat"), cls
    assert {cls for cls in CASES if hasattr(_pair(cls, {})[0], "init_quat")} == {
        "HammerObject",
        "HookFrame",
        "StandWithMount",
    }


def test_a_bad_hammer_shape_is_refused_after_the_draws() -> None:
    """An ``MjcfValueError`` names the two shapes, after the draws (robosuite asserts there)."""
    theirs_rng, mine_rng = np.random.default_rng(3), np.random.default_rng(3)
    with pytest.raises(AssertionError):
        rs.HammerObject("h", handle_shape="sphere", rng=theirs_rng)
    with pytest.raises(MjcfValueError, match="'box' or 'cylinder', got 'sphere'"):
        ours.HammerObject("h", handle_shape="sphere", rng=mine_rng)
    assert mine_rng.bit_generator.state == theirs_rng.bit_generator.state


def test_a_cone_refuses_what_is_not_a_material() -> None:
    """Any ``CustomMaterial`` works, anything else says so (robosuite asserts its own class)."""
    with pytest.raises(AssertionError):
        rs.ConeObject("c", material="steel_mat")
    with pytest.raises(MjcfValueError, match="material must be a CustomMaterial, got 'steel_mat'"):
        ours.ConeObject("c", material="steel_mat")


def test_a_numpy_pot_color_works_here() -> None:
    """A numpy colour gives the tuple's pot (robosuite reads its truth value: ``ValueError``)."""
    color = np.array([1.0, 1.0, 0.0, 1.0])
    with pytest.raises(ValueError, match="truth value"):
        rs.PotWithHandlesObject("pot", rgba_body=color, use_texture=False)
    mine = ours.PotWithHandlesObject("pot", rgba_body=color, use_texture=False)
    same = ours.PotWithHandlesObject("pot", rgba_body=(1.0, 1.0, 0.0, 1.0), use_texture=False)
    assert text_of(mine.get_obj()) == text_of(same.get_obj())


def test_recipes_have_robosuites_signatures() -> None:
    """Parameter names, order and defaults are robosuite's."""
    for cls in CASES:
        mine, theirs = inspect.signature(getattr(ours, cls)), inspect.signature(getattr(rs, cls))
        assert [(p.name, p.default) for p in mine.parameters.values()] == [
            (p.name, p.default) for p in theirs.parameters.values()
        ], cls


@pytest.mark.parametrize("cls", ["Bin", "PotWithHandlesObject", "RatchetingWrenchObject"])
def test_scaled_recipes_are_robosuites(cls: str) -> None:
    """``set_scale`` scales a recipe's body and offsets as robosuite's does."""
    mine, theirs = _pair(cls, {})
    for obj in (mine, theirs):
        obj.set_scale([2.0, 1.5, 0.5])
    assert text_of(mine.get_obj()) == text_of(theirs.get_obj())
    for name in ("bottom_offset", "top_offset", "horizontal_radius"):
        assert_same_value(getattr(mine, name), getattr(theirs, name), name)


def _world(objects: list[Any]) -> MujocoWorldBase:
    """The objects in one world, half a metre apart (``_world`` of the composite tests)."""
    for i, obj in enumerate(objects):
        obj.get_obj().set("pos", f"{0.5 * i} 0 0.3")
    return composite_world(objects)


def test_a_world_of_all_nine_compiles_and_steps_as_robosuites() -> None:
    """MuJoCo compiles the same world from either library's nine objects and steps it alike."""
    runs = []
    for module in (ours, rs):
        objects = [
            getattr(module, cls)(f"o{i}", **({"rng": np.random.default_rng(0)} if i == 4 else {}))
            for i, cls in enumerate(CASES)
        ]
        world = _world(objects)
        model = world.get_model(mode="mujoco")
        data = mujoco.MjData(model)
        for _ in range(30):
            mujoco.mj_step(model, data)
        runs.append((world, model, data))
    (my_world, my_model, my_data), (their_world, their_model, their_data) = runs
    assert text_of(my_world.root) == text_of(their_world.root)
    assert my_model.nbody == their_model.nbody == 1 + 8 + 1 + 3
    assert my_model.ngeom == their_model.ngeom
    np.testing.assert_array_equal(my_data.qpos, their_data.qpos)
    np.testing.assert_array_equal(my_data.xpos, their_data.xpos)


# -- drawn parameters ---------------------------------------------------------------------

_LENGTH = st.floats(0.005, 0.3)
_SMALL = st.floats(0.001, 0.02)
_DENSITY = st.one_of(st.integers(1, 20000), st.floats(1.0, 20000.0))
_FRICTION = st.none() | st.tuples(st.floats(0.1, 3.0), st.floats(0.0, 0.5), st.floats(0.0, 0.01))
_RGBA = st.tuples(*[st.floats(0.0, 1.0)] * 4)
_SOLIMP = st.tuples(st.floats(0.8, 0.99), st.floats(0.9, 0.999), st.floats(0.0001, 0.01))


def _sizes(count: int) -> st.SearchStrategy[tuple[float, ...]]:
    return st.tuples(*[_LENGTH] * count)


@st.composite
def _radii(draw: st.DrawFn) -> dict[str, float]:
    inner = draw(st.floats(0.001, 0.05))
    return {"inner_radius": inner, "outer_radius": inner + draw(st.floats(0.001, 0.05))}


#: Drawn arguments per class, over the ranges each parameter takes.
ARGUMENTS: dict[str, st.SearchStrategy[dict[str, Any]]] = {
    "Bin": st.fixed_dictionaries(
        {},
        optional={
            "bin_size": _sizes(3).map(lambda s: (s[0] + 0.05, s[1] + 0.05, s[2] + 0.02)),
            "wall_thickness": _SMALL,
            "transparent_walls": st.booleans(),
            "friction": _FRICTION,
            "density": _DENSITY,
            "use_texture": st.booleans(),
            "rgba": _RGBA,
        },
    ),
    "Lid": st.fixed_dictionaries(
        {},
        optional={
            "lid_size": _sizes(3),
            "handle_size": _sizes(3),
            "transparent": st.booleans(),
            "friction": _FRICTION,
            "density": _DENSITY,
            "use_texture": st.booleans(),
            "rgba": _RGBA,
        },
    ),
    "ConeObject": st.builds(
        dict,
        _radii(),
        height=_LENGTH,
        ngeoms=st.integers(2, 20),
        use_box=st.booleans(),
        rgba=st.none() | _RGBA,
        material=st.none() | st.just(_STEEL),
        density=_DENSITY,
        friction=_FRICTION,
        solimp=_SOLIMP,
    ),
    "HollowCylinderObject": st.builds(
        dict,
        _radii(),
        height=_LENGTH,
        ngeoms=st.integers(3, 20),
        make_half=st.booleans(),
        rgba=st.none() | _RGBA,
        material=st.none() | st.just(_STEEL),
        density=_DENSITY,
        friction=_FRICTION,
    ),
    "HammerObject": st.fixed_dictionaries(
        {},
        optional={
            "handle_shape": st.sampled_from(["box", "cylinder"]),
            "handle_radius": st.one_of(_SMALL, st.tuples(_SMALL, _SMALL).map(sorted)),
            "handle_length": st.one_of(_LENGTH, st.tuples(_LENGTH, _LENGTH).map(sorted)),
            "handle_density": st.one_of(_DENSITY, st.tuples(_DENSITY, _DENSITY).map(sorted)),
            "handle_friction": st.floats(0.5, 5.0),
            "head_density_ratio": st.floats(0.5, 3.0),
            "use_texture": st.booleans(),
            "rgba_handle": _RGBA,
            "rgba_face": _RGBA,
        },
    ),
    "HookFrame": st.fixed_dictionaries(
        {},
        optional={
            "frame_length": _LENGTH,
            "frame_height": _LENGTH,
            "frame_thickness": _SMALL,
            "hook_height": st.none() | _SMALL,
            "grip_location": st.none() | _LENGTH,
            "grip_size": st.none() | st.tuples(_SMALL, _SMALL),
            "tip_size": st.none() | st.tuples(_SMALL, _SMALL, _SMALL, _SMALL),
            "friction": _FRICTION,
            "density": _DENSITY,
            "use_texture": st.booleans(),
        },
    ),
    "StandWithMount": st.fixed_dictionaries(
        {},
        optional={
            "size": _sizes(3),
            "mount_location": st.tuples(st.floats(-0.1, 0.1), st.floats(-0.1, 0.1)),
            "mount_width": _SMALL,
            "wall_thickness": _SMALL,
            "base_thickness": _SMALL,
            "initialize_on_side": st.booleans(),
            "add_hole_vis": st.booleans(),
            "friction": _FRICTION,
            "density": _DENSITY,
            "use_texture": st.booleans(),
        },
    ),
    "PotWithHandlesObject": st.fixed_dictionaries(
        {},
        optional={
            "body_half_size": _sizes(3),
            "handle_radius": _SMALL,
            "handle_length": _LENGTH,
            "handle_width": _LENGTH,
            "handle_friction": st.floats(0.5, 3.0),
            "density": _DENSITY,
            "use_texture": st.booleans(),
            "rgba_body": _RGBA,
            "rgba_handle_0": _RGBA,
            "solid_handle": st.booleans(),
            "thickness": _SMALL,
        },
    ),
    "RatchetingWrenchObject": st.fixed_dictionaries(
        {},
        optional={
            "handle_size": _sizes(3),
            "outer_radius_1": st.floats(0.02, 0.05),
            "inner_radius_1": st.floats(0.001, 0.02),
            "height_1": _SMALL,
            "ngeoms": st.integers(3, 12),
            "grip_size": st.none() | st.tuples(_SMALL, _SMALL),
            "density": _DENSITY,
            "friction": _FRICTION,
        },
    ),
}


@pytest.mark.parametrize("cls", list(CASES))
@PER_CLASS
@given(data=st.data())
def test_drawn_recipes_are_robosuites(cls: str, data: st.DataObject) -> None:
    """Any parameters in range give robosuite's object (hammers from equal seeds)."""
    kwargs = data.draw(ARGUMENTS[cls], label="arguments")
    seed = data.draw(st.integers(0, 2**32 - 1), label="seed")
    mine, theirs = _pair(cls, kwargs, seed)
    assert_same_recipe(cls, mine, theirs)


def test_every_object_class_of_robosuite_is_here() -> None:
    """Each class ``robosuite.models.objects`` exports has its twin in this library."""
    exported = {
        name
        for name, value in vars(rs).items()
        if isinstance(value, type) and issubclass(value, rs.MujocoObject)
    }
    assert len(exported) >= 34
    assert sorted(exported - set(ours.__all__)) == []
