"""Tests of ``mjcf_model.values.writing``."""

from __future__ import annotations

import math

import pytest

from mjcf_model.values import format_float, format_value, to_vec3

# -- Node behaviour: immutability, typed views, attribute order, generic elements, values. -----


@pytest.mark.parametrize(
    "value",
    [0.1, 1 / 3, 1e-300, 5e-324, 1.7976931348623157e308, -0.0, 2.0, 1e16, 123456789.125, math.pi],
)
def test_floats_are_written_shortest_and_exact(value: float) -> None:
    """Every float is written as text that reads back to the same double."""
    text = format_float(value)
    assert float(text) == value
    assert math.copysign(1, float(text)) == math.copysign(1, value)
    assert len(text) <= len(repr(value))


def test_value_formatting() -> None:
    """Booleans, ints, tuples and text are written as MJCF spells them."""
    assert format_value(True) == "true" and format_value(False) == "false"
    assert format_value((1.0, -0.5, 3)) == "1 -0.5 3"
    assert format_value("hinge") == "hinge"
    assert to_vec3(" 1\t2\n3 ") == (1.0, 2.0, 3.0)
