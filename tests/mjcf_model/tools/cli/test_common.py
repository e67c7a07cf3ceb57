"""Tests of ``mjcf_model.tools.cli.common``."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import mujoco
import numpy as np

from tests.support.cli import UNTIDY, run

# -- The command line as people wire it into shells and CI: closed pipes, missing files, advice.
#
# Each test runs ``mjcf-model`` in a fresh process on real files, as a user does.


def test_a_missing_file_is_said_plainly(tmp_path: Path) -> None:
    """A missing model: exit 2, the file and the system's reason, no Python in the message."""
    missing = tmp_path / "nowhere.xml"
    done = subprocess.run(
        [sys.executable, "-m", "mjcf_model", "diff", str(missing), str(missing)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 2
    assert done.stderr == (
        f"mjcf-model diff: cannot read {str(missing)!r}: No such file or directory\n"
    )


#: A tetrahedron, the smallest mesh MuJoCo compiles.
_TETRAHEDRON = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"


def test_command_line_advice_speaks_of_files_not_arguments(tmp_path: Path) -> None:
    """``diff --compiled`` of a copy without its mesh says what to do with the files.

    The library's own advice (``assets=``) names a Python argument; on the command
    line that is no help.
    """
    original = tmp_path / "robot"
    original.mkdir()
    (original / "part.obj").write_text(_TETRAHEDRON)
    text = (
        '<mujoco><asset><mesh file="part.obj"/></asset>'
        '<worldbody><geom type="mesh" mesh="part"/></worldbody></mujoco>'
    )
    (original / "robot.xml").write_text(text)
    copy = tmp_path / "copy"
    copy.mkdir()
    shutil.copy(original / "robot.xml", copy / "robot.xml")
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "mjcf_model",
            "diff",
            "--compiled",
            str(original / "robot.xml"),
            str(copy / "robot.xml"),
        ],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 2
    assert "assets=" not in done.stderr and "inline_includes" not in done.stderr
    assert str(copy / "part.obj") in done.stderr
    assert "put the file where the model names it" in done.stderr


# -- The verbs of ``mjcf-model`` run as a user runs them: a process, real files, exit codes. ---


def test_bad_file_names_file_and_line(tmp_path: Path) -> None:
    """A malformed file fails every reading verb with the file and line, exit status 2."""
    bad = tmp_path / "bad.xml"
    bad.write_text("<mujoco>\n<worldbody>\n<geom size='1'>\n</worldbody></mujoco>")
    for arguments in (["fmt", str(bad)], ["info", str(bad)], ["diff", str(bad), str(bad)]):
        done = run(*arguments)
        assert done.returncode == 2, arguments
        assert f"{bad}:4" in done.stderr, done.stderr


def test_an_output_into_a_missing_folder(tmp_path: Path) -> None:
    """A verb's output path creates its missing folders; a file in the way exits 2, named."""
    arm = tmp_path / "arm.xml"
    arm.write_text(UNTIDY)
    scaled = tmp_path / "out" / "nested" / "big.xml"
    done = run("scale", str(arm), "--factor", "2", "-o", str(scaled))
    assert done.returncode == 0, done.stderr
    original = mujoco.MjModel.from_xml_path(str(arm))
    assert np.allclose(mujoco.MjModel.from_xml_path(str(scaled)).geom_size, 2 * original.geom_size)
    blocked = run("scale", str(arm), "--factor", "2", "-o", str(arm / "big.xml"))
    assert blocked.returncode == 2
    assert f"{str(arm)!r} is a file, not a folder" in blocked.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["arm.xml", "out"]


def test_outputs_resolve_from_where_they_are_written(tmp_path: Path) -> None:
    """Outputs resolve from where they are written, and compose writes all or nothing.

    A model printed to stdout names its meshes from the working folder; new files get
    the umask's mode; compose checks the export folder before writing anything.
    """
    demo = tmp_path / "demo"
    assert run("examples", str(demo)).returncode == 0
    printed = subprocess.run(
        [
            sys.executable,
            "-m",
            "mjcf_model",
            "prefix",
            str(demo / "workcell" / "workcell.xml"),
            "p_",
        ],
        capture_output=True,
        text=True,
        check=False,
        cwd=tmp_path,
    )
    assert printed.returncode == 0, printed.stderr
    (tmp_path / "printed.xml").write_text(printed.stdout)
    assert mujoco.MjModel.from_xml_path(str(tmp_path / "printed.xml")).mesh("p_wedge").id == 0
    scene = tmp_path / "scene.xml"
    (tmp_path / "full").mkdir()
    (tmp_path / "full" / "x").write_text("")
    refused = run(
        "compose",
        str(scene),
        str(demo / "workcell" / "workcell.xml"),
        str(demo / "arm.xml"),
        "--export",
        str(tmp_path / "full"),
    )
    assert refused.returncode == 2 and not scene.exists()
    assert (
        run(
            "compose",
            str(scene),
            str(demo / "workcell" / "workcell.xml"),
            f"{demo / 'arm.xml'}:left/@left_mount",
        ).returncode
        == 0
    )
    assert mujoco.MjModel.from_xml_path(str(scene)).joint("left/elbow").id >= 0
    mask = os.umask(0)
    os.umask(mask)
    assert scene.stat().st_mode & 0o777 == 0o666 & ~mask
