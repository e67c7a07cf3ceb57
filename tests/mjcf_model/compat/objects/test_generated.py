"""Tests of ``mjcf_model.compat.objects.generated``."""

from __future__ import annotations

import copy
import tempfile
import uuid
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import robosuite.models.objects as rs
from PIL import Image
from robosuite.utils.mjcf_utils import CustomMaterial as TheirMaterial

from mjcf_model import MjcfValueError
from mjcf_model.compat import CustomMaterial
from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_object,
    assert_same_tree,
)

# -- Generated objects (primitives, composites) of ``mjcf_model.compat.objects`` against
#    robosuite.


PRIMITIVES = ["BoxObject", "BallObject", "CylinderObject", "CapsuleObject"]
SIZES = {
    "BoxObject": [0.02, 0.03, 0.04],
    "BallObject": [0.03],
    "CylinderObject": (0.03, 0.05),
    "CapsuleObject": [0.02, 0.04],
}
OBJ_TYPES = ["all", "visual", "collision"]
MATERIALS = ["none", "default", "named", "named_ours", "shared", "shared_ours"]
JOINTS = ["default", "none", "custom"]

_WOOD = {
    "texture": "WoodRed",
    "tex_name": "redwood",
    "mat_name": "redwood_mat",
    "tex_attrib": {"type": "cube"},
    "mat_attrib": {"texrepeat": "1 1", "specular": "0.4", "shininess": "0.1"},
}
_METAL = {"texture": "Metal", "tex_name": "metal", "mat_name": "metal_mat", "shared": True}


def _materials(kind: str) -> tuple[Any, Any]:
    """(robosuite's argument, this library's argument) for a material kind."""
    if kind == "none":
        return None, None
    if kind == "default":
        return "default", "default"
    spec = _WOOD if kind.startswith("named") else _METAL
    theirs = TheirMaterial(**copy.deepcopy(spec))
    mine = CustomMaterial(**spec) if kind.endswith("ours") else TheirMaterial(**copy.deepcopy(spec))
    return theirs, mine


def _joints(kind: str) -> Any:
    if kind == "default":
        return "default"
    if kind == "none":
        return None
    return [{"type": "slide", "axis": "1 0 0"}, {"name": "h", "type": "hinge", "damping": 0.1}]


def assert_default_material_assets(mine: Any, theirs: Any, rgba: Any) -> None:
    """Robosuite's PNG texture of ``rgba`` is here MuJoCo's flat texture of that colour."""
    their_texture, their_material = list(theirs.asset)
    my_texture, my_material = list(mine.asset)
    assert_same_tree(my_material, their_material)
    assert their_texture.get("file") == str(
        Path(tempfile.gettempdir(), "robosuite_temp_tex/tex.png")
    )
    assert my_texture.get("name") == their_texture.get("name")
    assert [my_texture.get(k) for k in ("builtin", "width", "height")] == ["flat", "100", "100"]
    assert my_texture.get("rgb1") == my_texture.get("rgb2")
    name = f"probe_{uuid.uuid4().hex}"  # a file of our own: tex.png is shared by every object
    probe = TheirMaterial(texture=list(rgba), tex_name=name, mat_name=name)
    pixel = Image.open(probe.tex_attrib["file"]).getpixel((0, 0))
    rgb = [float(v) for v in str(my_texture.get("rgb1")).split()]
    assert list(pixel[:3]) == [int(v * 255) for v in rgb]


PRIMITIVE_CASES = [
    (cls, obj_type, material, joints)
    for cls in PRIMITIVES
    for obj_type in OBJ_TYPES
    for material in MATERIALS
    for joints in JOINTS
]


@pytest.mark.parametrize(("cls", "obj_type", "material", "joints"), PRIMITIVE_CASES)
def test_primitive_matches(cls: str, obj_type: str, material: str, joints: str) -> None:
    """Each primitive, with every obj_type, material and joints choice, is robosuite's."""
    their_material, my_material = _materials(material)
    their_joints, my_joints = _joints(joints), _joints(joints)
    common = {"size": SIZES[cls], "rgba": [0, 0.5, 1, 1], "obj_type": obj_type}
    theirs = getattr(rs, cls)("obj", material=their_material, joints=their_joints, **common)
    mine = getattr(ours, cls)("obj", material=my_material, joints=my_joints, **common)
    assert_same_object(mine, theirs, asset=material != "default")
    if material == "default":
        assert_default_material_assets(mine, theirs, common["rgba"])
    assert my_joints == their_joints
    assert mine.shared_materials == theirs.shared_materials
    assert mine.shared_textures == theirs.shared_textures


ARGUMENT_CASES = [
    {},
    {"friction": 0.5, "density": 500},
    {
        "friction": [2, 0.01, 0.001],
        "density": 250.5,
        "solref": [0.01, 1],
        "solimp": [0.8, 0.9, 0.01],
    },
    {"rgba": np.array([0.2, 0.4, 0.6, 0.5])},
    {"size": np.float32([0.1, 0.2, 0.3])},
]


@pytest.mark.parametrize("cls", PRIMITIVES)
@pytest.mark.parametrize("case", range(len(ARGUMENT_CASES)))
def test_primitive_arguments_match(cls: str, case: int) -> None:
    """Friction, density, solver parameters, numpy colours and float32 sizes are written alike."""
    kwargs = {"size": SIZES[cls], **ARGUMENT_CASES[case]}
    if "size" in ARGUMENT_CASES[case]:
        kwargs["size"] = np.float32(SIZES[cls])
    assert_same_object(getattr(ours, cls)("p", **kwargs), getattr(rs, cls)("p", **kwargs))


@pytest.mark.parametrize("cls", ["BoxObject", "CylinderObject"])
@pytest.mark.parametrize("seed", [0, 1, 7])
def test_seeded_sizes_match(cls: str, seed: int) -> None:
    """Sizes drawn with a seeded generator (Lift's cube) are robosuite's, with its material."""
    low, high = ([0.02] * 3, [0.022] * 3) if cls == "BoxObject" else ([0.015, 0.1], [0.03, 0.1])
    their_material, my_material = _materials("named")
    theirs = getattr(rs, cls)(
        "cube",
        size_min=low,
        size_max=high,
        material=their_material,
        rng=np.random.default_rng(seed),
    )
    mine = getattr(ours, cls)(
        "cube", size_min=low, size_max=high, material=my_material, rng=np.random.default_rng(seed)
    )
    assert_same_object(mine, theirs)


@pytest.mark.parametrize("cls", PRIMITIVES)
@pytest.mark.parametrize("scales", [[2], [[1, 2, 3]], [2, [1, 1, 0.5]], [1]])
def test_primitive_scaling_matches(cls: str, scales: list[Any]) -> None:
    """set_scale scales geom size and pos only, compounds, and leaves offsets (golden 11)."""
    theirs, mine = getattr(rs, cls)("s", size=SIZES[cls]), getattr(ours, cls)("s", size=SIZES[cls])
    for scale in scales:
        theirs.set_scale(scale)
        mine.set_scale(scale)
    assert_same_object(mine, theirs)


def test_primitive_golden() -> None:
    """The contract's e7 BoxObject body and horizontal radius (golden check 7)."""
    box = ours.BoxObject("cube", size=[0.02, 0.02, 0.02], rgba=[1, 0, 0, 1])
    assert ET.tostring(box.get_obj(), encoding="unicode") == (
        '<body pos="0 0 0" name="cube_main"><geom rgba="0.5 0 0 1" density="1000" '
        'friction="1 0.005 0.0001" solref="0.02 1.0" solimp="0.9 0.95 0.001" type="box" '
        'size="0.02 0.02 0.02" pos="0 0 0" group="0" name="cube_g0" /><geom conaffinity="0" '
        'contype="0" mass="1e-8" rgba="1 0 0 1" type="box" size="0.02 0.02 0.02" pos="0 0 0" '
        'group="1" name="cube_g0_vis" /><joint type="free" name="cube_joint0" /><site '
        'type="sphere" group="0" pos="0 0 0" size="0.002 0.002 0.002" rgba="1 0 0 1" '
        'name="cube_default_site" /></body>'
    )
    assert ET.tostring(box.asset, encoding="unicode") == "<asset />"
    assert box.horizontal_radius == 0.0282842712474619


# -- composite objects ----------------------------------------------------------------


@pytest.mark.parametrize(
    "kwargs",
    [
        {"size": [0.1, 0.2]},
        {"rgba": [1, 0, 0]},
        {"friction": [1, 0.1]},
        {"obj_type": "solid"},
        {"size": [0.1] * 3, "size_max": [0.2] * 3},
    ],
)
def test_bad_arguments_raise_value_errors(kwargs: dict[str, Any]) -> None:
    """Where robosuite asserts (or raises ValueError), a MjcfValueError says what was expected."""
    with pytest.raises((AssertionError, ValueError)):
        rs.BoxObject("b", **kwargs)
    with pytest.raises(MjcfValueError):
        ours.BoxObject("b", **kwargs)


@pytest.mark.parametrize("kind", ["shared", "named", "shared_ours", "named_ours"])
def test_append_material_twice_matches(kind: str) -> None:
    """Appending a material after construction, twice, adds and prefixes as robosuite does."""
    theirs, mine = rs.BoxObject("b", size=[0.1] * 3), ours.BoxObject("b", size=[0.1] * 3)
    for _ in range(2):
        their_material, my_material = _materials(kind)
        theirs.append_material(their_material)
        mine.append_material(my_material)
    assert_same_object(mine, theirs)
    assert mine.shared_materials == theirs.shared_materials
