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


def test_an_unknown_element_lists_the_names_there_are(tmp_path: Path) -> None:
    """``--element KIND:NAME`` for a name the model lacks lists its names of that kind."""
    many = "".join(f'<geom name="g{i}" size="0.1"/>' for i in range(15))
    model = tmp_path / "many.xml"
    model.write_text(f"<mujoco><worldbody>{many}</worldbody></mujoco>")
    done = run("info", str(model), "--element", "geom:nosuch")
    listed = ", ".join(f"g{i}" for i in range(12))
    assert done.returncode == 2
    assert done.stderr == (
        f"mjcf-model info: no geom named 'nosuch' in the model; its geom names: {listed} and "
        "3 more\n"
    )
    sites = run("info", str(model), "--element", "site:s")
    assert sites.stderr.endswith("no site named 's' in the model; it has no named site\n")
