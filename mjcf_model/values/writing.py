"""Field values into MJCF text: the one place numbers are formatted."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from mjcf_model.caching import IdentityCache
from mjcf_model.values.kinds import _CHUNK, _ONLY_FLOATS, _ONLY_INTS, Floats, Ints, Unparsed, Value

__all__ = [
    "format_float",
    "format_value",
    "plain_value",
    "remember_text",
]

#: A number list this long is looked up among the remembered texts before it is formatted.
LONG_LIST = 256
#: The texts of long number lists formatted once and kept with them (see
#: :func:`remember_text`); bounded, each text held with its very list.
_REMEMBERED: IdentityCache[str] = IdentityCache(1024)


def remember_text(value: Floats | Ints) -> str:
    """Format a long number list once and keep its text with it: writing it again copies.

    For lists a program holds and writes many times, unchanged: a skin file's tens of
    thousands of numbers, written inline into every model that renames its bones. Only
    this very list (not an equal one) is written from the remembered text.

    Examples:
        >>> numbers = tuple(float(i) for i in range(300))
        >>> remember_text(numbers) is format_value(numbers)
        True

    """
    return _REMEMBERED.recall_for(value, lambda: _formatted_list(value))


def _unpadded_exponents(text: str) -> str:
    """``text`` (numbers ``repr`` wrote) with each exponent's plus sign and zero padding gone.

    Examples:
        >>> _unpadded_exponents("1e-05 2 3.5e+20")
        '1e-5 2 3.5e20'

    """
    pieces = text.split("e")
    for index in range(1, len(pieces)):
        exponent, space, rest = pieces[index].partition(" ")
        sign = "-" if exponent.startswith("-") else ""
        pieces[index] = sign + (exponent.lstrip("+-").lstrip("0") or "0") + space + rest
    return "e".join(pieces)


def format_float(value: float) -> str:
    """Write a float as the shortest text that reads back to the same double.

    The fewest digits that read back exactly (Python's ``repr``), with integral
    values without ``.0`` (``1.0`` becomes ``"1"``) and exponents without padding
    or plus sign (``1e-07`` becomes ``"1e-7"``); ``-0.0`` keeps its sign.

    Examples:
        >>> format_float(0.1), format_float(2.0), format_float(-0.0), format_float(8.2904e-07)
        ('0.1', '2', '-0', '8.2904e-7')
        >>> format_float(1e16), format_float(2.5e-300)
        ('1e16', '2.5e-300')

    """
    if value.is_integer() and abs(value) < 1e16:
        if value == 0.0 and math.copysign(1.0, value) < 0:
            return "-0"
        return str(int(value))
    text = repr(value)
    return _unpadded_exponents(text) if "e" in text else text


def format_value(value: Value) -> str:
    """Write a field value as MJCF attribute text.

    Examples:
        >>> format_value((1.0, 0.5)), format_value(3), format_value(False), format_value("a")
        ('1 0.5', '3', 'false', 'a')

    """
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return format_float(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, Unparsed):
        return value.text
    if len(value) >= LONG_LIST:
        known = _REMEMBERED.get((id(value),))
        if known is not None and known[0] is value:
            return known[1]
    return _formatted_list(value)


def _formatted_list(value: Floats | Ints) -> str:
    if len(value) > _CHUNK // 8:  # a piece at a time: no list of millions of strings
        step = _CHUNK // 8
        return " ".join(_format_items(value[i : i + step]) for i in range(0, len(value), step))
    return _format_items(value)


def _format_items(values: Floats | Ints) -> str:
    kinds = set(map(type, values))
    if kinds == _ONLY_FLOATS:
        # What format_float does, in C: repr is the shortest text, and an integral
        # float below 1e16 is the only one whose repr ends in ".0", which goes.
        text = (" ".join(map(repr, values)) + " ").replace(".0 ", " ")[:-1]
        return _unpadded_exponents(text) if "e" in text else text
    if kinds == _ONLY_INTS:
        return " ".join(map(str, values))
    return " ".join(format_float(v) if isinstance(v, float) else str(v) for v in values)


def plain_value(value: Any) -> Any:
    """Numpy arrays and scalars as plain Python values, lists as tuples.

    Examples:
        >>> import numpy as np
        >>> plain_value(np.array([1.5, 2.0])), plain_value(np.int64(3))
        ((1.5, 2.0), 3)

    """
    if isinstance(value, np.ndarray):
        return plain_value(value.tolist())
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, (list, tuple)):
        return tuple(plain_value(v) for v in value)
    return value
