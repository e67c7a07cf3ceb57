"""Tests of ``mjcf_model.tools.cli.diff``."""

from __future__ import annotations

import json
from pathlib import Path

from tests.support.cli import UNTIDY, run

# -- The verbs of ``mjcf-model`` run as a user runs them: a process, real files, exit codes. ---


def test_diff_exit_codes_and_json(tmp_path: Path) -> None:
    """0 when only formatting differs, 1 with the change listed, 2 for a missing file."""
    first, second, third = tmp_path / "a.xml", tmp_path / "b.xml", tmp_path / "c.xml"
    first.write_text(UNTIDY)
    second.write_text(run("fmt", "-", stdin=UNTIDY).stdout)
    third.write_text(UNTIDY.replace('pos="0 0 .3"', 'pos="0 0 .4"'))
    assert run("diff", str(first), str(second)).returncode == 0
    different = run("diff", str(first), str(third))
    assert different.returncode == 1
    assert different.stdout == (
        "~ /mujoco/worldbody/body[@name='arm']/site[@name='tip'] pos: 0 0 0.3 -> 0 0 0.4\n"
    )
    report = json.loads(run("diff", "--json", "--compiled", str(first), str(third)).stdout)
    assert report["equal"] is False
    assert report["changes"][0]["attribute"] == "pos"
    assert "site_pos" in report["compiled"]
    assert run("diff", str(first), str(tmp_path / "missing.xml")).returncode == 2
