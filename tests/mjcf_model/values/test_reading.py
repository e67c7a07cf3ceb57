"""Tests of ``mjcf_model.values.reading``."""

from __future__ import annotations

import ast
import time
from pathlib import Path

import numpy as np
import pytest

import mjcf_model
from mjcf_model import (
    Geom,
    MjcfValueError,
)
from mjcf_model.serializers import loads

# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


#: The packages as imported: the installed wheel under tests/run_installed.py.
PACKAGES = [Path(mjcf_model.__file__).parent, Path(mjcf_model.serializers.__file__).parent]


# -- numbers ---------------------------------------------------------------------------


def _patterns() -> list[tuple[Path, str]]:
    found = []
    for package in PACKAGES:
        for path in package.rglob("*.py"):
            for node in ast.walk(ast.parse(path.read_text())):
                if (
                    isinstance(node, ast.Call)
                    and isinstance(node.func, ast.Attribute)
                    and isinstance(node.func.value, ast.Name)
                    and node.func.value.id == "re"
                ):
                    first = node.args[0] if node.args else None
                    assert isinstance(first, ast.Constant), f"{path}: a pattern built at run time"
                    pattern = first.value
                    found.append((path, pattern if isinstance(pattern, str) else pattern.decode()))
    return found


def test_every_regular_expression_is_one_character_class() -> None:
    """No pattern can backtrack: each is a single character class, matched in linear time.

    This is how the library keeps regular expressions off untrusted text: a
    pattern with quantifiers or alternation fails here, and must be replaced by
    plain string code (as number parsing was: ``float`` on split tokens).
    """
    patterns = _patterns()
    assert patterns, "the scan found no pattern at all: it is broken"
    for path, pattern in patterns:
        assert pattern.startswith("[") and pattern.endswith("]"), (path, pattern)
        inner = pattern[1:-1].replace("\\]", "")
        assert "]" not in inner and "[" not in inner.replace("\\[", ""), (path, pattern)


@pytest.mark.parametrize("digits", [20, 30, 5000])
def test_number_parsing_is_linear(digits: int) -> None:
    """``size="111...1x"`` took 44 s at 20 digits, multiplying by 7 for each two more."""
    text = f'<mujoco><worldbody><geom size="{"1" * digits}x"/></worldbody></mujoco>'
    start = time.perf_counter()
    geom = loads(text).worldbody.geoms[0]
    with pytest.raises(MjcfValueError, match="expected a number"):
        Geom(size=geom.size.text)
    assert time.perf_counter() - start < 1.0


@pytest.mark.parametrize("spelling", ["1..2", "0.20.4", "-0.-0.015", "--1", "1,2", "1e", "x"])
def test_malformed_numbers_raise_mjcf_errors(spelling: str) -> None:
    """``float``'s ValueError never escapes: building a node raises MjcfValueError."""
    with pytest.raises(MjcfValueError, match="expected a number"):
        Geom(size=spelling)
    with pytest.raises(MjcfValueError):
        Geom(group=spelling)


# -- Node behaviour: immutability, typed views, attribute order, generic elements, values. -----


def test_vectors_accept_lists_arrays_and_text() -> None:
    """Sequences, numpy arrays and MJCF text all become tuples of floats."""
    expected = (0.0, 1.5, -2.0)
    assert Geom(pos=[0, 1.5, -2]).pos == expected
    assert Geom(pos=np.array([0, 1.5, -2])).pos == expected
    assert Geom(pos=np.array([0, 1.5, -2], dtype=np.float32)).pos == expected
    assert Geom(pos="0 1.5 -2").pos == expected
    assert all(type(v) is float for v in Geom(pos=np.arange(3)).pos or ())
