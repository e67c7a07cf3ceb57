"""XML objects of ``mjcf_model.compat.objects`` against robosuite 1.5.2's, case by case."""

from __future__ import annotations

import copy
import itertools
import pickle
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest
import robosuite.models.base as rs_base
import robosuite.models.objects as rs

from mjcf_model import MjcfLookupError
from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_object,
    assert_same_tree,
    assert_same_value,
    assert_view_matches_model,
)

#: The contract's fixture t1: two default classes, unnamed geoms, a group-3 geom,
#: an unused mesh, a nested body with a slide joint and a two-size site.
T1 = """<mujoco model="t1">
  <asset>
    <mesh name="m1" file="meshes/a.stl" scale="2 2 2"/>
    <mesh name="unused" file="meshes/b.stl"/>
    <texture name="tex" file="../textures/x.png" type="2d"/>
    <material name="mat" texture="tex"/>
  </asset>
  <default>
    <default class="col"><geom group="0" friction="2 0.1 0.1"/></default>
    <default class="vis"><geom group="1" contype="0" conaffinity="0"/></default>
  </default>
  <worldbody>
    <body>
      <body name="object" pos="0 0 0.1">
        <geom class="col" type="box" size="0.1 0.2 0.3" pos="0.1 0 0"/>
        <geom class="vis" type="mesh" mesh="m1" material="mat"/>
        <geom name="named" type="cylinder" size="0.05 0.2" group="0" material="mat"/>
        <geom type="sphere" size="0.05" group="3"/>
        <body name="child" pos="1 1 1">
          <joint name="hj" type="slide" range="0 0.1" pos="0 0 1"/>
          <geom type="sphere" size="0.05" group="0"/>
          <site name="s" size="0.005 0.02" pos="0 0 0" type="cylinder"/>
          <site name="ball" size="0.01" pos="0.1 0 0"/>
        </body>
      </body>
      <site name="bottom_site" pos="0 0 -0.1" size="0.005"/>
      <site name="top_site" pos="0 0 0.1" size="0.005"/>
      <site name="horizontal_radius_site" pos="0.2 0.2 0" size="0.1"/>
    </body>
  </worldbody>
</mujoco>"""

#: t2: a nested default class (robosuite: KeyError).
T2 = """<mujoco model="t2">
  <default>
    <default class="a"><geom group="0" rgba="0 1 0 1"/>
      <default class="b"><geom size="0.05" friction="2 0.1 0.1"/></default>
    </default>
  </default>
  <worldbody><body><body name="object">
    <geom class="b" type="sphere"/><geom class="a" type="box" size="0.1 0.1 0.1"/>
  </body><site name="bottom_site" pos="0 0 -0.1"/></body></worldbody>
</mujoco>"""

#: t3: a geom without ``group`` (robosuite: TypeError).
T3 = """<mujoco><worldbody><body><body name="object">
  <geom type="sphere" size="0.05" material="m"/><geom type="box" size="0.1 0.1 0.1" group="1"/>
</body></body></worldbody><asset><material name="m" rgba="0 0 1 1"/></asset></mujoco>"""

#: t4: the object body is not inside an outer body (robosuite: AttributeError).
T4 = """<mujoco><worldbody><body name="object"><geom size="0.1" group="0"/></body>
</worldbody></mujoco>"""

#: t5: a main default (dropped, as robosuite drops it) and a childclass.
T5 = """<mujoco model="t5">
  <default><geom density="500"/>
    <default class="a"><geom rgba="0 0 1 1" friction="2 0.1 0.1"/></default>
  </default>
  <worldbody><body><body name="object" childclass="a">
    <geom type="sphere" size="0.05" group="0"/><body name="inner">
    <geom type="box" size="0.1 0.1 0.1" group="0" rgba="1 1 1 1"/>
    </body></body><site name="bottom_site" pos="0 0 -0.1"/></body></worldbody>
</mujoco>"""


@pytest.fixture(scope="module")
def fixture_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The fixture files t1..t5, written once."""
    folder = tmp_path_factory.mktemp("xml_objects")
    for name, text in {"t1": T1, "t2": T2, "t3": T3, "t4": T4, "t5": T5}.items():
        (folder / f"{name}.xml").write_text(text)
    return folder


# -- robosuite's shipped objects ------------------------------------------------------

SHIPPED = [
    "BottleObject",
    "CanObject",
    "LemonObject",
    "MilkObject",
    "BreadObject",
    "CerealObject",
    "SquareNutObject",
    "RoundNutObject",
    "MilkVisualObject",
    "BreadVisualObject",
    "CerealVisualObject",
    "CanVisualObject",
    "PlateWithHoleObject",
]
#: Names, among them ones a file's names already start with ("can_mesh" in "can").
NAMES = ["can", "obj", "milk", "c2"]
#: What happens after construction: nothing, scaling (twice compounds), placing.
OPERATIONS = ["none", "scale2", "scale123", "scale_twice", "pos_euler"]


def _operate(obj: Any, operation: str) -> None:
    if operation == "scale2":
        obj.set_scale(2)
    elif operation == "scale123":
        obj.set_scale([1, 2, 3])
    elif operation == "scale_twice":
        obj.set_scale(2)
        obj.set_scale([1, 1, 0.5])
    elif operation == "pos_euler":
        obj.set_pos([0.1, -0.2, 0.83])
        obj.set_euler(np.array([0.0, 0.0, 1.5]))


@pytest.mark.parametrize(
    ("cls", "name", "operation"),
    [
        (cls, name, op)
        for cls in SHIPPED
        for name, op in itertools.chain(
            ((n, "none") for n in NAMES), (("obj", op) for op in OPERATIONS[1:])
        )
    ],
)
def test_shipped_object_matches(cls: str, name: str, operation: str) -> None:
    """Each object robosuite ships gives robosuite's body, assets, document and properties."""
    theirs, mine = getattr(rs, cls)(name), getattr(ours, cls)(name)
    _operate(theirs, operation)
    _operate(mine, operation)
    assert_same_object(mine, theirs)
    assert_same_value(mine.rot, theirs.rot, "rot")


@pytest.mark.parametrize(
    "kwargs",
    [
        {},
        {"friction": 1.0, "damping": 0.5},
        {"friction": 0.3},
        {"damping": 2},
        {"lock": True},
        {"lock": True, "friction": 1.0, "damping": 0.5},
    ],
)
def test_door_matches(kwargs: dict[str, Any]) -> None:
    """DoorObject with hinge friction, damping and the locked variant is robosuite's."""
    theirs, mine = rs.DoorObject("door", **kwargs), ours.DoorObject("door", **kwargs)
    assert_same_object(mine, theirs)
    for field in ("door_body", "frame_body", "latch_body", "hinge_joint", "lock"):
        assert getattr(mine, field) == getattr(theirs, field)


def test_can_golden() -> None:
    """The contract's CanObject("can") values (golden check 8) hold."""
    can = ours.CanObject("can")
    assert can.bodies == ["can_main"] and can.joints == ["can_joint0"]
    assert can.sites == ["can_default_site"] and can.actuators == [] and can.sensors == []
    np.testing.assert_array_equal(can.bottom_offset, [0.0, 0.0, -0.06])
    np.testing.assert_array_equal(can.get_bounding_box_half_size(), [0.025, 0.025, 0.06])
    assert can.asset[0].get("name") == "can_mesh"  # skipped: it starts with the prefix
    assert [c.tag for c in can.root] == [
        *["asset", "worldbody", "actuator", "sensor", "tendon", "equality", "contact"]
    ]
    assert can.get_xml().endswith(
        "<actuator /><sensor /><tendon /><equality /><contact /></mujoco>"
    )
    assert ours.SquareNutObject("nut").important_sites == {
        "obj": "nut_default_site",
        "handle": "nut_handle_site",
    }


def test_can_scaled_twice_golden() -> None:
    """CanObject.set_scale(2) twice: mesh scale 4 and bottom offset -0.24 (golden check 11)."""
    can = ours.CanObject("can")
    can.set_scale(2)
    can.set_scale(2)
    assert can.asset[0].get("scale") == "4.0 4.0 4.0"
    np.testing.assert_array_equal(can.bottom_offset, [0.0, 0.0, -0.24])


def test_set_scale_of_another_body_scales_it_in_place_as_robosuite_does() -> None:
    """``set_scale(scale, obj=body)`` scales that live body in place, and the object's meshes."""
    trees = []
    for module in (rs, ours):
        can = module.CanObject("can")
        other = module.BoxObject("box", size=[0.1, 0.1, 0.1]).get_obj()
        can.set_scale([1, 2, 3], obj=other)
        trees.append((other, can.asset))
    (theirs, their_asset), (mine, my_asset) = trees
    assert_same_tree(mine, theirs)
    assert_same_tree(my_asset, their_asset)


# -- MujocoXMLObject on the contract's fixture --------------------------------------

XML_CASES = [
    {"obj_type": t, "duplicate_collision_geoms": d, "joints": j, "scale": s}
    for t in ("all", "visual", "collision")
    for d in (True, False)
    for j in ("default", None, "custom")
    for s in (None, 2.0, [1, 2, 3])
]


def _joint_list() -> list[dict[str, str]]:
    return [{"type": "hinge", "axis": "0 0 1"}, {"name": "sl", "type": "slide"}]


@pytest.mark.parametrize("case", XML_CASES, ids=lambda case: "-".join(map(str, case.values())))
def test_xml_object_matches(fixture_dir: Path, case: dict[str, Any]) -> None:
    """MujocoXMLObject on t1 with every obj_type, duplication, joints and scale is robosuite's."""
    kwargs = dict(case)
    their_joints = _joint_list() if kwargs["joints"] == "custom" else kwargs["joints"]
    my_joints = _joint_list() if kwargs["joints"] == "custom" else kwargs["joints"]
    path = str(fixture_dir / "t1.xml")
    theirs = rs.MujocoXMLObject(path, "obj", **{**kwargs, "joints": their_joints})
    mine = ours.MujocoXMLObject(path, "obj", **{**kwargs, "joints": my_joints})
    assert_same_object(mine, theirs)
    assert my_joints == their_joints  # the caller's dicts get the same names written in
    if kwargs["joints"] == "custom":
        assert mine.joint_specs is my_joints and my_joints[0]["name"] == "joint0"


def test_xml_object_golden_values(fixture_dir: Path) -> None:
    """The contract's e8 values for t1: names, scaled meshes, sites and offsets."""
    plain = ours.MujocoXMLObject(str(fixture_dir / "t1.xml"), "obj")
    assert plain.visual_geoms == ["obj_g1", "obj_g4_visual", "obj_g0_visual", "obj_named_visual"]
    assert plain.joints == ["obj_hj", "obj_joint0"]
    big = ours.MujocoXMLObject(str(fixture_dir / "t1.xml"), "obj", scale=2.0)
    assert [m.get("scale") for m in big.asset.iter("mesh")] == ["4.0 4.0 4.0", "2.0 2.0 2.0"]
    assert big.get_obj().get("pos") == "0 0 0.1"
    np.testing.assert_array_equal(big.bottom_offset, [0.0, 0.0, -0.2])
    wide = ours.MujocoXMLObject(str(fixture_dir / "t1.xml"), "obj", scale=[1, 2, 3])
    sizes = {s.get("name"): s.get("size") for s in wide.worldbody.iter("site")}
    assert sizes["obj_s"] == "0.0075 0.06" and sizes["obj_default_site"] == "0.002 0.004 0.006"
    assert sizes["obj_ball"] == "0.02"


def test_nested_defaults_resolved(fixture_dir: Path) -> None:
    """t2: robosuite raises KeyError; here nested classes resolve as MuJoCo resolves them."""
    path = str(fixture_dir / "t2.xml")
    with pytest.raises(KeyError):
        rs.MujocoXMLObject(path, "o")
    obj = ours.MujocoXMLObject(path, "o", joints=None, duplicate_collision_geoms=False)
    geoms = list(obj.get_obj().iter("geom"))
    assert dict(geoms[0].attrib) == {
        "type": "sphere",
        "size": "0.05",
        "friction": "2 0.1 0.1",
        "group": "0",
        "rgba": "0 1 0 1",
        "name": "o_g0",
    }
    assert dict(geoms[1].attrib)["rgba"] == "0 1 0 1"
    original = mujoco.MjModel.from_xml_path(path)
    compiled = obj.get_model()
    np.testing.assert_array_equal(compiled.geom_friction, original.geom_friction)
    np.testing.assert_array_equal(compiled.geom_size[:, 0], original.geom_size[:, 0])


def test_geom_without_group_is_collision(fixture_dir: Path) -> None:
    """t3: robosuite raises TypeError; a geom without group is a collision geom (group 0)."""
    path = str(fixture_dir / "t3.xml")
    with pytest.raises(TypeError):
        rs.MujocoXMLObject(path, "o")
    obj = ours.MujocoXMLObject(path, "o")
    assert obj.contact_geoms == ["o_g0"]
    assert obj.visual_geoms == ["o_g1", "o_g0_visual"]
    twin = obj.get_obj().find("geom[@name='o_g0_visual']")
    assert twin is not None and twin.get("material") == "o_m" and twin.get("group") == "1"


def test_missing_outer_body_is_a_lookup_error(fixture_dir: Path) -> None:
    """t4: robosuite raises AttributeError; here an MjcfLookupError says what is expected."""
    path = str(fixture_dir / "t4.xml")
    with pytest.raises(AttributeError):
        rs.MujocoXMLObject(path, "o")
    with pytest.raises(MjcfLookupError, match=r"worldbody/body/body\[@name='object'\]"):
        ours.MujocoXMLObject(path, "o")


def test_childclass_resolved_main_default_dropped(fixture_dir: Path) -> None:
    """t5: main defaults dropped as robosuite does; childclass resolved where robosuite breaks."""
    path = str(fixture_dir / "t5.xml")
    theirs = rs.MujocoXMLObject(path, "o", joints=None, duplicate_collision_geoms=False)
    assert theirs.get_obj().get("childclass") == "o_a"
    with pytest.raises(ValueError, match="unknown default childclass"):
        theirs.get_model()
    mine = ours.MujocoXMLObject(path, "o", joints=None, duplicate_collision_geoms=False)
    explicit = fixture_dir / "t5_explicit.xml"  # each geom names the class itself
    explicit.write_text(T5.replace(' childclass="a"', "").replace("<geom ", '<geom class="a" '))
    expected = rs.MujocoXMLObject(str(explicit), "o", joints=None, duplicate_collision_geoms=False)
    assert_same_tree(mine.root, expected.root)
    assert all(g.get("density") is None for g in mine.get_obj().iter("geom"))
    original = mujoco.MjModel.from_xml_path(path)
    compiled = mine.get_model()
    np.testing.assert_array_equal(compiled.geom_rgba, original.geom_rgba)
    np.testing.assert_array_equal(compiled.geom_friction, original.geom_friction)


# -- the live ElementTree -------------------------------------------------------------


def test_handed_out_elements_stay_live() -> None:
    """get_obj() is one element for the object's life; changes reach it; foreign edits stay."""
    milk = ours.MilkObject("milk")
    body = milk.get_obj()
    world = ET.Element("worldbody")
    world.append(body)
    body.set("quat", "0 0 0.707 0.707")  # as robosuite's environments do
    milk.set_pos([1, 2, 3])
    milk.set_scale(2)
    assert milk.get_obj() is body and world[0] is body
    assert body.get("pos") == "1 2 3" and body.get("quat") == "0 0 0.707 0.707"
    assert body[0].get("pos") == "0.0 0.0 0.0"
    assert body in list(milk.root.iter("body"))


def test_objects_pickle_and_copy() -> None:
    """Objects pickle and deep-copy to equal, independent objects."""
    can = ours.CanObject("can")
    for clone in (pickle.loads(pickle.dumps(can)), copy.deepcopy(can)):
        assert type(clone) is ours.CanObject
        assert clone.get_xml() == can.get_xml()
        clone.set_pos([1, 1, 1])
        assert can.get_obj().get("pos") is None
        assert_view_matches_model(clone)


def test_isinstance_does_not_depend_on_which_was_imported_first() -> None:
    """Objects made before robosuite is imported pass ``isinstance`` against it once it is.

    This module imports robosuite first; a fresh process makes the objects first.
    """
    code = (
        "from mjcf_model.compat import objects as ours\n"
        "import sys\n"
        "assert not any(m.startswith('robosuite') for m in sys.modules)\n"
        "made = [ours.CanObject('c'), ours.BoxObject('b'), ours.Bin('n')]\n"
        "import robosuite.models.base as rs_base, robosuite.models.objects as rs\n"
        "twins = [rs.CanObject, rs.BoxObject, rs.CompositeObject]\n"
        "print([isinstance(o, t) and isinstance(o, rs_base.MujocoModel) "
        "for o, t in zip(made, twins)])\n"
    )
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert found.stdout.strip() == "[True, True, True]"


def test_isinstance_of_robosuite_twins() -> None:
    """Every class passes isinstance against its robosuite twin and robosuite's bases."""
    cases: list[tuple[Any, type]] = [
        (ours.CanObject("c"), rs.CanObject),
        (ours.CanObject("c"), rs.MujocoXMLObject),
        (ours.CanObject("c"), rs_base.MujocoXML),
        (ours.DoorObject("d"), rs.DoorObject),
        (ours.BoxObject("b"), rs.BoxObject),
        (ours.BoxObject("b"), rs.PrimitiveObject),
        (ours.BallObject("b"), rs.MujocoGeneratedObject),
        (ours.CylinderObject("b"), rs.CylinderObject),
        (ours.CapsuleObject("b"), rs.CapsuleObject),
        *[(getattr(ours, name)("r"), getattr(rs, name)) for name in RECIPES],
        (ours.Bin("b"), rs.CompositeObject),
        (ours.RatchetingWrenchObject("w"), rs.CompositeBodyObject),
    ]
    for obj, twin in cases:
        assert isinstance(obj, twin) and isinstance(obj, rs.MujocoObject)
        assert isinstance(obj, rs_base.MujocoModel) and isinstance(obj, ours.MujocoObject)
    assert not isinstance(ours.BoxObject("b"), rs.CanObject)


def test_robosuite_is_never_imported_and_may_come_later() -> None:
    """The library does not import robosuite; objects made before it is imported pass its checks."""
    script = (
        "import sys\n"
        "from mjcf_model.compat.objects import CanObject, BoxObject\n"
        "can, box = CanObject('can'), BoxObject('box')\n"
        "assert 'robosuite' not in sys.modules, 'imported robosuite'\n"
        "assert can.__class__ is CanObject\n"
        "import robosuite.models.objects as rs\n"
        "assert isinstance(can, rs.MujocoObject) and isinstance(box, rs.BoxObject)\n"
        "print('ok')\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, check=False
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "ok"


#: robosuite's composite recipes (made of geoms, or of objects' bodies).
RECIPES = (
    "Bin", "Lid", "ConeObject", "HollowCylinderObject", "HammerObject", "HookFrame",
    "StandWithMount", "PotWithHandlesObject", "RatchetingWrenchObject",
)  # fmt: skip


@pytest.mark.parametrize(
    "cls", ["CanObject", "BoxObject", "CompositeObject", "MujocoXMLModel", *RECIPES]
)
def test_no_robosuite_method_is_inherited(cls: str) -> None:
    """Every public attribute of robosuite's twin is defined by this library's class."""
    mine = getattr(ours, cls)
    twin = getattr(rs, cls, None) or getattr(rs_base, cls)
    defined = {name for klass in mine.__mro__ for name in vars(klass)}
    public = {n for n in dir(twin) if not n.startswith("__") and not n.startswith("_get_")}
    # robosuite's in-place helpers: ours read their input and leave it as it was.
    in_place = {"_replace_defaults_inline", "_get_default_classes", "_remove_joints"}
    assert public - defined <= in_place
