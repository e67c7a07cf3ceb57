"""Tests of ``mjcf_model.tools.cli.fmt``."""

from __future__ import annotations

import os
from pathlib import Path

import mujoco
import pytest

from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.tools.cli import main
from tests.support.cli import UNTIDY, run

# -- The verbs of ``mjcf-model`` run as a user runs them: a process, real files, exit codes. ---


def test_fmt_check_write_then_clean(tmp_path: Path) -> None:
    """--check fails on an untidy file, fmt rewrites it, then --check passes: ruff's contract."""
    path = tmp_path / "arm.xml"
    path.write_text(UNTIDY)
    before = mujoco.MjModel.from_xml_path(str(path))
    checked = run("fmt", "--check", str(path))
    assert checked.returncode == 1 and f"would reformat {path}" in checked.stderr
    assert path.read_text() == UNTIDY
    written = run("fmt", str(path))
    assert written.returncode == 0, written.stderr
    assert "1 file reformatted, 0 files unchanged" in written.stderr
    assert path.read_text() != UNTIDY and "  <worldbody>\n" in path.read_text()
    after = mujoco.MjModel.from_xml_path(str(path))
    assert model_differences(before, after, ignore=path_fields()) == []
    assert run("fmt", "--check", str(path)).returncode == 0
    assert list(tmp_path.iterdir()) == [path]  # no temporary file left behind


def test_fmt_diff_and_stdin(tmp_path: Path) -> None:
    """--diff prints a unified diff and writes nothing; - reads stdin and writes stdout."""
    path = tmp_path / "arm.xml"
    path.write_text(UNTIDY)
    shown = run("fmt", "--diff", str(path))
    assert shown.returncode == 1
    assert shown.stdout.startswith(f"--- {path}\n+++ {path}\n@@")
    assert '+      <geom name="upper" size="0.10 0.2" type="capsule"/>' in shown.stdout
    assert path.read_text() == UNTIDY
    piped = run("fmt", "-", stdin=UNTIDY)
    assert piped.returncode == 0, piped.stderr
    assert piped.stdout.startswith('<mujoco model="arm">\n  <default>\n')
    assert run("fmt", "-", stdin=piped.stdout).stdout == piped.stdout


def test_fmt_refuses_a_rewrite_that_compiles_differently(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """When the proof fails the file is left as it was and the exit status is 2."""
    import mjcf_model.tools.formatting as formatting

    path = tmp_path / "arm.xml"
    path.write_text(UNTIDY)
    monkeypatch.setattr(formatting, "written_differences", lambda *args: ("geom_size",))
    assert main(["fmt", str(path)]) == 2
    assert "not rewritten, it changes the model: geom_size" in capsys.readouterr().err
    assert path.read_text() == UNTIDY


def test_fmt_keeps_the_file_when_the_write_fails(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """A write that fails half way leaves the old file whole and no temporary file."""
    path = tmp_path / "arm.xml"
    path.write_text(UNTIDY)

    def broken(source: object, target: object) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", broken)
    assert main(["fmt", "--quiet", str(path)]) == 2
    assert "cannot write: No space left on device" in capsys.readouterr().err
    assert path.read_text() == UNTIDY
    assert list(tmp_path.iterdir()) == [path]
