"""Tests of ``mjcf_model.compat.objects.xml``."""

from __future__ import annotations

import importlib.util
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest
import robosuite.models.base as rs_base
import robosuite.models.objects as rs
from robosuite.models.arenas import TableArena
from robosuite.models.grippers import PandaGripper
from robosuite.models.robots import Panda
from robosuite.models.tasks import ManipulationTask
from robosuite.utils.mjcf_utils import GRIPPER_COLLISION_COLOR, CustomMaterial, xml_path_completion

from mjcf_model import MjcfLookupError, MjcfValueError
from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_object,
    assert_same_tree,
    assert_same_value,
    assert_view_matches_model,
    text_of,
)

# -- XML objects of ``mjcf_model.compat.objects`` against robosuite 1.5.2's, case by case. -----


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


# -- The compat objects inside robosuite's own pipeline: worlds, tasks, grippers and arenas. ---
#
# robosuite's environments with these objects: tests/mjcf_model/test_compat.py.


class OurPandaGripper(ours.MujocoXMLModel):
    """robosuite's ``PandaGripper`` naming and colours, on this library's MujocoXMLModel."""

    def __init__(self, idn: Any = 0) -> None:
        super().__init__(xml_path_completion("grippers/panda_gripper.xml"), idn=idn)

    naming_prefix = property(lambda self: f"gripper{self.idn}_")
    contact_geom_rgba = property(lambda self: GRIPPER_COLLISION_COLOR)
    # robosuite's raw names for the Panda gripper (plain data in its properties)
    _important_sites = PandaGripper._important_sites
    _important_geoms = PandaGripper._important_geoms
    _important_sensors = PandaGripper._important_sensors


OurPandaGripper.__name__ = "PandaGripper"


@pytest.mark.parametrize("idn", [0, 1, "right"])
def test_xml_model_matches_panda_gripper(idn: Any) -> None:
    """MujocoXMLModel reads, names, prefixes and recolours PandaGripper as robosuite (golden 13)."""
    theirs, mine = PandaGripper(idn=idn), OurPandaGripper(idn=idn)
    assert_same_tree(mine.root, theirs.root)
    assert [c.tag for c in mine.root] == [
        *["asset", "actuator", "worldbody", "sensor", "tendon", "equality", "contact"]
    ]
    names = ["name", "naming_prefix", "root_body", "bodies", "joints", "actuators", "sites"]
    names += ["sensors", "contact_geoms", "visual_geoms", "bottom_offset", "base_offset"]
    names += ["important_sites", "important_geoms", "important_sensors"]
    for name in names:
        assert_same_value(getattr(mine, name), getattr(theirs, name), name)
    assert_view_matches_model(mine)


def _scene(module: Any) -> list[Any]:
    wood = CustomMaterial(
        "WoodRed",
        "redwood",
        "redwood_mat",
        {"type": "cube"},
        {"texrepeat": "1 1", "specular": "0.4"},
    )
    objects = [
        module.CanObject("can"),
        module.MilkObject("milk"),
        module.BoxObject("cube", size=[0.02, 0.02, 0.02], material=wood),
        module.CylinderObject("cyl", size=[0.02, 0.04]),
        module.SquareNutObject("nut"),
    ]
    for index, obj in enumerate(objects):  # placed as robosuite's environments place them
        obj.get_obj().set("pos", f"{-0.2 + 0.1 * index} 0.05 0.9")
    return objects


def test_manipulation_task_scene_compiles_and_steps() -> None:
    """Table, Panda and five objects in robosuite's ManipulationTask: robosuite's XML, 100 steps."""
    runs = []
    for module in (rs, ours):
        robot = Panda()
        robot.add_gripper(PandaGripper())
        task = ManipulationTask(
            mujoco_arena=TableArena(), mujoco_robots=[robot], mujoco_objects=_scene(module)
        )
        model = task.get_model(mode="mujoco")
        data = mujoco.MjData(model)
        for _ in range(100):
            mujoco.mj_step(model, data)
        runs.append((task, model, data))
    (their_task, _, their_data), (my_task, my_model, my_data) = runs
    assert text_of(my_task.root) == text_of(their_task.root)
    assert my_model.nbody > 5 and np.all(np.isfinite(my_data.qpos))
    np.testing.assert_array_equal(my_data.qpos, their_data.qpos)
    can_body = mujoco.mj_name2id(my_model, mujoco.mjtObj.mjOBJ_BODY, "can_main")
    assert my_data.xpos[can_body][2] < 0.9  # it fell towards the table


# -- ``MujocoXML`` of ``mjcf_model.compat.objects`` against robosuite's, on robosuite's own
#    files.


def _asset_files() -> list[Path]:
    spec = importlib.util.find_spec("robosuite")
    assert spec is not None and spec.submodule_search_locations
    assets = Path(spec.submodule_search_locations[0], "models", "assets")
    return sorted(assets.rglob("*.xml"))


ASSET_FILES = _asset_files()


@pytest.mark.parametrize("path", ASSET_FILES, ids=lambda p: "/".join(p.parts[-2:]))
def test_reads_every_robosuite_file_alike(path: Path) -> None:
    """Every XML file robosuite ships reads to robosuite's document (defaults, sections, paths)."""
    theirs, mine = rs_base.MujocoXML(str(path)), ours.MujocoXML(str(path))
    assert_same_tree(mine.root, theirs.root)
    assert mine.name == theirs.name and mine.folder == theirs.folder
    for section in ("worldbody", "actuator", "sensor", "asset", "tendon", "equality", "contact"):
        assert getattr(mine, section) is mine.root.find(section)
    assert mine.tree.getroot() is mine.root
    assert mine.get_element_names(mine.worldbody, "geom") == theirs.get_element_names(
        theirs.worldbody, "geom"
    )
    assert_view_matches_model(mine)


@pytest.mark.parametrize("merge_body", ["default", "table", None])
def test_merge_matches(merge_body: str | None) -> None:
    """merge() brings in bodies, assets, actuators and sensors as robosuite's merge does."""
    arena = xml_path_completion("arenas/table_arena.xml")
    gripper = xml_path_completion("grippers/panda_gripper.xml")
    can = xml_path_completion("objects/can.xml")
    theirs, mine = rs_base.MujocoXML(arena), ours.MujocoXML(arena)
    theirs.merge([rs_base.MujocoXML(gripper), rs_base.MujocoXML(can)], merge_body=merge_body)
    mine.merge([ours.MujocoXML(gripper), rs_base.MujocoXML(can)], merge_body=merge_body)
    assert_same_tree(mine.root, theirs.root)
    assert_view_matches_model(mine)


def test_output_matches(tmp_path: Path) -> None:
    """get_xml, save_model and get_model give robosuite's XML (white space aside) and model."""
    path = xml_path_completion("arenas/table_arena.xml")
    theirs, mine = rs_base.MujocoXML(path), ours.MujocoXML(path)
    assert mine.create_default_element("keyframe") is mine.create_default_element("keyframe")
    theirs.create_default_element("keyframe")
    assert text_of(ET.fromstring(mine.get_xml())) == text_of(ET.fromstring(theirs.get_xml()))
    for pretty in (False, True):  # robosuite keeps the file's white space; this library does not
        theirs.save_model(str(tmp_path / "theirs.xml"), pretty=pretty)
        mine.save_model(str(tmp_path / "mine.xml"), pretty=pretty)
        saved = [ET.parse(tmp_path / f"{who}.xml").getroot() for who in ("mine", "theirs")]
        assert text_of(saved[0]) == text_of(saved[1])
    assert mine.get_model().ngeom == theirs.get_model().ngeom
    with pytest.raises(ValueError, match="Unkown model mode"):
        mine.get_model(mode="mjx")


class _TheirModel(rs_base.MujocoXMLModel):
    contact_geom_rgba = property(lambda self: [0, 0, 0.5, 1])


class _MyModel(ours.MujocoXMLModel):
    contact_geom_rgba = property(lambda self: [0, 0, 0.5, 1])


_MODEL_NAMES = ["root_body", "bodies", "joints", "actuators", "sites", "sensors"]
_MODEL_NAMES += ["contact_geoms", "visual_geoms"]


@pytest.mark.parametrize("path", ASSET_FILES, ids=lambda p: "/".join(p.parts[-2:]))
def test_xml_model_on_every_robosuite_file(path: Path) -> None:
    """MujocoXMLModel names, prefixes and recolours each file as robosuite's, or refuses alike."""
    try:
        theirs = _TheirModel(str(path), idn=0)
    except (AssertionError, KeyError) as error:
        if "group" in str(error) or str(error) == "'2'":  # an unnamed geom of group 2: robosuite
            assert _MyModel(str(path)).contact_geoms is not None  # crashes, this names it not
            return
        with pytest.raises(MjcfValueError, match=r"^Invalid number of root bodies") as refused:
            _MyModel(str(path), idn=0)
        if isinstance(error, AssertionError):  # robosuite's words; a KeyError names no count
            assert str(refused.value) == str(error)
        return
    mine = _MyModel(str(path), idn=0)
    assert_same_tree(mine.root, theirs.root)
    for name in _MODEL_NAMES:
        raw = getattr(theirs, f"_{name}")
        if raw is None:  # an unnamed root body: neither can prefix it
            with pytest.raises(TypeError):
                getattr(mine, name)
        elif isinstance(raw, list) and None in raw:  # robosuite raises TypeError; None stays
            assert getattr(mine, name) == [n if n is None else "0_" + n for n in raw], name
        else:
            assert getattr(mine, name) == getattr(theirs, name), name
    assert_view_matches_model(mine)


#: A model whose equality refers to sites (``site1``/``site2``), a texture known by its
#: file name, and a main default class.
SITE_WELD = """<mujoco>
  <asset><texture file="wood.png" type="2d"/><material name="m" texture="wood"/></asset>
  <worldbody><body name="base"><geom size="0.1" group="0"/><site name="a"/>
    <body name="arm" pos="0 0 0.3"><joint name="j" type="hinge"/><geom size="0.1" group="1"/>
    <site name="b"/></body></body></worldbody>
  <equality><weld site1="a" site2="b"/></equality>
</mujoco>"""


def test_prefixes_references_robosuite_misses(tmp_path: Path) -> None:
    """site1/site2 and file-named textures get the prefix with their targets; the model compiles."""
    path = tmp_path / "weld.xml"
    path.write_text(SITE_WELD)
    theirs, mine = _TheirModel(str(path), idn=0), _MyModel(str(path), idn=0)
    weld_theirs, weld_mine = theirs.equality[0], mine.equality[0]
    assert (weld_theirs.get("site1"), weld_theirs.get("site2")) == ("a", "b")
    assert (weld_mine.get("site1"), weld_mine.get("site2")) == ("0_a", "0_b")
    assert theirs.asset[0].get("name") is None and theirs.asset[1].get("texture") == "0_wood"
    assert mine.asset[0].get("name") == "0_wood" and mine.asset[1].get("texture") == "0_wood"
    mine.asset[0].set("file", str(Path(xml_path_completion("textures/wood-tiles.png"))))
    model = mine.get_model()
    assert model.neq == 1 and model.ntex == 1


def test_deep_object_file_is_read_without_recursion(tmp_path: Path) -> None:
    """An object 3,000 bodies deep reads: defaults inlined through childclass, geoms split."""
    depth = 3000
    inner = '<geom size="0.01"/>'
    for level in reversed(range(depth)):
        inner = f'<body name="b{level}"><geom size="0.01" group="1"/>{inner}</body>'
    path = tmp_path / "deep.xml"
    path.write_text(
        '<mujoco><default><default class="grey"><geom rgba="0.5 0.5 0.5 1"/></default></default>'
        '<worldbody><body><body name="object" childclass="grey">'
        f"{inner}</body></body></worldbody></mujoco>"
    )
    deep = ours.MujocoXMLObject(str(path), name="deep")
    geoms = list(deep.get_obj().iter("geom"))
    assert len(geoms) == depth + 2  # the innermost collision geom gains a visual twin
    assert all(geom.get("rgba") in ("0.5 0.5 0.5 1", "0.5 0 0 1") for geom in geoms)
    assert [geom.get("name") for geom in geoms[:2]] == ["deep_g0", "deep_g1"]
    assert geoms[-1].get("name") == f"deep_g{depth}_visual"
    assert all(element.get("childclass") is None for element in deep.get_obj().iter())
    assert len(deep.visual_geoms) == depth + 1 and deep.contact_geoms == [f"deep_g{depth}"]
    live = geoms[-2]
    deep.set_scale(2)  # the live elements handed out are patched in place, all the way down
    assert live.get("size") == "0.02" and next(deep.get_obj().iter("geom")) is geoms[0]
