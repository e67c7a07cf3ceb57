"""The command line as people wire it into shells and CI: closed pipes, missing files, advice.

Each test runs ``mjcf-model`` in a fresh process on real files, as a user does.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from mjcf_model.tools.cli import BROKEN_PIPE_STATUS

#: Geoms enough for a long diff.
_GEOMS = 2_000


def _many_geoms(folder: Path) -> Path:
    path = folder / "many.xml"
    geoms = "".join(f'<geom name="g{i}" size="0.1"/>\n' for i in range(_GEOMS))
    path.write_text(f"<mujoco>\n<worldbody>\n{geoms}</worldbody>\n</mujoco>\n")
    return path


def _reader_gone(arguments: list[str], stdin: Path | None = None) -> tuple[int, str]:
    """Run the command with its output's reader gone before it writes (``| head -0``).

    Closing the pipe first makes every write fail, whatever the size of the
    system's pipe buffers (``| head -1`` after a big buffer can leave none).
    """
    with stdin.open("rb") if stdin is not None else open(os.devnull, "rb") as source:
        reading, writing = os.pipe()
        os.close(reading)
        try:
            done = subprocess.run(
                [sys.executable, "-m", "mjcf_model", *arguments],
                stdin=source,
                stdout=writing,
                stderr=subprocess.PIPE,
                check=False,
            )
        finally:
            os.close(writing)
    return done.returncode, done.stderr.decode()


@pytest.mark.parametrize(
    "verb",
    ["diff", "fmt-stdin", "fmt-diff", "prefix", "info"],
)
def test_a_closed_pipe_ends_the_command_quietly(tmp_path: Path, verb: str) -> None:
    """``mjcf-model ... | head`` prints no traceback and no errno: it ends as ``git log`` does."""
    many = _many_geoms(tmp_path)
    empty = tmp_path / "empty.xml"
    empty.write_text("<mujoco>\n<worldbody/>\n</mujoco>\n")
    arguments, stdin = {
        "diff": (["diff", str(empty), str(many)], None),
        "fmt-stdin": (["fmt", "-"], many),
        "prefix": (["prefix", str(many), "left_"], None),
        "fmt-diff": (["fmt", "--diff", str(many)], None),
        "info": (["info", str(many)], None),
    }[verb]
    status, errors = _reader_gone(arguments, stdin)
    assert errors == ""
    assert status == BROKEN_PIPE_STATUS


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
