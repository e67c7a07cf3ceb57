"""Tests of ``mjcf_model.tools.cli``."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from mjcf_model.tools.cli import BROKEN_PIPE_STATUS
from tests.support.cli import run

# -- The command line as people wire it into shells and CI: closed pipes, missing files, advice.
#
# Each test runs ``mjcf-model`` in a fresh process on real files, as a user does.


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


# -- The verbs of ``mjcf-model`` run as a user runs them: a process, real files, exit codes. ---


VERBS = (
    "check",
    "fmt",
    "diff",
    "compose",
    "prefix",
    "scale",
    "export",
    "info",
    "render",
    "examples",
)


@pytest.mark.parametrize("verb", VERBS)
def test_every_verb_has_help(verb: str) -> None:
    """``mjcf-model VERB --help`` describes the verb and exits 0."""
    done = run(verb, "--help")
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith(f"usage: mjcf-model {verb}")
