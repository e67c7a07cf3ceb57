"""Tests of ``mjcf_model.tools.cli.info``."""

from __future__ import annotations

from pathlib import Path

from tests.support.cli import UNTIDY, run

# -- The verbs of ``mjcf-model`` run as a user runs them: a process, real files, exit codes. ---


def test_info_summary_and_element(tmp_path: Path) -> None:
    """Info lists counts, names, classes; --element names the class that gives each value."""
    arm = tmp_path / "arm.xml"
    arm.write_text(UNTIDY)
    summary = run("info", str(arm), "--defaults")
    assert summary.returncode == 0, summary.stderr
    assert "model: arm\n" in summary.stdout
    assert "  body (1): arm\n" in summary.stdout
    assert "    red: sets geom\n" in summary.stdout
    element = run("info", str(arm), "--element", "geom:upper")
    assert element.stdout.splitlines()[-1] == "rgba = 1 0 0 1 (class red)"
    assert run("info", str(arm), "--element", "upper").returncode == 2
    assert run("info", "-", stdin=UNTIDY).stdout == run("info", str(arm)).stdout
