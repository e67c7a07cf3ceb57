"""Tests of ``mjcf_model.tools.cli.parts``."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.support.cli import _files, run

# -- ``mjcf-model compose`` places each part: a process, real files, MuJoCo's compiled poses. --
#
# Each expected pose is computed from the part compiled alone (``mj_kinematics`` at
# ``qpos0``), moved by the placement with MuJoCo's own quaternion functions.


@pytest.mark.parametrize(
    ("placement", "said"),
    [
        (["pos=1,2"], "expected 3 numbers, found 2"),
        (["pos=1,x,0"], "expected a number, found 'x'"),
        (["quat=1,0,0"], "quat=W,X,Y,Z"),
        (["pos=inf,0,0"], "finite"),
        (["quat=1,0,0,1", "euler=0,0,90"], "both quat= and euler="),
        (["pos=0,0,1", "pos=0,0,2"], "pos= is given twice"),
    ],
)
def test_compose_bad_placement_writes_nothing(
    tmp_path: Path, placement: list[str], said: str
) -> None:
    """A placement text of the wrong form exits 2, names the part and the form, writes nothing."""
    files = _files(tmp_path)
    scene_path = tmp_path / "scene.xml"
    part = f"{files['free']}:a_"
    done = run("compose", str(scene_path), str(files["base"]), part, *placement)
    assert done.returncode == 2
    assert done.stderr.startswith(f"mjcf-model compose: part {part!r}")
    assert said in done.stderr
    assert not scene_path.exists()


def test_compose_placement_before_any_part(tmp_path: Path) -> None:
    """A placement word before the first part (the base is not placed) exits 2, writes nothing."""
    files = _files(tmp_path)
    scene_path = tmp_path / "scene.xml"
    done = run("compose", str(scene_path), str(files["base"]), "pos=0,0,1", str(files["free"]))
    assert done.returncode == 2
    assert "comes before any part" in done.stderr
    assert not scene_path.exists()
