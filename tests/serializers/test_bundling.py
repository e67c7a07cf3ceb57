"""Tests of ``mjcf_model.serializers.bundling``: every file a model uses, under readable names."""

from __future__ import annotations

import errno
from pathlib import Path

import mujoco
import pytest

from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.errors import MjcfAssetError
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.serializers.bundling import bundled, bundled_on_disk
from tests.support.model_files import obj_mesh, write_tree

#: Three meshes: two files of one name in different folders, and a copy of the first.
MODEL = """<mujoco>
  <compiler meshdir="meshes"/>
  <asset>
    <mesh name="upper" file="arm/link.obj"/>
    <mesh name="lower" file="leg/link.obj"/>
    <mesh name="again" file="copy.obj"/>
  </asset>
  <worldbody>
    <geom type="mesh" mesh="upper"/><geom type="mesh" mesh="lower"/><geom type="mesh" mesh="again"/>
  </worldbody>
</mujoco>
"""


def _robot(root: Path) -> Path:
    files = {
        "robot.xml": MODEL,
        "meshes/arm/link.obj": obj_mesh(5),
        "meshes/leg/link.obj": obj_mesh(6),
        "meshes/copy.obj": obj_mesh(5),
    }
    return write_tree(root, files) / "robot.xml"


def test_a_bundle_compiles_from_memory_to_the_model_on_disk(tmp_path: Path) -> None:
    """Clashing names get ``_2``, equal contents are stored once; MuJoCo compiles it alike."""
    path = _robot(tmp_path)
    bundle = bundled(load(path), folder="assets/")
    assert [m.file for m in bundle.model.asset.meshes] == [
        "assets/link.obj",
        "assets/link_2.obj",
        "assets/link.obj",
    ]
    assert sorted(bundle.files) == ["link.obj", "link_2.obj"]
    assert bundle.files["link.obj"] == (tmp_path / "meshes/copy.obj").read_bytes()
    assets = {f"assets/{name}": data for name, data in bundle.files.items()}
    text = dumps(bundle.model)
    assert "meshdir" not in text  # the paths name the bundle's entries themselves
    in_memory = mujoco.MjModel.from_xml_string(text, assets)
    on_disk = mujoco.MjModel.from_xml_path(str(path))
    assert model_differences(on_disk, in_memory, ignore=path_fields()) == []


def test_names_differing_only_in_case_do_not_share_a_file(tmp_path: Path) -> None:
    """A folder on macOS or Windows could not hold both: the second is renamed."""
    model = loads(
        '<mujoco><asset><mesh name="a" file="A/Part.obj"/><mesh name="b" file="B/part.obj"/>'
        "</asset></mujoco>"
    )
    bundle = bundled(model, assets={"A/Part.obj": obj_mesh(4), "B/part.obj": obj_mesh(5)})
    assert [m.file for m in bundle.model.asset.meshes] == ["Part.obj", "part_2.obj"]


def test_files_on_disk_stay_where_they_are_and_missing_ones_are_refused(tmp_path: Path) -> None:
    """``bundled_on_disk`` names files MuJoCo reads itself by their absolute paths."""
    path = _robot(tmp_path)
    bundle = bundled_on_disk(load(path), {})
    assert bundle.files == {}
    assert [Path(m.file) for m in bundle.model.asset.meshes] == [
        (tmp_path / "meshes" / name).resolve()
        for name in ("arm/link.obj", "leg/link.obj", "copy.obj")
    ]
    with pytest.raises(MjcfAssetError) as missing:
        bundled(loads('<mujoco><asset><mesh file="gone.obj"/></asset></mujoco>'))
    assert "gone.obj" in str(missing.value) and "give loads() base_dir=" in str(missing.value)


def test_a_missing_file_of_a_loaded_model_is_located_in_its_file(tmp_path: Path) -> None:
    """The error names the model's file, line and element path, and the missing file.

    It carries the errno and advises putting the file in place (the model knows its folder).
    """
    path = tmp_path / "arm.xml"
    path.write_text(
        '<mujoco>\n<compiler meshdir="meshes"/>\n<asset>\n'
        '  <mesh name="hand" file="hand.stl"/>\n</asset>\n</mujoco>'
    )
    with pytest.raises(MjcfAssetError) as missing:
        bundled(load(path))
    error = missing.value
    where = (str(path), 4, "/mujoco/asset/mesh[@name='hand']")
    assert (error.file, error.line, error.path) == where
    assert error.errno == errno.ENOENT and error.filename == str(tmp_path / "meshes" / "hand.stl")
    assert "put the file where the model names it" in str(error)
    assert "load the model from its file" not in str(error)
