"""Tests of ``mjcf_model.serializers.dumping``."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from mjcf_model import (
    Comment,
    MjcfAssetError,
    Mujoco,
)
from mjcf_model.serializers import dump, load

# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


# -- nodes that cannot be written cannot be built --------------------------------------


def test_dump_of_any_buildable_node_loads_back(tmp_path: Path) -> None:
    """What can be built can be dumped to a file and read back equal."""
    model = Mujoco(model="é\U0001f600", children=[Comment(text=" ok ")])
    dump(model, tmp_path / "m.xml")
    assert load(tmp_path / "m.xml") == model


# -- Bad input raises an MjcfError subclass that says where (file, line, path) and what. -------


def _write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def test_atomic_dump_keeps_old_file_on_failure(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """If the final rename fails, the old file is intact and no temporary file is left."""
    target = _write(tmp_path / "model.xml", "<mujoco model='old'/>\n")

    def fail(*_: object) -> None:
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", fail)
    with pytest.raises(OSError, match="disk full"):
        dump(Mujoco(model="new"), target)
    assert target.read_text() == "<mujoco model='old'/>\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["model.xml"]


def test_atomic_dump_failure_while_writing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A failure in the middle of writing leaves neither a partial file nor a temporary one."""
    target = _write(tmp_path / "model.xml", "<mujoco model='old'/>\n")

    def fail(_fd: int) -> None:
        raise OSError("I/O error")

    monkeypatch.setattr(os, "fsync", fail)
    with pytest.raises(OSError, match="I/O error"):
        dump(Mujoco(model="new"), target)
    assert target.read_text() == "<mujoco model='old'/>\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["model.xml"]


@pytest.mark.parametrize("inside", ["scene.xml", "deeper/scene.xml"])
def test_dump_with_a_file_in_the_way_of_its_folder(tmp_path: Path, inside: str) -> None:
    """A file where a folder must be gives an MjcfAssetError naming it; nothing is written."""
    blocker = _write(tmp_path / "out", "not a folder")
    with pytest.raises(MjcfAssetError) as caught:
        dump(Mujoco(model="new"), blocker / inside)
    assert isinstance(caught.value, OSError)
    assert f"{str(blocker)!r} is a file, not a folder" in str(caught.value)
    assert ".tmp" not in str(caught.value)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    assert blocker.read_text() == "not a folder"


def test_dump_replaces_on_success(tmp_path: Path) -> None:
    """A successful dump replaces the file and keeps its permissions."""
    target = _write(tmp_path / "model.xml", "<mujoco model='old'/>\n")
    target.chmod(0o640)
    dump(Mujoco(model="new"), target)
    assert target.read_text() == '<mujoco model="new"/>\n'
    assert target.stat().st_mode & 0o777 == 0o640
