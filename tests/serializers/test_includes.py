"""Tests of ``mjcf_model.serializers.includes``."""

from __future__ import annotations

import re
from pathlib import Path

import mujoco
import pytest

from mjcf_model import (
    Body,
    Comment,
    Geom,
    Include,
    Joint,
    MjcfAssetError,
    MjcfIncludeCycleError,
    MjcfIncludeError,
    Site,
    Worldbody,
    compiled,
)
from mjcf_model.bridge.compare import model_differences, path_fields
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


#: A tetrahedron of edge ``{size}`` in OBJ text.
_TETRAHEDRON = (
    "v 0 0 0\nv {size} 0 0\nv 0 {size} 0\nv 0 0 {size}\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
)


@pytest.mark.parametrize("strippath", ["false", "true"])
def test_an_included_part_from_another_folder_reads_its_mesh_from_the_main_meshdir(
    tmp_path: Path, strippath: str
) -> None:
    """An included part's mesh is read from the main file's meshdir, not from beside it.

    The part (another folder, a mesh of its name beside it) names a mesh the main
    file's meshdir also holds: MuJoCo reads the meshdir's, and so do ``compiled``,
    ``inline_includes`` and the inlined text written beside the main file. Without it,
    MuJoCo looks beside the part, as mjcf-model does (with ``strippath``, neither finds it).
    """
    main, parts = tmp_path / "main", tmp_path / "parts"
    (main / "meshes").mkdir(parents=True)
    parts.mkdir()
    (parts / "tet.obj").write_text(_TETRAHEDRON.format(size=1))
    (main / "meshes" / "tet.obj").write_text(_TETRAHEDRON.format(size=2))
    (parts / "arm.xml").write_text(
        '<mujoco><asset><mesh name="m" file="tet.obj"/></asset><worldbody><body><freejoint/>'
        '<geom type="mesh" mesh="m"/></body></worldbody></mujoco>'
    )
    scene = main / "scene.xml"
    scene.write_text(
        f'<mujoco><compiler meshdir="meshes" strippath="{strippath}"/>'
        '<include file="../parts/arm.xml"/></mujoco>'
    )
    theirs = mujoco.MjModel.from_xml_path(str(scene))
    big = mujoco.MjModel.from_xml_string(
        '<mujoco><asset><mesh name="m" file="tet.obj"/></asset><worldbody><body><freejoint/>'
        '<geom type="mesh" mesh="m"/></body></worldbody></mujoco>',
        {"tet.obj": _TETRAHEDRON.format(size=2).encode()},
    )
    assert theirs.mesh_vert.tolist() == big.mesh_vert.tolist()  # the meshdir's, twice as big
    inlined = load(scene, inline_includes=True)
    (main / "inlined.xml").write_text(dumps(inlined))
    for ours in (
        compiled(load(scene)),
        compiled(inlined),
        mujoco.MjModel.from_xml_path(str(main / "inlined.xml")),
    ):
        assert model_differences(theirs, ours, ignore=path_fields()) == []
    # Without the meshdir's file MuJoCo, given the main file's absolute path, looks beside
    # the part (unless strippath drops the folders); compiled(load()) does the same.
    (main / "meshes" / "tet.obj").unlink()
    mujoco.mj_clearCache(mujoco.mj_getCache())  # else MuJoCo serves the decoded mesh again
    if strippath == "false":
        theirs = mujoco.MjModel.from_xml_path(str(scene.resolve()))
        assert theirs.mesh_vert.tolist() != big.mesh_vert.tolist()  # the part's own mesh
        for ours in (compiled(load(scene)), compiled(load(scene, inline_includes=True))):
            assert model_differences(theirs, ours, ignore=path_fields()) == []
    else:
        with pytest.raises(ValueError, match=re.escape("meshes/tet.obj")):
            mujoco.MjModel.from_xml_path(str(scene.resolve()))
        missing = re.escape(f"cannot read {str(main / 'meshes' / 'tet.obj')!r}")
        with pytest.raises(MjcfAssetError, match=missing):
            compiled(load(scene))
