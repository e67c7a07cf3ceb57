"""Tests of ``mjcf_model.serializers.exporting``."""

from __future__ import annotations

import shutil
from pathlib import Path

import mujoco
import pytest

from mjcf_model import (
    MjcfValueError,
    compiled,
)
from mjcf_model.serializers import dump, export, load, loads
from tests.conftest import corpus_id
from tests.support.model_files import _same, obj_mesh, with_files, write_tree

# -- Where a model's files are: compiled in memory, dumped elsewhere, exported, MuJoCo as
#    referee.


def test_export_is_self_contained_readable_and_movable(tmp_path: Path) -> None:
    """Export copies every file under its own name, once per content, and survives a move."""
    a = write_tree(tmp_path / "a", {"link.obj": obj_mesh(5), "same.obj": obj_mesh(9)})
    b = write_tree(tmp_path / "b", {"link.obj": obj_mesh(6), "same.obj": obj_mesh(9)})
    text = (
        '<mujoco model="two arms"><asset>'
        f'<mesh name="a" file="{a}/link.obj"/><mesh name="b" file="{b}/link.obj"/>'
        f'<mesh name="c" file="{a}/same.obj"/><mesh name="d" file="{b}/same.obj"/>'
        "</asset><worldbody>"
        + "".join(f'<geom type="mesh" mesh="{n}"/>' for n in "abcd")
        + "</worldbody></mujoco>"
    )
    model = loads(text)
    expected = mujoco.MjModel.from_xml_string(text)
    path = export(model, tmp_path / "out")
    assert path == tmp_path / "out" / "two_arms.xml"
    assert sorted(p.name for p in (tmp_path / "out" / "assets").iterdir()) == [
        "link.obj",
        "link_2.obj",
        "same.obj",
    ]
    moved = tmp_path / "moved"
    shutil.move(tmp_path / "out", moved)
    assert _same(mujoco.MjModel.from_xml_path(str(moved / path.name)), expected) == []
    with pytest.raises(MjcfValueError, match="not an empty folder"):
        export(model, moved)


def test_export_bundles_asset_models_with_their_own_files(tmp_path: Path) -> None:
    """An asset ``<model>`` file is exported with its meshes and still attaches identically."""
    folder = write_tree(
        tmp_path / "scene",
        {
            "scene.xml": '<mujoco><asset><model name="g" file="../gripper/gripper.xml"/></asset>'
            '<worldbody><body name="arm"><attach model="g" body="palm" prefix="g_"/></body>'
            "</worldbody></mujoco>",
            "../gripper/gripper.xml": '<mujoco><compiler meshdir="meshes"/>'
            '<asset><mesh name="finger" file="finger.obj"/></asset><worldbody><body name="palm">'
            '<geom type="mesh" mesh="finger"/></body></worldbody></mujoco>',
            "../gripper/meshes/finger.obj": obj_mesh(8),
        },
    )
    expected = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    assert _same(compiled(load(folder / "scene.xml")), expected) == []
    path = export(load(folder / "scene.xml"), tmp_path / "out")
    shutil.rmtree(tmp_path / "gripper")
    assert _same(mujoco.MjModel.from_xml_path(str(path)), expected) == []


@pytest.mark.parametrize("path", with_files(), ids=corpus_id)
def test_corpus_model_dumped_elsewhere_and_exported_compiles_identically(
    path: Path, tmp_path: Path
) -> None:
    """A corpus model dumped into a fresh folder, or exported and moved, compiles identically."""
    expected = mujoco.MjModel.from_xml_path(str(path))
    model = load(path, inline_includes=True)
    dumped = tmp_path / "dumped" / "model.xml"
    dumped.parent.mkdir()
    dump(model, dumped)
    assert _same(mujoco.MjModel.from_xml_path(str(dumped)), expected) == []
    exported = export(model, tmp_path / "exported")
    shutil.move(tmp_path / "exported", tmp_path / "moved")
    moved = tmp_path / "moved" / exported.name
    assert _same(mujoco.MjModel.from_xml_path(str(moved)), expected) == []


def test_export_tells_apart_names_that_differ_only_in_case(tmp_path: Path) -> None:
    """``Link.obj`` and ``link.obj`` are one file on macOS or Windows: the second is renamed."""
    a = write_tree(tmp_path / "a", {"Link.obj": obj_mesh(5)})
    b = write_tree(tmp_path / "b", {"link.obj": obj_mesh(6)})
    text = (
        f'<mujoco><asset><mesh name="a" file="{a}/Link.obj"/><mesh name="b" file="{b}/link.obj"/>'
        '</asset><worldbody><geom type="mesh" mesh="a"/><geom type="mesh" mesh="b"/>'
        "</worldbody></mujoco>"
    )
    path = export(loads(text), tmp_path / "out")
    assert sorted(p.name for p in (path.parent / "assets").iterdir()) == ["Link.obj", "link_2.obj"]
    expected = mujoco.MjModel.from_xml_string(text)
    assert _same(mujoco.MjModel.from_xml_path(str(path)), expected) == []
