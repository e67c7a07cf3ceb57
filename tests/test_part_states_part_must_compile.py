"""Composing keyframes with a part MuJoCo rejects: the error says why the part must compile alone.

Keys are composed from each part compiled on its own, so a part that does not
compile raises :class:`MjcfCompileError` with MuJoCo's own message, located in
the part's file, line and element, and told that the part must compile on its own.
"""

from __future__ import annotations

import re

import mujoco
import pytest

from mjcf_model import MjcfCompileError, attach
from serializers import load, loads
from tests.conftest import FIXTURES

#: A free body with no geom (no mass), which MuJoCo rejects, and a key.
MASSLESS = FIXTURES / "part_states" / "massless.xml"


def test_a_part_that_does_not_compile_alone_is_refused_with_its_location() -> None:
    """MuJoCo's message, the part's file, line and element, and that it must compile alone."""
    path = MASSLESS  # MuJoCo reads the same file the part is loaded from
    with pytest.raises(ValueError) as rejected:
        mujoco.MjModel.from_xml_path(str(path))
    first, located = str(rejected.value).splitlines()[:2]
    mujocos = first.removeprefix("Error: ")
    line = re.search(r"line (\d+)", located)
    assert line is not None
    with pytest.raises(MjcfCompileError, match="the part must compile on its own") as caught:
        attach(loads("<mujoco/>"), load(path), prefix="c_")
    error = caught.value
    assert mujocos in error.detail
    assert "composing keyframes reads each part's initial state and keys" in error.detail
    assert error.file == str(path)
    assert error.line == int(line.group(1))
    assert error.path == "/mujoco/worldbody/body[@name='float']"
    assert str(error).startswith(f"{path}:{error.line}: {error.path}: ")
