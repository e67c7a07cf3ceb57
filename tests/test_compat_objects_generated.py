"""Generated objects (primitives, composites) of ``mjcf_model.compat.objects`` against robosuite."""

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
import robosuite.models.objects.generated_objects as rs_generated
import robosuite.models.objects.objects as rs_objects
from PIL import Image
from robosuite.utils.mjcf_utils import CustomMaterial as TheirMaterial

from mjcf_model import MjcfValueError
from mjcf_model.compat import CustomMaterial
from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_object,
    assert_same_tree,
    assert_same_value,
    assert_view_matches_model,
)

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


def test_mujoco_object_scale_argument_works() -> None:
    """Robosuite's MujocoObject(scale=2) raises TypeError; here the scale waits for the body."""
    with pytest.raises(TypeError):
        rs.MujocoObject(scale=2)
    assert ours.MujocoObject(scale=2).obj_type == "all"
    later = ours.MujocoObject()
    later.set_scale(2)  # robosuite: TypeError (no body yet); here it waits for the body
    assert later._pending_scale == 2

    def peg(base: type, **kwargs: Any) -> Any:
        class Peg(base):  # type: ignore[misc, valid-type]
            def __init__(self) -> None:
                super().__init__(**kwargs)
                self._name = "peg"
                self._obj = self._get_object_subtree()
                self._get_object_properties()

            def exclude_from_prefixing(self, inp: Any) -> bool:
                return False

            def _get_object_subtree(self) -> ET.Element:
                body = ET.Element("body", name="main")
                ET.SubElement(body, "geom", type="box", size="0.1 0.1 0.1", group="0", name="g0")
                site = ET.SubElement(body, "site", self.get_site_attrib_template())
                site.set("name", "default_site")
                return body

        return Peg()

    theirs, mine = peg(rs.MujocoObject), peg(ours.MujocoObject)
    assert_same_tree(mine.get_obj(), theirs.get_obj())
    assert (mine.contact_geoms, mine.sites) == (theirs.contact_geoms, theirs.sites)
    theirs.set_scale(2)
    mine.set_scale(2)
    assert_same_tree(mine.get_obj(), theirs.get_obj())
    assert_same_tree(peg(ours.MujocoObject, scale=2).get_obj(), theirs.get_obj())


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


def test_composite_golden_bin() -> None:
    """Bin's walls: numpy-formatted densities, frictions and quaternions (golden check 10)."""
    mine, theirs = (
        ours.Bin("bin", bin_size=(0.2, 0.2, 0.1)),
        rs.Bin("bin", bin_size=(0.2, 0.2, 0.1)),
    )
    assert_same_tree(mine.get_obj(), theirs.get_obj())
    geoms = list(mine.get_obj().iter("geom"))
    assert geoms[0].get("density") == "1000.0" and geoms[0].get("friction") == "1.0 0.005 0.0001"
    assert any(g.get("quat") == "6.123233995736766e-17 0.0 0.0 1.0" for g in geoms)


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
