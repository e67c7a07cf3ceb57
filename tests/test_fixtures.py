"""Round trips of hand-written MJCF fixtures for features the robosuite/dm_control corpus lacks.

Every fixture under ``tests/fixtures`` compiles in MuJoCo as written. Each must
survive every serializer (text, file, ElementTree, dict) unchanged and compile,
after the round trip, to a model identical field by field to the original.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from pathlib import Path

import mujoco
import pytest

from mjcf_model import (
    Actuator,
    Asset,
    Attach,
    Body,
    Comment,
    Default,
    Deformable,
    Element,
    Equality,
    Extension,
    ExtensionPlugin,
    Flex,
    Flexcomp,
    FlexcompEdge,
    FlexcompPin,
    FlexContact,
    FlexElasticity,
    Frame,
    GenericElement,
    Geom,
    Key,
    Keyframe,
    Model,
    PluginConfig,
    PluginInstance,
    Replicate,
    Sensor,
    Tendon,
    Worldbody,
)
from mjcf_model.serializers import (
    dump,
    dumps,
    from_dict,
    from_etree,
    load,
    loads,
    to_dict,
    to_etree,
)
from mjcf_model.tools.check import check_file
from tests.conftest import FIXTURES
from tests.support.fixture_checks import comments, compile_round_trip, names, section, walk

#: Every top-level fixture; the included parts live in ``fixtures/include_parts``.
FIXTURE_NAMES = (
    "attach.xml",
    "attach_gripper.xml",
    "comments.xml",
    "defaults.xml",
    "flex.xml",
    "frames.xml",
    "includes.xml",
    "keyframes.xml",
    "mechanics.xml",
    "plugins.xml",
    "replicate.xml",
)
FIXTURE_PATHS = [FIXTURES / name for name in FIXTURE_NAMES]


_COMMENT = re.compile(r"<!--(.*?)-->", re.DOTALL)

fixture_path = pytest.mark.parametrize("path", FIXTURE_PATHS, ids=FIXTURE_NAMES)


# -- the fixture set ----------------------------------------------------------------------


def test_fixture_list_is_complete() -> None:
    """Every top-level XML file in the fixtures directory is in the parametrized list."""
    assert sorted(p.name for p in FIXTURES.glob("*.xml")) == sorted(FIXTURE_NAMES)


@fixture_path
def test_fixture_compiles_in_mujoco(path: Path) -> None:
    """MuJoCo compiles the fixture as written."""
    model = mujoco.MjModel.from_xml_path(str(path))
    assert model.nbody >= 1


# -- round trips every fixture must survive -----------------------------------------------


@fixture_path
@pytest.mark.parametrize("inline_includes", [False, True], ids=["kept", "inlined"])
def test_check_file_identical(path: Path, inline_includes: bool) -> None:
    """The round-tripped text compiles to a model identical to the original."""
    result = check_file(path, inline_includes=inline_includes)
    assert (result.status, result.differences, result.message) == ("identical", (), "")
    assert result.ok


@fixture_path
def test_text_idempotent(path: Path) -> None:
    """Writing, reading and writing again gives the same text."""
    model = load(path)
    text = dumps(model)
    assert dumps(loads(text)) == text


@fixture_path
def test_text_round_trip(path: Path) -> None:
    """Reading the written text gives an equal model."""
    model = load(path)
    assert loads(dumps(model)) == model


@fixture_path
def test_file_round_trip(path: Path, tmp_path: Path) -> None:
    """Dumping to a file and loading it back gives an equal model and the same text.

    The model is read from text, so it has no folder of its own and is written as
    it is (a loaded model dumped elsewhere is relocated: tests/mjcf_model/files/test_provenance.py).
    """
    model = loads(path.read_bytes())
    target = tmp_path / path.name
    dump(model, target)
    assert target.read_text(encoding="utf-8") == dumps(model)
    assert load(target) == model


@fixture_path
def test_etree_round_trip(path: Path) -> None:
    """Converting to ElementTree and back gives an equal model."""
    model = load(path)
    assert from_etree(to_etree(model)) == model


@fixture_path
def test_dict_round_trip(path: Path) -> None:
    """Converting to a dict and back gives an equal model; the dict is strict JSON."""
    model = load(path)
    data = to_dict(model)
    assert from_dict(data) == model
    assert from_dict(json.loads(json.dumps(data, allow_nan=False))) == model


@fixture_path
def test_every_element_typed(path: Path) -> None:
    """Every element of the fixture is read as a typed node, not a generic one."""
    for inline_includes in (False, True):
        model = load(path, inline_includes=inline_includes)
        generic = [n.tag for n in walk(model) if isinstance(n, GenericElement)]
        assert generic == []


@fixture_path
def test_comments_survive(path: Path) -> None:
    """Every comment of the source is a Comment node and is written back."""
    source = path.read_text(encoding="utf-8")
    model = load(path)
    texts = comments(model)
    assert len(texts) == source.count("<!--")
    written = dumps(model)
    for text in texts:
        assert f"<!--{text}-->" in written


@fixture_path
def test_comments_in_document_order(path: Path) -> None:
    """The comment nodes, in tree order, are the source's comments in document order."""
    source = path.read_text(encoding="utf-8")
    model = load(path)
    assert comments(model) == _COMMENT.findall(source)
    assert comments(loads(dumps(model))) == _COMMENT.findall(source)


# -- comments -----------------------------------------------------------------------------


def test_comments_around_root_become_first_and_last_children() -> None:
    """Comments before and after the root element are the root's first and last children."""
    model = load(FIXTURES / "comments.xml")
    first, second = model.children[:2]
    assert first == Comment(text=" Comment before the root element. ")
    assert second == Comment(text="two comments in a row before the root")
    assert model.children[-2] == Comment(text=" Comment after the root element. ")
    assert model.children[-1] == Comment(
        text=" Second comment after the root, with entities left alone: &amp; &lt; "
    )


def test_comments_in_odd_places() -> None:
    """Comments keep their position among siblings in bodies, sections and tendons."""
    model = load(FIXTURES / "comments.xml")
    torso = section(model, Worldbody).bodies[0]
    assert torso.children[-1] == Comment(text=" last child of the torso body ")
    empty = torso.bodies[0]
    assert empty.children == (Comment(text=" a body whose only content is a comment "),)
    anchor = section(model, Worldbody).bodies[1]
    assert anchor.children[1:] == (
        Comment(text=" one "),
        Comment(text=" two "),
        Comment(text=" three consecutive comments "),
    )
    assert section(model, Sensor).children == (Comment(text=" otherwise empty sensor section "),)
    assert len(section(model, Actuator).children) == 1
    assert isinstance(section(model, Actuator).children[0], Comment)
    strap = section(model, Tendon).elements[0]
    kinds = ["comment" if isinstance(c, Comment) else c.site for c in strap.children]
    assert kinds == ["s1", "comment", "s3", "comment", "s2"]
    symbols = [t for t in comments(model) if "Symbols" in t]
    assert symbols == [""" Symbols: a < b > c & d; "quotes" and 'apostrophes' """]
    assert any("日本語" in t and "🤖" in t for t in comments(model))


def test_comment_text_is_written_verbatim() -> None:
    """Markup characters and unicode in comments are written unescaped, as in the source."""
    written = dumps(load(FIXTURES / "comments.xml"))
    assert """<!-- Symbols: a < b > c & d; "quotes" and 'apostrophes' -->""" in written
    assert "Ωμέγα, 日本語, emoji 🤖" in written
    assert "with odd   indentation\tand a tab -->" in written
    assert '<text name="note" data="a &amp; b &lt;c&gt; &quot;d&quot; é"/>' in written


# -- frames -------------------------------------------------------------------------------


def _own_geoms(container: Element) -> list[str]:
    """Return the geom names of one body in document order, looking through frames."""
    found: list[str] = []
    for child in container.children:
        if isinstance(child, Geom):
            assert child.name is not None
            found.append(child.name)
        elif isinstance(child, Frame):
            found.extend(_own_geoms(child))
    return found


def _bodies_in_order(container: Element) -> Iterator[Body]:
    """Yield the bodies below a container in MuJoCo's id order (depth first, through frames)."""
    for child in container.children:
        if isinstance(child, Body):
            yield child
            yield from _bodies_in_order(child)
        elif isinstance(child, Frame):
            yield from _bodies_in_order(child)


def test_frame_geom_order_follows_document() -> None:
    """Compiled geom ids follow the document order of geoms interleaved with frames."""
    path = FIXTURES / "frames.xml"
    model = load(path)
    world = section(model, Worldbody)
    expected = _own_geoms(world)
    assert expected == [
        "floor",
        "table_top",
        "leg_a",
        "leg_b",
        "table_edge",
        "wall",
        "marker",
        "scaled_box",
        "last",
    ]
    for body in _bodies_in_order(world):
        expected.extend(_own_geoms(body))
    original = mujoco.MjModel.from_xml_path(str(path))
    assert names(original, mujoco.mjtObj.mjOBJ_GEOM, original.ngeom) == expected
    again = compile_round_trip(model, path)
    assert names(again, mujoco.mjtObj.mjOBJ_GEOM, again.ngeom) == expected
    geom_tags = re.compile(r'<geom name="([^"]+)"')
    assert geom_tags.findall(dumps(model)) == geom_tags.findall(path.read_text(encoding="utf-8"))


def test_frames_keep_childclass_and_unmodelled_attributes() -> None:
    """Frames are typed, keep their childclass, and keep attributes like scale as extras."""
    model = load(FIXTURES / "frames.xml")
    frames = {f.name: f for f in walk(model) if isinstance(f, Frame)}
    assert {"table_frame", "leg_frame", "elbow_frame", "inner_frame", "outer", "scaled"} <= set(
        frames
    )
    assert frames["leg_frame"].childclass == "red"
    assert frames["inner_frame"].childclass == "red"
    assert frames["table_frame"].euler == (0.0, 0.0, 0.3)
    assert frames["inner_frame"].xyaxes == (0.0, 1.0, 0.0, -1.0, 0.0, 0.0)
    assert [f.name for f in frames["outer"].frames] == ["middle"]
    assert dict(frames["scaled"].extra) == {"scale": "2", "scaling": "geometry"}
    written = dumps(model)
    assert '<frame name="scaled" pos="0 -1 0.2" scale="2" scaling="geometry">' in written
    assert '<frame name="leg_frame" pos="0 0 -0.2" childclass="red">' in written


# -- replicate ----------------------------------------------------------------------------


def test_replicate_attributes_are_typed() -> None:
    """Replicate elements keep count, offset, euler and sep as typed values."""
    model = load(FIXTURES / "replicate.xml")
    replicates = [n for n in walk(model) if isinstance(n, Replicate)]
    assert [(r.count, r.offset, r.euler, r.sep) for r in replicates] == [
        (4, (0.3, 0.0, 0.0), None, None),
        (6, None, (0.0, 0.0, 60.0), "_"),
        (2, (0.0, -1.0, 0.0), (0.0, 0.0, 90.0), None),
        (3, (0.2, 0.0, 0.0), None, "-"),
    ]


def test_replicate_names_get_suffixes_after_round_trip() -> None:
    """The round-tripped replicates compile to the same suffixed names."""
    path = FIXTURES / "replicate.xml"
    again = compile_round_trip(load(path), path)
    bodies = names(again, mujoco.mjtObj.mjOBJ_BODY, again.nbody)
    assert bodies[1:5] == ["post0", "post1", "post2", "post3"]
    assert [f"pin_{i}" for i in range(6)] == bodies[6:12]
    assert bodies[12:] == ["cell-00", "cell-10", "cell-20", "cell-01", "cell-11", "cell-21"]
    sensors = names(again, mujoco.mjtObj.mjOBJ_SENSOR, again.nsensor)
    assert "cube_acc-21" in sensors
    assert "pin_q_5" in sensors
    sites = names(again, mujoco.mjtObj.mjOBJ_SITE, again.nsite)
    assert "post_top3" in sites


# -- attach -------------------------------------------------------------------------------


def test_attach_and_model_asset() -> None:
    """The model asset and the attach elements are typed and compile with their prefixes."""
    path = FIXTURES / "attach.xml"
    model = load(path)
    assert section(model, Asset).elements == (Model(name="gripper", file="attach_gripper.xml"),)
    attaches = [n for n in walk(model) if isinstance(n, Attach)]
    assert [(a.model, a.body, a.prefix) for a in attaches] == [
        ("gripper", "palm", "g1_"),
        ("gripper", "palm", "g2_"),
        ("gripper", "left", "g3_"),
    ]
    again = compile_round_trip(model, path)
    bodies = names(again, mujoco.mjtObj.mjOBJ_BODY, again.nbody)
    assert {"g1_palm", "g1_left", "g2_right", "g3_left"} <= set(bodies)
    assert names(again, mujoco.mjtObj.mjOBJ_ACTUATOR, again.nu) == [
        "lift_act",
        "g1_close",
        "g2_close",
    ]


# -- plugins ------------------------------------------------------------------------------


def test_plugins_are_typed_and_compile() -> None:
    """Extension plugins, instances and configs are typed; the plugins compile again."""
    path = FIXTURES / "plugins.xml"
    model = load(path)
    declared = [
        p.plugin for p in section(model, Extension).elements if isinstance(p, ExtensionPlugin)
    ]
    assert declared == ["mujoco.pid", "mujoco.sdf.torus", "mujoco.sensor.touch_grid"]
    instances = [n.name for n in walk(model) if isinstance(n, PluginInstance)]
    assert instances == ["pid_hinge", "donut"]
    configs = [(c.key, c.value) for c in walk(model) if isinstance(c, PluginConfig)]
    assert ("radius1", "0.2") in configs
    assert ("size", "4 4") in configs
    again = compile_round_trip(model, path)
    assert (again.nplugin, again.nu, again.na) == (4, 2, 1)


# -- flex ---------------------------------------------------------------------------------


def test_flexcomp_and_deformable_are_typed() -> None:
    """Flexcomps and their edge, elasticity, contact and pin children are typed."""
    model = load(FIXTURES / "flex.xml")
    flexcomps = {f.name: f for f in walk(model) if isinstance(f, Flexcomp)}
    assert sorted(flexcomps) == ["cloth", "jelly", "rope"]
    cloth_kinds = [type(c) for c in flexcomps["cloth"].elements]
    assert cloth_kinds == [FlexcompEdge, FlexContact, FlexcompPin]
    assert [type(c) for c in flexcomps["jelly"].elements] == [FlexElasticity, FlexContact]
    flexes = [f for f in section(model, Deformable).elements if isinstance(f, Flex)]
    assert [f.name for f in flexes] == ["triangle"]
    original = mujoco.MjModel.from_xml_path(str(FIXTURES / "flex.xml"))
    assert original.nflex == 4


# -- defaults -----------------------------------------------------------------------------


def _class_tree(default: Default) -> list[object]:
    """Return the nesting of default classes as nested lists of class names."""
    return [default.dclass, [_class_tree(d) for d in default.elements if isinstance(d, Default)]]


def test_nested_default_classes() -> None:
    """Three levels of default classes keep their nesting and childclass references."""
    path = FIXTURES / "defaults.xml"
    model = load(path)
    assert _class_tree(section(model, Default)) == [
        None,
        [
            ["robot", [["link", [["fingertip", []]]], ["sensor_site", []]]],
            ["prop", [["prop_wide", []]]],
        ],
    ]
    bodies = {b.name: b for b in walk(model) if isinstance(b, Body)}
    assert [bodies[n].childclass for n in ("base", "link1", "link2", "tip")] == [
        "robot",
        "link",
        None,
        "fingertip",
    ]
    again = compile_round_trip(model, path)
    tip = mujoco.mj_name2id(again, mujoco.mjtObj.mjOBJ_GEOM, "tip_geom")
    assert (again.geom_condim[tip], again.geom_priority[tip]) == (6, 1)
    j3 = mujoco.mj_name2id(again, mujoco.mjtObj.mjOBJ_JOINT, "j3")
    assert again.jnt_type[j3] == mujoco.mjtJoint.mjJNT_SLIDE


# -- keyframes ----------------------------------------------------------------------------


def test_keyframes_keep_every_vector() -> None:
    """Keys keep qpos, qvel, ctrl, act and the mocap vectors of all mocap bodies."""
    path = FIXTURES / "keyframes.xml"
    model = load(path)
    keys = {k.name: k for k in section(model, Keyframe).elements if isinstance(k, Key)}
    assert keys["tilted"].time == 0.5
    assert keys["tilted"].act == (0.25, -0.5)
    moved = keys["mocap_moved"]
    assert moved.mpos == (0.1, 0.2, 0.3, -0.1, -0.2, 0.6)
    assert moved.mquat == (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    again = compile_round_trip(model, path)
    original = mujoco.MjModel.from_xml_path(str(path))
    assert again.nkey == original.nkey == 4
    assert (again.key_mquat == original.key_mquat).all()


# -- mechanics ----------------------------------------------------------------------------


def test_mechanics_counts_after_round_trip() -> None:
    """Actuators, tendons, equalities, sensors and contact pairs all survive."""
    path = FIXTURES / "mechanics.xml"
    model = load(path)
    kinds = [type(a).__name__ for a in section(model, Actuator).elements]
    assert kinds == [
        "Motor",
        "Position",
        "Velocity",
        "General",
        "General",
        "Muscle",
        "Muscle",
        "Adhesion",
        "Cylinder",
        "Damper",
        "Motor",
        "IntVelocity",
    ]
    equalities = [type(e).__name__ for e in section(model, Equality).elements]
    assert equalities == [
        "Connect",
        "Connect",
        "Weld",
        "Weld",
        "EqualityJoint",
        "EqualityJoint",
        "EqualityTendon",
    ]
    rope = next(t for t in section(model, Tendon).elements if getattr(t, "name", None) == "rope")
    assert [c.tag for c in rope.elements] == ["site", "site", "pulley", "site", "site"]
    again = compile_round_trip(model, path)
    counts = (again.nu, again.ntendon, again.neq, again.nsensor, again.npair, again.nexclude)
    assert counts == (12, 5, 7, 25, 2, 2)
