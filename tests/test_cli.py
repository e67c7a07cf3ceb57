"""The ``mjcf-model`` command line."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from mjcf_model.tools.check import CheckResult
from mjcf_model.tools.cli import example_path, main


def test_example_is_identical(capsys: pytest.CaptureFixture[str]) -> None:
    """The bundled example round-trips; the report says so and the exit status is 0."""
    assert main(["check", "--example"]) == 0
    out = capsys.readouterr().out
    assert f"identical     {example_path()}" in out
    assert "1 files: 1 identical" in out


def test_module_entry_point() -> None:
    """``python -m mjcf_model`` runs the same command line."""
    done = subprocess.run(
        [sys.executable, "-m", "mjcf_model", "check", "--example"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert "1 identical" in done.stdout


def test_errors_and_rejections(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A file MuJoCo rejects fails the run (``--strict`` is still taken); so do missing files."""
    rejected = tmp_path / "rejected.xml"
    rejected.write_text("<mujoco><worldbody><geom type='box'/></worldbody></mujoco>")
    assert main(["check", str(rejected)]) == 1
    assert main(["check", "--strict", str(rejected)]) == 1
    assert main(["check", str(tmp_path / "missing.xml")]) == 1
    out = capsys.readouterr().out
    assert f"not compiled  {rejected}" in out
    assert "ERROR" in out and "no such file" in out


def test_a_difference_fails_the_run(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """When the compiled models differ the fields are listed and the exit status is 1."""
    import mjcf_model.tools.cli.check as cli

    def differing(path: str, *, inline_includes: bool = False, part: bool = False) -> CheckResult:
        return CheckResult(path=str(path), status="different", differences=("geom_size",))

    monkeypatch.setattr(cli, "check_file", differing)
    assert main(["check", "--example"]) == 1
    assert "fields: geom_size" in capsys.readouterr().out


def test_no_files_is_a_usage_error(capsys: pytest.CaptureFixture[str]) -> None:
    """Without files or --example the command says what to do."""
    assert main(["check"]) == 2
    assert "--example" in capsys.readouterr().err


def test_written_model_that_does_not_compile_is_an_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """check_file reports an error, not a crash, when the written text does not compile."""
    import serializers
    from mjcf_model.tools.check import check_file

    path = tmp_path / "m.xml"
    path.write_text("<mujoco><worldbody><geom size='0.1'/></worldbody></mujoco>")
    assert check_file(path).ok
    monkeypatch.setattr(serializers, "dumps", lambda node: "<mujoco><nonsense/></mujoco>")
    result = check_file(path)
    assert result.status == "error"
    assert "the written model does not compile" in result.message
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.xml"]  # no temporary file left
