"""Tests of ``mjcf_model.serializers.includes``."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import (
    Body,
    Comment,
    Geom,
    Include,
    Joint,
    MjcfIncludeCycleError,
    MjcfIncludeError,
    Site,
    Worldbody,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.serializers import dumps, load, loads
from tests.conftest import FIXTURES
from tests.support.fixture_checks import comments, compile_round_trip, names, section, walk
from tests.support.oracles import _compiled

# -- Round trips of hand-written MJCF fixtures for features the robosuite/dm_control corpus
#    lacks.
#
# Every fixture under ``tests/fixtures`` compiles in MuJoCo as written. Each must
# survive every serializer (text, file, ElementTree, dict) unchanged and compile,
# after the round trip, to a model identical field by field to the original.


INCLUDES = FIXTURES / "includes.xml"
INCLUDE_PARTS = (
    FIXTURES / "include_parts" / "common.xml",
    FIXTURES / "include_parts" / "robot.xml",
    FIXTURES / "include_parts" / "nested" / "hand.xml",
)


# -- includes -----------------------------------------------------------------------------


def test_includes_kept() -> None:
    """By default includes stay Include nodes and are written back as include elements."""
    model = load(INCLUDES)
    includes = [n for n in walk(model) if isinstance(n, Include)]
    assert [i.file for i in includes] == ["include_parts/common.xml", "include_parts/robot.xml"]
    assert model.children[1] == Include(file="include_parts/common.xml")
    assert [type(e) for e in section(model, Worldbody).elements] == [Geom, Include, Geom]
    written = dumps(model)
    assert '  <include file="include_parts/common.xml"/>\n' in written
    assert '    <include file="include_parts/robot.xml"/>\n' in written
    again = loads(written)
    assert [n for n in walk(again) if isinstance(n, Include)] == includes


def test_includes_inlined() -> None:
    """With inline_includes the included files' elements stand where the includes were."""
    kept = load(INCLUDES)
    model = load(INCLUDES, inline_includes=True)
    assert not any(isinstance(n, Include) for n in walk(model))
    assert "<include" not in dumps(model)
    common = load(INCLUDE_PARTS[0])
    assert model.children[0] == kept.children[0]
    assert model.children[1:5] == common.children
    assert model.children[5] == kept.children[2]
    assert model.children[6] is section(model, Worldbody)
    assert model.children[7:] == kept.children[4:]
    world = section(model, Worldbody).elements
    assert [(type(e), e.name) for e in world] == [
        (Geom, "floor"),
        (Body, "robot"),
        (Geom, "robot_plate"),
        (Geom, "after_robot"),
    ]
    robot = world[1]
    assert [type(e) for e in robot.elements] == [Joint, Geom, Body]
    hand = robot.bodies[0]
    assert [(type(e), e.name) for e in hand.elements] == [
        (Joint, "wrist"),
        (Geom, "palm"),
        (Site, "grip"),
    ]
    assert robot.children[-1] == Comment(text=" trailing comment after the included root ")


def test_inlined_comments_come_from_every_file() -> None:
    """Inlining keeps the comments of the main file and of every included file."""
    model = load(INCLUDES, inline_includes=True)
    sources = [INCLUDES, *INCLUDE_PARTS]
    expected = sum(p.read_text(encoding="utf-8").count("<!--") for p in sources)
    assert len(comments(model)) == expected == 4


def test_kept_and_inlined_compile_alike() -> None:
    """The kept and the inlined round trips compile to the same model."""
    kept = compile_round_trip(load(INCLUDES), INCLUDES)
    inlined = compile_round_trip(load(INCLUDES, inline_includes=True), INCLUDES)
    assert model_differences(kept, inlined) == []
    assert names(kept, mujoco.mjtObj.mjOBJ_BODY, kept.nbody) == ["world", "robot", "hand"]


def test_missing_include_raises(tmp_path: Path) -> None:
    """Inlining an include of a missing file names the including file and line."""
    main = tmp_path / "main.xml"
    main.write_text(
        '<mujoco>\n  <worldbody>\n    <include file="missing.xml"/>\n  </worldbody>\n</mujoco>\n'
    )
    with pytest.raises(MjcfIncludeError) as info:
        load(main, inline_includes=True)
    assert isinstance(info.value, OSError)
    message = str(info.value)
    assert f"{main}:3" in message
    assert "missing.xml" in message
    kept = load(main)
    assert section(kept, Worldbody).elements == (Include(file="missing.xml"),)


def test_missing_nested_include_names_the_nested_file(tmp_path: Path) -> None:
    """A missing include inside an included file is reported at that file and line."""
    (tmp_path / "sub").mkdir()
    main = tmp_path / "main.xml"
    main.write_text(
        '<mujoco>\n  <worldbody>\n    <include file="sub/a.xml"/>\n  </worldbody>\n</mujoco>\n'
    )
    part = tmp_path / "sub" / "a.xml"
    part.write_text(
        '<mujoco>\n  <body name="a">\n    <geom size="0.1"/>\n'
        '    <include file="gone.xml"/>\n  </body>\n</mujoco>\n'
    )
    with pytest.raises(MjcfIncludeError) as info:
        load(main, inline_includes=True)
    message = str(info.value)
    assert f"{part.resolve()}:4" in message
    assert "gone.xml" in message


def test_include_cycle_raises(tmp_path: Path) -> None:
    """Files that include each other raise an error that mentions the cycle."""
    a = tmp_path / "a.xml"
    b = tmp_path / "b.xml"
    a.write_text('<mujoco>\n  <include file="b.xml"/>\n</mujoco>\n')
    b.write_text('<mujoco>\n  <include file="a.xml"/>\n</mujoco>\n')
    with pytest.raises(MjcfIncludeCycleError, match="cycle") as info:
        load(a, inline_includes=True)
    assert isinstance(info.value, ValueError)
    assert f"{b.resolve()}:2" in str(info.value)
    with pytest.raises(ValueError, match="already included"):
        mujoco.MjModel.from_xml_path(str(a))


def test_self_include_raises(tmp_path: Path) -> None:
    """A file that includes itself is a cycle too."""
    a = tmp_path / "self.xml"
    a.write_text(
        '<mujoco>\n  <worldbody>\n    <include file="self.xml"/>\n  </worldbody>\n</mujoco>\n'
    )
    with pytest.raises(MjcfIncludeCycleError, match="cycle"):
        load(a, inline_includes=True)


# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


# -- depth -----------------------------------------------------------------------------


def test_include_chain_deeper_than_the_recursion_limit(tmp_path: Path) -> None:
    """MuJoCo follows include chains of any length (1,000 here); so does ``load``."""
    length = 1_000
    for index in range(length):
        inner = (
            f'<include file="part{index + 1}.xml"/>'
            if index + 1 < length
            else '<geom name="last" size="0.1"/>'
        )
        (tmp_path / f"part{index}.xml").write_text(f"<mujoco>{inner}</mujoco>")
    main = tmp_path / "main.xml"
    main.write_text('<mujoco><worldbody><include file="part0.xml"/></worldbody></mujoco>')
    compiled = mujoco.MjModel.from_xml_path(str(main))
    model = load(main, inline_includes=True)
    assert [g.name for g in model.worldbody.geoms] == ["last"]
    assert model_differences(compiled, _compiled(dumps(model))) == []


def test_include_root_may_be_any_element(tmp_path: Path) -> None:
    """MuJoCo takes the children of an included file's root, whatever its tag."""
    (tmp_path / "part.xml").write_text('<parts><geom name="g" size="1"/></parts>')
    main = tmp_path / "main.xml"
    main.write_text('<mujoco><worldbody><include file="part.xml"/></worldbody></mujoco>')
    compiled = mujoco.MjModel.from_xml_path(str(main))
    model = load(main, inline_includes=True)
    assert model_differences(compiled, _compiled(dumps(model))) == []


def test_include_name_too_long_is_an_include_error(tmp_path: Path) -> None:
    """``OSError: File name too long`` becomes an include error naming the element."""
    main = tmp_path / "main.xml"
    main.write_text(f'<mujoco><include file="{"x" * 5000}.xml"/></mujoco>')
    with pytest.raises(MjcfIncludeError) as caught:
        load(main, inline_includes=True)
    assert caught.value.line == 1 and caught.value.path == "/mujoco/include"
