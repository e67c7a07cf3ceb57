"""``MujocoXML`` of ``mjcf_model.compat.objects`` against robosuite's, on robosuite's own files."""

from __future__ import annotations

import importlib.util
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import robosuite.models.base as rs_base
from robosuite.utils.mjcf_utils import xml_path_completion

from mjcf_model import MjcfValueError
from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_tree,
    assert_view_matches_model,
    text_of,
)


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
