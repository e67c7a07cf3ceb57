"""``mjcf-model lint`` as a user runs it: a process, real files, exit codes, settings."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from mjcf_model.errors import MjcfValueError
from mjcf_model.tools.cli.lint import lint_settings

REVERSED = (
    '<mujoco>\n<worldbody>\n<body>\n<joint name="j" range="1 -1"/>\n<geom size="1"/>\n'
    "</body>\n</worldbody>\n</mujoco>\n"
)
UNUSED = (
    '<mujoco><asset><material name="old"/></asset><worldbody><geom size="1"/></worldbody></mujoco>'
)


def _run(*arguments: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "mjcf_model", "lint", *arguments],
        capture_output=True,
        text=True,
        check=False,
        cwd=cwd,
    )


def test_findings_print_with_file_line_and_path_and_exit_1(tmp_path: Path) -> None:
    """Text output: one line a finding and a count; a clean file exits 0."""
    (tmp_path / "bad.xml").write_text(REVERSED)
    (tmp_path / "good.xml").write_text(REVERSED.replace("1 -1", "-1 1"))
    done = _run("bad.xml", "good.xml", cwd=tmp_path)
    assert done.returncode == 1, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith("bad.xml:4: /mujoco/worldbody/body/joint[@name='j']: R201 ")
    assert lines[-1] == "1 finding (1 error) in 2 files"
    assert _run("good.xml", cwd=tmp_path).returncode == 0


def test_json_lists_every_finding_as_an_object(tmp_path: Path) -> None:
    """``--format json``: one list of objects with the six fields."""
    (tmp_path / "a.xml").write_text(REVERSED)
    (tmp_path / "b.xml").write_text(UNUSED)
    done = _run("a.xml", "b.xml", "--format", "json", cwd=tmp_path)
    found = json.loads(done.stdout)
    assert done.returncode == 1
    assert [(f["file"], f["rule"], f["severity"]) for f in found] == [
        ("a.xml", "R201", "error"),
        ("b.xml", "A401", "warning"),
    ]
    assert all(set(f) == {"file", "line", "path", "rule", "severity", "message"} for f in found)


def test_select_ignore_and_pyproject_settings_choose_the_rules(tmp_path: Path) -> None:
    """The nearest ``[tool.mjcf-model.lint]`` ignores A; ``--select`` replaces its choice."""
    (tmp_path / "pyproject.toml").write_text('[tool.mjcf-model.lint]\nignore = ["A"]\n')
    (tmp_path / "b.xml").write_text(UNUSED)
    assert _run("b.xml", cwd=tmp_path).returncode == 0
    assert _run("b.xml", "--select", "A401", "--ignore", "R", cwd=tmp_path).returncode == 0
    (tmp_path / "pyproject.toml").write_text('[tool.mjcf-model.lint]\nselect = ["A401"]\n')
    assert _run("b.xml", cwd=tmp_path).returncode == 1
    assert _run("b.xml", "--select", "R", cwd=tmp_path).returncode == 0


def test_an_unreadable_or_rejected_file_exits_2_and_the_others_are_still_linted(
    tmp_path: Path,
) -> None:
    """MuJoCo's rejection is said with the element; the good file's findings still print."""
    (tmp_path / "a.xml").write_text(REVERSED)
    (tmp_path / "broken.xml").write_text(
        REVERSED.replace('range="1 -1"', 'limited="true" range="1 -1"')
    )
    done = _run("broken.xml", "nothere.xml", "a.xml", cwd=tmp_path)
    assert done.returncode == 2
    assert "broken.xml:4: /mujoco/worldbody/body/joint[@name='j']" in done.stderr
    assert "nothere.xml" in done.stderr and "R201" in done.stdout


def test_the_rules_are_listed_and_a_bad_code_is_refused(tmp_path: Path) -> None:
    """``--rules`` lists each code; an unknown code says which codes there are."""
    listed = _run("--rules", cwd=tmp_path)
    assert listed.returncode == 0 and "K104  key-ctrl-servo-mismatch" in listed.stdout
    (tmp_path / "a.xml").write_text(REVERSED)
    refused = _run("a.xml", "--select", "Q1", cwd=tmp_path)
    assert refused.returncode == 2 and "no lint rule is 'Q1'" in refused.stderr


def test_settings_with_another_key_or_type_are_refused_naming_the_file(tmp_path: Path) -> None:
    """Only lists of codes under ``select`` and ``ignore``."""
    (tmp_path / "pyproject.toml").write_text('[tool.mjcf-model.lint]\nselect = "K"\n')
    with pytest.raises(MjcfValueError, match="select = 'K'") as caught:
        lint_settings(tmp_path)
    assert caught.value.file == str(tmp_path / "pyproject.toml")
