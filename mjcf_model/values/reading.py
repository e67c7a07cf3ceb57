"""MJCF text (or Python values) into field values: the attrs converters of every node field."""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Collection, Iterable, Iterator
from typing import Any

import numpy as np

from mjcf_model.errors import MjcfValueError
from mjcf_model.values.kinds import (
    _CHUNK,
    _ONLY_FLOATS,
    _ONLY_INTS,
    _SPACES,
    NAN,
    Floats,
    Ints,
    Unparsed,
    Value,
    _shortened,
    check_text,
)

__all__ = [
    "OneOf",
    "float_from_text",
    "floats_from_text",
    "numbers_of",
    "one_of",
    "text_reader",
    "to_bool",
    "to_float",
    "to_floats",
    "to_int",
    "to_ints",
    "to_str",
    "to_vec1to2",
    "to_vec1to3",
    "to_vec1to5",
    "to_vec2",
    "to_vec3",
    "to_vec4",
    "to_vec6",
]


def _one_nan(items: Floats) -> Floats:
    """``items`` with every NaN replaced by :data:`NAN`."""
    if not any(map(math.isnan, items)):
        return items
    return tuple(NAN if math.isnan(v) else v for v in items)


def _parse_float(token: Any, original: object) -> float:
    if isinstance(token, bool):
        raise MjcfValueError(f"expected a number, found {original!r}")
    try:
        number = float(token)
    except (TypeError, ValueError):
        raise MjcfValueError(f"expected a number, found {_shortened(token)!r}") from None
    return NAN if number != number else number


def _parse_int(token: Any, original: object) -> int:
    if isinstance(token, bool):
        raise MjcfValueError(f"expected an integer, found {original!r}")
    if isinstance(token, int):
        return token
    if isinstance(token, float):
        if token.is_integer():
            return int(token)
        raise MjcfValueError(f"expected an integer, found {token!r}")
    if hasattr(token, "__index__"):  # numpy integers
        return int(token)
    try:
        return int(token)
    except (TypeError, ValueError):
        raise MjcfValueError(f"expected an integer, found {_shortened(token)!r}") from None


def _tokens(value: object) -> list[Any]:
    if isinstance(value, str):
        return value.split()
    if isinstance(value, Iterable):
        return list(value)
    if hasattr(value, "tolist"):  # numpy scalar
        return [value.tolist()]
    return [value]


def _count_phrase(lo: int, hi: int | None) -> str:
    if hi == lo:
        return f"{lo} number" + ("" if lo == 1 else "s")
    if hi is None:
        return f"at least {lo} numbers"
    return f"{lo} to {hi} numbers"


def _floats(value: object, lo: int, hi: int | None) -> Floats:
    items: Floats
    if type(value) is str:
        return floats_from_text(lo, hi, value)
    if type(value) is tuple and value and set(map(type, value)) <= _ONLY_FLOATS:
        items = _one_nan(value)  # already floats (a transform's output): checked in C
    elif type(value) is Unparsed:
        return value  # type: ignore[return-value]
    else:
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            value = (value,)
        items = tuple(_parse_float(t, value) for t in _tokens(value))
    return _counted(items, lo, hi, items)


def floats_from_text(lo: int, hi: int | None, text: str) -> Floats:
    """Read ``lo`` to ``hi`` floats (``hi`` ``None``: any number) from attribute text.

    The text path of every float converter; readers call it directly.

    Examples:
        >>> floats_from_text(1, 3, "0.1 2"), floats_from_text(1, 1, "nan")
        ((0.1, 2.0), (nan,))

    """
    # ``float`` reads one token in time linear in its length; no regular
    # expression ever sees attribute text (see tests/mjcf_model/values/test_reading.py).
    try:
        if len(text) > _CHUNK:
            items = tuple(f for chunk in _chunks(text) for f in map(float, chunk.split()))
        else:
            items = tuple(map(float, text.split()))
    except ValueError:
        bad = next(t for t in text.split() if not _reads_as_float(t))
        raise MjcfValueError(f"expected a number, found {_shortened(bad)!r}") from None
    if "n" in text or "N" in text:  # every spelling of NaN has an n; most text none
        items = _one_nan(items)
    return _counted(items, lo, hi, text)


def _counted(items: Floats, lo: int, hi: int | None, found: object) -> Floats:
    """``items``, or the error saying how many numbers were expected."""
    n = len(items)
    if n < lo or (hi is not None and n > hi):
        raise MjcfValueError(
            f"expected {_count_phrase(lo, hi)}, found {n} in {_shortened(found)!r}"
        )
    return items


def _chunks(text: str) -> Iterator[str]:
    """``text`` in pieces of about ``_CHUNK`` characters, cut at white space."""
    start = 0
    while start < len(text):
        cuts = [i for i in (text.find(c, start + _CHUNK) for c in _SPACES) if i >= 0]
        end = min(cuts) if cuts else len(text)
        yield text[start:end]
        start = end


def _reads_as_float(token: str) -> bool:
    try:
        float(token)
    except ValueError:
        return False
    return True


def to_str(value: str | Unparsed | None) -> str | None:
    """Accept a string (names, references, keywords, file names) that XML can carry.

    Examples:
        >>> to_str("torso")
        'torso'

    """
    if value is None:
        return value
    if isinstance(value, str):
        return check_text(value)
    if type(value) is Unparsed:
        return value  # type: ignore[return-value]
    raise MjcfValueError(f"expected text, found {_shortened(value)!r}")


def to_float(value: str | float | Unparsed | None) -> float | None:
    """Convert text or a number to one float.

    Examples:
        >>> to_float("1e-3")
        0.001

    """
    if value is None:
        return value
    if type(value) is float:
        return NAN if value != value else value
    if isinstance(value, str):
        return float_from_text(value)
    if type(value) is Unparsed:
        return value  # type: ignore[return-value]
    return _parse_float(value, value)


def float_from_text(text: str) -> float:
    """Read one float from attribute text (the text path of :func:`to_float`).

    Examples:
        >>> float_from_text(" 1e-3 ")
        0.001

    """
    (item,) = floats_from_text(1, 1, text)
    return item


def to_int(value: str | int | Unparsed | None) -> int | None:
    """Convert text or an integral number to an int.

    Examples:
        >>> to_int("3")
        3

    """
    if value is None or type(value) is int:
        return value
    if isinstance(value, str):
        tokens = value.split()
        if len(tokens) != 1:
            raise MjcfValueError(f"expected one integer, found {_shortened(value)!r}")
        return _parse_int(tokens[0], value)
    if type(value) is Unparsed:
        return value  # type: ignore[return-value]
    return _parse_int(value, value)


def to_bool(value: str | bool | Unparsed | None) -> bool | None:
    """Convert MJCF ``"true"``/``"false"`` (or a bool) to a bool.

    Examples:
        >>> to_bool("false")
        False

    """
    if value is None or isinstance(value, bool):
        return value
    if type(value) is Unparsed:
        return value  # type: ignore[return-value]
    if value == "true":
        return True
    if value == "false":
        return False
    if isinstance(value, np.bool_):
        return bool(value)
    raise MjcfValueError(f"expected 'true' or 'false', found {value!r}")


def to_floats(value: object) -> Floats | None:
    """Convert text, a sequence or an array to any number of floats.

    Examples:
        >>> to_floats([1, 2.5])
        (1.0, 2.5)

    """
    return None if value is None else _floats(value, 0, None)


def to_ints(value: object) -> Ints | None:
    """Convert text, a sequence or an array to any number of ints.

    Examples:
        >>> to_ints("0 1 2")
        (0, 1, 2)

    """
    if value is None or type(value) is Unparsed:
        return value  # type: ignore[return-value]
    if type(value) is tuple and set(map(type, value)) <= _ONLY_INTS:
        return value  # already ints: checked in C
    return tuple(_parse_int(t, _shortened(value)) for t in _tokens(value))


def to_vec2(value: object) -> Floats | None:
    """Exactly two floats (ranges, ``solref``)."""
    return None if value is None else _floats(value, 2, 2)


def to_vec3(value: object) -> Floats | None:
    """Exactly three floats (positions, axes, Euler angles)."""
    return None if value is None else _floats(value, 3, 3)


def to_vec4(value: object) -> Floats | None:
    """Exactly four floats (quaternions, ``rgba``, ``axisangle``)."""
    return None if value is None else _floats(value, 4, 4)


def to_vec6(value: object) -> Floats | None:
    """Exactly six floats (``fromto``, ``xyaxes``, ``fullinertia``)."""
    return None if value is None else _floats(value, 6, 6)


def to_vec1to2(value: object) -> Floats | None:
    """One or two floats (``solref``: MuJoCo fills a missing second value from defaults)."""
    return None if value is None else _floats(value, 1, 2)


def to_vec1to3(value: object) -> Floats | None:
    """One to three floats (geom and site ``size``, ``friction``)."""
    return None if value is None else _floats(value, 1, 3)


def to_vec1to5(value: object) -> Floats | None:
    """One to five floats (``solimp``: MuJoCo fills missing values from defaults)."""
    return None if value is None else _floats(value, 1, 5)


#: The text path of each float converter, for readers that only ever pass text.
_TEXT_READERS: dict[Callable[[Any], Any], Callable[[str], Any]] = {
    to_float: float_from_text,
    to_floats: functools.partial(floats_from_text, 0, None),
    to_vec2: functools.partial(floats_from_text, 2, 2),
    to_vec3: functools.partial(floats_from_text, 3, 3),
    to_vec4: functools.partial(floats_from_text, 4, 4),
    to_vec6: functools.partial(floats_from_text, 6, 6),
    to_vec1to2: functools.partial(floats_from_text, 1, 2),
    to_vec1to3: functools.partial(floats_from_text, 1, 3),
    to_vec1to5: functools.partial(floats_from_text, 1, 5),
}


def text_reader(converter: Callable[[Any], Any]) -> Callable[[str], Any]:
    """What ``converter`` does to attribute text, without its checks for other types.

    Examples:
        >>> text_reader(to_vec3)("0 0 1"), text_reader(to_int)("2")
        ((0.0, 0.0, 1.0), 2)

    """
    return _TEXT_READERS.get(converter, converter)


class OneOf:
    """An attrs validator that accepts ``None`` or one of a set of MJCF keywords.

    Examples:
        >>> check = OneOf({"box", "sphere"})
        >>> check(None, None, "cube")
        Traceback (most recent call last):
            ...
        mjcf_model.errors.MjcfValueError: expected one of 'box', 'sphere', found 'cube'

    """

    __slots__ = ("_listing", "allowed")

    def __init__(self, choices: Collection[str]) -> None:
        #: The keywords accepted.
        self.allowed = frozenset(choices)
        self._listing = ", ".join(repr(c) for c in sorted(self.allowed))

    def __call__(self, _instance: Any, _attribute: Any, value: str | None) -> None:
        """Raise :class:`MjcfValueError` unless ``value`` is ``None`` or allowed."""
        if value is not None and value not in self.allowed and not isinstance(value, Unparsed):
            raise MjcfValueError(f"expected one of {self._listing}, found {value!r}")

    def __repr__(self) -> str:
        return f"OneOf({sorted(self.allowed)!r})"


def one_of(choices: Collection[str]) -> OneOf:
    """Make a validator for a keyword field (see :class:`OneOf`).

    Examples:
        >>> one_of({"hinge"}).allowed
        frozenset({'hinge'})

    """
    return OneOf(choices)


def numbers_of(value: Value | None) -> tuple[float, ...] | None:
    """The numbers in an attribute value, typed or text; ``None`` when it has none.

    Examples:
        >>> numbers_of("1 2.5"), numbers_of(3), numbers_of("x")
        ((1.0, 2.5), (3.0,), None)

    """
    if value is None:
        return None
    if type(value) is tuple:
        return tuple(map(float, value))
    if type(value) is float:
        return (value,)
    if isinstance(value, str):
        try:
            return tuple(float(part) for part in value.split())
        except ValueError:
            return None
    if isinstance(value, (int, float)):
        return (float(value),)
    return tuple(float(v) for v in value)
