"""Tests of ``mjcf_model.tools.cli.examples``."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import mujoco
import numpy as np

from tests.support.cli import run

# -- The verbs of ``mjcf-model`` run as a user runs them: a process, real files, exit codes. ---


def test_readme_main_job(tmp_path: Path) -> None:
    """The README's main job: two bundled arms on the workcell, each where it belongs.

    The arm (radians) is attached twice to the workcell (degrees, its own mesh
    folder) at its two mount sites, and the scene compiles.
    """
    demo = tmp_path / "demo"
    assert run("examples", str(demo)).returncode == 0
    scene = demo / "scene.xml"
    parts = [f"{demo / 'arm.xml'}:left_@left_mount", f"{demo / 'arm.xml'}:right_@right_mount"]
    done = run("compose", str(scene), str(demo / "workcell" / "workcell.xml"), *parts)
    assert done.returncode == 0, done.stderr
    compiled = mujoco.MjModel.from_xml_path(str(scene))
    data = mujoco.MjData(compiled)
    mujoco.mj_kinematics(compiled, data)
    assert np.allclose(data.site("left_tip").xpos, [-0.2, 0, 1])
    assert np.allclose(data.site("right_tip").xpos, [0.2, 0, 1])
    assert np.allclose(compiled.joint("right_elbow").range, [-2, 2])  # radians, as the arm says
    assert compiled.mesh("wedge").id == 0
    summary = run("info", str(scene))
    assert "  site (4): left_mount, right_mount, left_tip, right_tip\n" in summary.stdout
    assert run("examples", str(demo)).returncode == 2  # not empty: nothing overwritten


def test_readme_main_job_command_runs_as_written(tmp_path: Path) -> None:
    """The README's main-job command (from the installed package's description) runs here."""
    from importlib import metadata

    readme = metadata.metadata("mjcf-model").get_payload()
    assert isinstance(readme, str)
    setup = "python3 -m venv .venv && .venv/bin/pip install -e . && "
    [line] = [line for line in readme.splitlines() if line.startswith(setup)]
    command = line.removeprefix(setup).replace(
        ".venv/bin/mjcf-model", f"{sys.executable} -m mjcf_model"
    )
    env = {k: v for k, v in os.environ.items() if k != "MUJOCO_GL"}
    done = subprocess.run(
        ["bash", "-c", command], cwd=tmp_path, capture_output=True, text=True, check=False, env=env
    )
    assert done.returncode == 0, done.stderr
    written, info = done.stdout.split("\n", 1)
    assert written.startswith("wrote demo/scene.xml: 2 parts attached to demo/workcell/")
    assert info.startswith("model: workcell\n")
    assert (tmp_path / "demo" / "scene.png").read_bytes().startswith(b"\x89PNG")
