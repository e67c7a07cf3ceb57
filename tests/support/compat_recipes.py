"""The cases and checks of the differential tests of robosuite's object recipes."""

from __future__ import annotations

import copy
from typing import Any

import numpy as np
import robosuite.models.objects as rs
from robosuite.utils.mjcf_utils import CustomMaterial as TheirMaterial

from mjcf_model.compat import CustomMaterial
from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_composite,
    assert_same_object,
    assert_same_value,
    text_of,
)

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
