"""Tests of ``mjcf_model.compat.objects.recipes``."""

from __future__ import annotations

import inspect
from typing import Any

import mujoco
import numpy as np
import pytest
import robosuite.models.objects as rs
from hypothesis import given
from hypothesis import strategies as st
from robosuite.models.world import MujocoWorldBase

from mjcf_model.bridge.compare import model_differences
from mjcf_model.compat import objects as ours
from tests.conftest import PER_CLASS
from tests.support.compat_objects import (
    assert_same_value,
    composite_world,
    text_of,
)
from tests.support.compat_recipes import (
    _STEEL,
    CASES,
    _pair,
    assert_same_recipe,
)

# -- The composite recipes (``Bin``, ``Lid``, ``ConeObject``, ``HammerObject``...) against
#    robosuite.
#
# Each case builds robosuite's object and ours from the same arguments and compares
# the body, the assets, every property, the recipe's own attributes and the
# arguments it gives ``CompositeObject``; hypothesis draws the parameters over their
# ranges; MuJoCo compiles and steps a world holding all nine.


CASE_IDS = [(cls, i) for cls, cases in CASES.items() for i in range(len(cases))]


@pytest.mark.parametrize(("cls", "index"), CASE_IDS, ids=[f"{c}-{i}" for c, i in CASE_IDS])
def test_recipe_is_robosuites(cls: str, index: int) -> None:
    """Body, assets, names, offsets, attributes and arguments are robosuite's, for each case."""
    mine, theirs = _pair(cls, CASES[cls][index])
    assert_same_recipe(cls, mine, theirs)
    my_model, their_model = (_world([obj]).get_model(mode="mujoco") for obj in (mine, theirs))
    assert model_differences(my_model, their_model) == []
    assert my_model.ngeom == len(mine.contact_geoms) + len(mine.visual_geoms) > 0


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
