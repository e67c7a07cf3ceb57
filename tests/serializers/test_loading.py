"""Tests of ``mjcf_model.serializers.loading``: text and files read into nodes."""

from __future__ import annotations

import errno
import io
from pathlib import Path

import mujoco
import pytest

from mjcf_model import (
    MjcfError,
    MjcfFileError,
    MjcfFileNotFoundError,
    MjcfSyntaxError,
    Mujoco,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.serializers import dumps, from_dict, load, loads, to_dict

#: A model that includes a file of its folder.
MAIN = """<mujoco model="main">
  <include file="parts/arm.xml"/>
  <worldbody><geom name="floor" type="plane" size="1 1 0.1"/></worldbody>
</mujoco>
"""
ARM = '<mujoco><worldbody><body name="arm"><geom size="0.1"/></body></worldbody></mujoco>'


def test_every_source_reads_the_model_mujoco_compiles(tmp_path: Path) -> None:
    """A path, an open file, text and bytes read alike; inlined includes compile as MuJoCo's."""
    (tmp_path / "parts").mkdir()
    (tmp_path / "parts" / "arm.xml").write_text(ARM)
    path = tmp_path / "main.xml"
    path.write_text(MAIN)
    kept = load(path)
    with path.open("rb") as stream:
        assert load(stream) == kept
    assert loads(MAIN) == loads(MAIN.encode()) == kept
    assert dumps(kept) == MAIN  # the include is kept as written
    inlined = load(path, inline_includes=True)
    assert [b.name for b in inlined.worldbody.bodies] == ["arm"]
    written = tmp_path / "inlined.xml"
    written.write_text(dumps(inlined))
    expected = mujoco.MjModel.from_xml_path(str(path))
    assert model_differences(expected, mujoco.MjModel.from_xml_path(str(written))) == []
    assert loads(MAIN, inline_includes=True, base_dir=tmp_path) == inlined


def test_errors_name_the_file_they_were_read_from() -> None:
    """Text reports ``<string>`` or the name given; an open file reports its own name."""
    broken = "<mujoco><worldbody></mujoco>"
    for read, name in (
        (lambda: loads(broken), "<string>"),
        (lambda: loads(broken, filename="scene.xml"), "scene.xml"),
    ):
        try:
            read()
        except MjcfSyntaxError as error:
            assert error.file == name and error.line == 1
        else:
            raise AssertionError("broken text was read")
    stream = io.BytesIO(broken.encode())
    try:
        load(stream)
    except MjcfSyntaxError as error:
        assert error.file == "<string>"
    else:
        raise AssertionError("broken text was read")


def test_a_loaded_model_knows_its_folder_and_equality_ignores_it(robot: Path) -> None:
    """``base_dir`` is the file's folder, kept by the dict form; ``==`` and ``hash`` ignore it."""
    model = load(robot)
    assert model.base_dir == robot.parent.resolve()
    again = loads(robot.read_text())
    assert again.base_dir is None and Mujoco().base_dir is None
    assert model == again and hash(model) == hash(again)
    assert from_dict(to_dict(model)) == model
    assert from_dict(to_dict(model)).base_dir == model.base_dir
    assert "base_dir" not in to_dict(again)
    assert loads("<mujoco/>", base_dir=robot.parent).base_dir == robot.parent.resolve()


def test_a_missing_main_file_is_a_file_not_found_error(tmp_path: Path) -> None:
    """``load`` and ``format_file`` of a missing file raise what ``open`` would, located."""
    from mjcf_model.tools.formatting import format_file

    missing = tmp_path / "no_such_model.xml"
    for read in (load, format_file):
        with pytest.raises(FileNotFoundError) as caught:
            read(missing)
        error = caught.value
        assert isinstance(error, MjcfFileNotFoundError) and isinstance(error, MjcfError)
        assert error.errno == errno.ENOENT and error.filename == str(missing)
        assert str(error) == f"cannot read {str(missing)!r}: No such file or directory"
    (tmp_path / "scene.xml").write_text("<mujoco/>")
    with pytest.raises(MjcfFileError) as folder:
        load(tmp_path)
    assert isinstance(folder.value, OSError) and folder.value.errno == errno.EISDIR
    assert str(folder.value) == (
        f"{str(tmp_path)!r} is a folder, not a file; name a model file in it: "
        f"{tmp_path / 'scene.xml'}"
    )
    with pytest.raises(MjcfFileError, match=r"^no file given: the path is empty; name the model"):
        load("")
