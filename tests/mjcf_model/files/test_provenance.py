"""Tests of ``mjcf_model.files.provenance``."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import mujoco
import pytest

from mjcf_model import (
    MjcfValueError,
    compiled,
    map_elements,
    with_attributes,
)
from mjcf_model.files.provenance import (
    Folders,
    element_file_references,
    file_references,
    with_paths,
)
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers import dump, dumps, load, loads
from tests.conftest import compiling_corpus, corpus_id
from tests.support.model_files import ROBOT, _same, obj_mesh, with_files, write_tree

# -- Where a model's files are: compiled in memory, dumped elsewhere, exported, MuJoCo as
#    referee.


def test_dump_elsewhere_relocates_and_dump_in_place_keeps_the_text(
    robot: Path, tmp_path: Path
) -> None:
    """Dumped into another folder the model compiles identically; in place its text is kept."""
    expected = mujoco.MjModel.from_xml_path(str(robot))
    model = load(robot)
    elsewhere = tmp_path / "scenes" / "deep" / "scene.xml"
    elsewhere.parent.mkdir(parents=True)
    dump(model, elsewhere)
    assert _same(mujoco.MjModel.from_xml_path(str(elsewhere)), expected) == []
    assert 'file="../../../robots/arm/assets/link.obj"' in elsewhere.read_text()
    beside = robot.parent / "copy.xml"
    dump(model, beside)
    assert beside.read_text() == dumps(model)
    assert _same(mujoco.MjModel.from_xml_path(str(beside)), expected) == []


def test_dump_creates_missing_folders(robot: Path, tmp_path: Path) -> None:
    """Dumped into folders that do not exist yet, they are made and the model compiles the same."""
    expected = mujoco.MjModel.from_xml_path(str(robot))
    target = tmp_path / "out" / "nested" / "scene.xml"
    dump(load(robot), target)
    assert sorted(p.name for p in target.parent.iterdir()) == ["scene.xml"]
    assert _same(mujoco.MjModel.from_xml_path(str(target)), expected) == []


def test_a_model_built_in_code_is_dumped_as_written(tmp_path: Path) -> None:
    """Without a folder of its own, a model's paths are written unchanged."""
    path = tmp_path / "m.xml"
    dump(loads(ROBOT), path)
    assert path.read_text() == dumps(loads(ROBOT))


def test_kept_includes_are_relocated(tmp_path: Path) -> None:
    """An ``<include>`` kept as such names its file from the folder the model is dumped to."""
    folder = write_tree(
        tmp_path / "model",
        {
            "main.xml": '<mujoco><include file="parts/arm.xml"/></mujoco>',
            "parts/arm.xml": '<mujoco><asset><mesh name="m" file="m.obj"/></asset>'
            '<worldbody><geom type="mesh" mesh="m"/></worldbody></mujoco>',
            "parts/m.obj": obj_mesh(5),
        },
    )
    expected = mujoco.MjModel.from_xml_path(str(folder / "main.xml"))
    target = tmp_path / "elsewhere" / "main.xml"
    target.parent.mkdir()
    dump(load(folder / "main.xml"), target)
    assert _same(mujoco.MjModel.from_xml_path(str(target)), expected) == []
    assert _same(compiled(load(folder / "main.xml")), expected) == []


def test_dump_refuses_to_lose_a_file_an_included_file_names(tmp_path: Path) -> None:
    """A kept include naming a file under the main folder cannot move: the error says why."""
    folder = write_tree(
        tmp_path / "model",
        {
            "main.xml": '<mujoco><compiler meshdir="meshes"/><include file="parts/arm.xml"/>'
            '<worldbody><geom type="mesh" mesh="m"/></worldbody></mujoco>',
            "parts/arm.xml": '<mujoco><asset><mesh name="m" file="m.obj"/></asset></mujoco>',
            "meshes/m.obj": obj_mesh(5),
        },
    )
    mujoco.MjModel.from_xml_path(str(folder / "main.xml"))
    target = tmp_path / "elsewhere" / "main.xml"
    target.parent.mkdir()
    with pytest.raises(MjcfValueError, match="inline_includes=True"):
        dump(load(folder / "main.xml"), target)
    assert not target.exists()
    dump(load(folder / "main.xml", inline_includes=True), target)
    expected = mujoco.MjModel.from_xml_path(str(folder / "main.xml"))
    assert _same(mujoco.MjModel.from_xml_path(str(target)), expected) == []


INCLUDED = '<mujoco><asset><mesh name="m" file="m.obj"/></asset></mujoco>'
USES_MESH = '<worldbody><geom type="mesh" mesh="m"/></worldbody></mujoco>'


@pytest.mark.parametrize(
    ("files", "points"),
    [
        ({"sub/m.obj": obj_mesh(5)}, 5),
        ({"sub/m.obj": obj_mesh(5), "m.obj": obj_mesh(6)}, 6),
        ({"sub/deeper/m.obj": obj_mesh(7)}, 7),
    ],
    ids=["beside-include", "main-folder-first", "beside-innermost"],
)
def test_inlined_includes_name_files_as_mujoco_finds_them(
    tmp_path: Path, files: dict[str, str], points: int
) -> None:
    """A path in an included file names, once inlined, the file MuJoCo reads for it."""
    deeper = "deeper" in next(iter(files))
    files = {
        "main.xml": '<mujoco><include file="sub/inc.xml"/>' + USES_MESH,
        "sub/inc.xml": '<mujoco><include file="deeper/inc.xml"/></mujoco>' if deeper else INCLUDED,
        "sub/deeper/inc.xml": INCLUDED,
        **files,
    }
    main = write_tree(tmp_path, files) / "main.xml"
    expected = mujoco.MjModel.from_xml_path(str(main))
    assert expected.mesh_vertnum.tolist() == [points]
    inlined = load(main, inline_includes=True)
    assert _same(compiled(inlined), expected) == []
    written = tmp_path / "written.xml"
    written.write_text(dumps(inlined))
    assert _same(mujoco.MjModel.from_xml_path(str(written)), expected) == []


def test_most_of_the_corpus_names_files() -> None:
    """The relocation corpus is not trivially small."""
    assert len(with_files()) >= 40


def test_a_linked_model_resolves_from_the_links_folder(tmp_path: Path) -> None:
    """A model read through a symbolic link finds its files beside the link, as MuJoCo does."""
    real = write_tree(tmp_path / "real", {"robot.xml": ROBOT.replace('meshdir="assets" ', "")})
    linked = write_tree(tmp_path / "linked", {"link.obj": obj_mesh(7)})
    (linked / "robot.xml").symlink_to(real / "robot.xml")
    expected = mujoco.MjModel.from_xml_path(str(linked / "robot.xml"))
    model = load(linked / "robot.xml")
    assert model.base_dir == linked.resolve()
    assert _same(compiled(model), expected) == []


def test_a_later_assetdir_overrides_an_earlier_meshdir(tmp_path: Path) -> None:
    """Compiler sections are read in order: assetdir sets both folders, as MuJoCo reads it."""
    text = ROBOT.replace(
        '<compiler meshdir="assets" texturedir="textures" angle="radian"/>',
        '<compiler meshdir="assets"/><compiler assetdir="shared"/>',
    )
    folder = write_tree(tmp_path / "m", {"robot.xml": text, "shared/link.obj": obj_mesh(8)})
    expected = mujoco.MjModel.from_xml_path(str(folder / "robot.xml"))
    assert _same(compiled(load(folder / "robot.xml")), expected) == []


def test_a_compiler_inside_a_kept_include_is_honoured_when_dumping_elsewhere(
    tmp_path: Path,
) -> None:
    """The mesh folder an included file sets still holds after the model moves."""
    folder = write_tree(
        tmp_path / "model",
        {
            "main.xml": '<mujoco><include file="settings.xml"/><asset><mesh name="m" '
            'file="m.obj"/></asset><worldbody><geom type="mesh" mesh="m"/></worldbody></mujoco>',
            "settings.xml": '<mujoco><compiler meshdir="meshes"/></mujoco>',
            "meshes/m.obj": obj_mesh(6),
        },
    )
    expected = mujoco.MjModel.from_xml_path(str(folder / "main.xml"))
    target = tmp_path / "elsewhere" / "main.xml"
    target.parent.mkdir()
    dump(load(folder / "main.xml"), target)
    assert _same(mujoco.MjModel.from_xml_path(str(target)), expected) == []


def test_dump_to_an_open_file_relocates_to_its_folder(robot: Path, tmp_path: Path) -> None:
    """An open file names its path, as load reads it: the model is relocated there too."""
    target = tmp_path / "scenes" / "scene.xml"
    target.parent.mkdir()
    with open(target, "w", encoding="utf-8") as stream:
        dump(load(robot), stream)
    expected = mujoco.MjModel.from_xml_path(str(robot))
    assert _same(mujoco.MjModel.from_xml_path(str(target)), expected) == []


def _every_path_rewritten(model: Mujoco) -> Mujoco:
    """The reference: every element visited by a walk, its file paths upper-cased."""
    folders = Folders.of(model)

    def visit(element: Any, key: str | None, ancestors: Any) -> Any:
        changes = {
            reference.attribute: reference.text.upper()
            for reference in element_file_references(element, key, folders, model.base_dir)
        }
        return with_attributes(element, changes)

    return map_elements(visit, model)


@pytest.mark.parametrize("path", compiling_corpus(), ids=corpus_id)
def test_with_paths_rewrites_what_a_walk_of_every_element_rewrites(path: Path) -> None:
    """Where the files stand in ``<asset>`` only those sections are rebuilt: the same result."""
    model = load(path)
    assert with_paths(model, lambda r: r.text.upper()) == _every_path_rewritten(model)


def test_with_paths_finds_file_paths_outside_the_asset_section() -> None:
    """A flexcomp's file in the worldbody, a default class's mesh, a kept include: all found."""
    model = loads(
        '<mujoco><default><mesh scale="2 2 2"/></default>'
        '<asset><mesh name="m" file="m.stl"/><texture name="t" type="2d" file="t.png"/></asset>'
        '<include file="part.xml"/>'
        '<worldbody><body><flexcomp name="f" type="mesh" file="f.obj" dim="2"/></body>'
        "</worldbody></mujoco>"
    )
    rewritten = with_paths(model, lambda r: r.text.upper())
    assert rewritten == _every_path_rewritten(model)
    texts = [r.text for r in file_references(rewritten)]
    assert sorted(texts) == ["F.OBJ", "M.STL", "PART.XML", "T.PNG"]
