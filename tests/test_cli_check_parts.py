"""``mjcf-model check`` as a CI job runs it: rejected models fail, parts are checked as parts.

Every test runs the command in a fresh process on files written here, and the
expected verdicts are MuJoCo's own (``MjModel.from_xml_path`` of each file).
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import mujoco
import pytest

#: A main model that declares a material and includes an arm that uses it.
_SCENE = """<mujoco model="scene">
  <asset>
    <material name="red" rgba="1 0 0 1"/>
  </asset>
  <include file="parts/arm.xml"/>
</mujoco>
"""
#: The arm: MuJoCo rejects it alone (the material is the scene's).
_ARM = """<mujoco>
  <worldbody>
    <body name="arm">
      <geom material="red" name="upper" size="0.05"/>
    </body>
  </worldbody>
</mujoco>
"""


def _check(*arguments: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "mjcf_model", "check", *arguments],
        capture_output=True,
        text=True,
        check=False,
    )


def _scene(folder: Path, scene: str = _SCENE) -> tuple[Path, Path]:
    (folder / "parts").mkdir()
    arm = folder / "parts" / "arm.xml"
    arm.write_text(_ARM)
    main = folder / "scene.xml"
    main.write_text(scene)
    return main, arm


def _rejects(path: Path) -> bool:
    try:
        mujoco.MjModel.from_xml_path(str(path))
    except ValueError:
        return True
    return False


def test_a_model_mujoco_rejects_fails_naming_file_line_and_element(tmp_path: Path) -> None:
    """Exit 1 by default (a CI job wired to ``check`` catches a broken model)."""
    broken = tmp_path / "broken.xml"
    broken.write_text(
        "<mujoco>\n  <worldbody>\n    <geom name='g' type='box'/>\n  </worldbody>\n</mujoco>\n"
    )
    assert _rejects(broken)
    done = _check(str(broken))
    assert done.returncode == 1
    assert f"not compiled  {broken}" in done.stdout
    assert f"{broken}:3: /mujoco/worldbody/geom[@name='g']" in done.stdout
    assert _check("--strict", str(broken)).returncode == 1  # old CI jobs keep working
    assert _check("--quiet", str(broken)).returncode == 1


def test_an_included_part_is_recognised_and_checked_with_its_scene(tmp_path: Path) -> None:
    """The arm alone is rejected by MuJoCo, but the scene including it compiles: a part."""
    main, arm = _scene(tmp_path)
    assert _rejects(arm) and not _rejects(main)
    done = _check(str(arm), str(main))
    assert done.returncode == 0, done.stdout
    assert (
        f"part          {arm}\n              a part for <include>, included by {main}"
        in done.stdout
    )
    assert "2 files: 1 identical, 1 part" in done.stdout


def test_a_part_whose_scene_is_rejected_fails(tmp_path: Path) -> None:
    """A part is only as good as the files including it: a broken scene fails the part."""
    main, arm = _scene(tmp_path, _SCENE.replace('name="red"', 'name="blue"'))
    assert _rejects(arm) and _rejects(main)
    done = _check(str(arm))
    assert done.returncode == 1
    assert f"not compiled  {arm}" in done.stdout and f"included by {main}" in done.stdout


def test_part_option_checks_a_part_without_its_scene(tmp_path: Path) -> None:
    """``--part``: a part with no scene in reach reads back the same, and says so."""
    (tmp_path / "alone").mkdir()
    arm = tmp_path / "alone" / "arm.xml"
    arm.write_text(_ARM)
    assert _check(str(arm)).returncode == 1  # not recognised: MuJoCo's verdict stands
    done = _check("--part", str(arm))
    assert done.returncode == 0, done.stdout
    assert "no file including it was found" in done.stdout


@pytest.mark.parametrize("bad", ["<mujoco><worldbody><geom pos='0 0'/></worldbody></mujoco>"])
def test_a_part_that_does_not_read_back_fails(tmp_path: Path, bad: str) -> None:
    """A part mjcf-model cannot read as MJCF fails, as any file does."""
    part = tmp_path / "part.xml"
    part.write_text(bad.replace("<mujoco>", "<mujoco").replace("</mujoco>", ""))
    assert _check("--part", str(part)).returncode == 1


def test_stdin_that_is_not_utf8_names_the_byte_line_and_column() -> None:
    """``check -`` on a Latin-1 comment: an error with the reader's location and advice."""
    done = subprocess.run(
        [sys.executable, "-m", "mjcf_model", "check", "-"],
        input=b"<mujoco>\n  <!-- caf\xe9 -->\n</mujoco>\n",
        capture_output=True,
        check=False,
    )
    assert done.returncode == 1
    out = done.stdout.decode()
    assert "ERROR         <stdin>" in out
    assert "<stdin>:2:" in out and "(column 11)" in out and "byte 0xE9 is not UTF-8" in out
    assert "iconv -f latin1 -t utf-8" in out
