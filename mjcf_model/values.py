"""Attribute values: the one place where MJCF text becomes Python values and back.

Node fields hold ``str``, ``int``, ``float``, ``bool`` or tuples of numbers. The
converters below are the attrs converters of those fields: they accept MJCF
text (as the reader hands it over), Python numbers, any sequence and numpy
arrays, and raise :class:`~mjcf_model.errors.MjcfValueError` on a wrong count
or a non-number. :func:`format_value` is their inverse and the only place that
formats numbers: floats are written with the shortest text that reads back to
the same double, so MuJoCo compiles the written model bit for bit the same.

>>> to_vec3("0 0.1 2")
(0.0, 0.1, 2.0)
>>> format_value((0.0, 0.1, 2.0))
'0 0.1 2'
>>> format_value(True)
'true'
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Callable, Collection, Iterable, Iterator
from typing import Any

import numpy as np

from mjcf_model.errors import MjcfValueError

__all__ = [
    "Floats",
    "Ints",
    "OneOf",
    "Unparsed",
    "Value",
    "check_name",
    "check_text",
    "float_from_text",
    "float_key",
    "floats_from_text",
    "format_float",
    "format_value",
    "one_of",
    "plain_value",
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

#: A vector of numbers as a node stores it.
Floats = tuple[float, ...]
#: A vector of integers as a node stores it.
Ints = tuple[int, ...]


#: The one NaN every field holds. ``nan != nan``, but tuples compare items by
#: identity first: with a single NaN object, two nodes holding NaN are equal
#: and hash alike, as their compiled models are identical.
NAN = float("nan")


def float_key(value: float | None) -> tuple[float | None]:
    """What ``==`` and ``hash`` compare of a one-number field: NaN equals NaN.

    ``float`` compares NaN unequal even to itself; a 1-tuple compares its item
    by identity first, and every field holds the same :data:`NAN` object.

    Example:
        >>> NAN == NAN, float_key(NAN) == float_key(NAN)
        (False, True)

    """
    return (value,)


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


_ONLY_FLOATS = frozenset({float})
_ONLY_INTS = frozenset({int})


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

    Example:
        >>> floats_from_text(1, 3, "0.1 2"), floats_from_text(1, 1, "nan")
        ((0.1, 2.0), (nan,))

    """
    # ``float`` reads one token in time linear in its length; no regular
    # expression ever sees attribute text (see tests/test_hostile.py).
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


#: Longer text is split a piece at a time, so a 50 MB attribute never becomes
#: millions of token strings at once.
_CHUNK = 1 << 20
_SPACES = (" ", "\n", "\t", "\r", "\f", "\v")


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


def _shortened(value: object, limit: int = 80) -> object:
    """``value`` for an error message: long text is cut, so a 50 MB attribute is not copied."""
    if isinstance(value, str) and len(value) > limit:
        return f"{value[:limit]}... ({len(value)} characters)"
    if isinstance(value, tuple) and len(value) > limit // 8:
        return (*value[: limit // 8], "...")
    return value


class Unparsed:
    """Attribute text a typed field cannot read, kept verbatim because MuJoCo may read it.

    MuJoCo reads some spellings the typed fields refuse (``size="0x10"`` is 16,
    ``pos=""`` is "use the default"). The readers keep such text as it was and
    the writers write it back unchanged, so the model compiles exactly as the
    file did. Using the value (iterating, indexing, converting it to a number)
    raises the :class:`~mjcf_model.errors.MjcfValueError` that reading it found,
    with the file, line and element path it came from.

    Example:
        >>> from serializers import loads
        >>> model = loads('<mujoco><worldbody><geom size="0x10"/></worldbody></mujoco>')
        >>> geom = model.worldbody.geoms[0]
        >>> geom.size
        Unparsed('0x10')
        >>> geom.size[0]
        Traceback (most recent call last):
        ...
        mjcf_model.errors.MjcfValueError: <string>:1: /mujoco/worldbody/geom: attribute 'size': \
expected a number, found '0x10' (kept verbatim: MuJoCo may read what mjcf-model cannot)

    """

    __slots__ = ("problem", "text")

    def __init__(self, text: str, problem: MjcfValueError | None = None) -> None:
        #: The attribute text exactly as read.
        self.text = check_text(text, "unparsed text")
        #: Why the typed field could not read it, located where it was read.
        self.problem = problem

    def __eq__(self, other: object) -> bool:
        return type(other) is Unparsed and other.text == self.text

    def __hash__(self) -> int:
        return hash((Unparsed, self.text))

    def __repr__(self) -> str:
        return f"Unparsed({_shortened(self.text)!r})"

    def fail(self, *_args: object) -> Any:
        """Raise the error reading this value found."""
        problem = self.problem or MjcfValueError(f"cannot read {_shortened(self.text)!r}")
        raise MjcfValueError(
            f"{problem.detail} (kept verbatim: MuJoCo may read what mjcf-model cannot)",
            file=problem.file,
            line=problem.line,
            path=problem.path,
        )

    __iter__ = __len__ = __getitem__ = __float__ = __int__ = __index__ = fail
    __add__ = __radd__ = __sub__ = __rsub__ = __mul__ = __rmul__ = __truediv__ = fail
    __neg__ = __lt__ = __le__ = __gt__ = __ge__ = __array__ = fail


#: Anything a node field may hold.
Value = str | int | float | bool | Floats | Ints | Unparsed


#: One character XML 1.0 cannot carry. Every pattern in the library is a single
#: character class, which cannot backtrack (tests/test_values.py checks this).
NOT_XML_CHARACTER = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")
_NOT_NAME_CHARACTER = re.compile(
    "[^-.0-9:A-Z_a-z\xb7\xc0-\xd6\xd8-\xf6\xf8-\u037d\u037f-\u1fff\u200c\u200d"
    "\u203f\u2040\u2070-\u218f\u2c00-\u2fef\u3001-\ud7ff\uf900-\ufdcf\ufdf0-\ufffd"
    "\U00010000-\U000effff]"
)
_NOT_NAME_START = frozenset("-.0123456789\xb7\u203f\u2040") | {chr(c) for c in range(0x300, 0x370)}


def check_text(value: str, what: str = "text") -> str:
    r"""Return ``value``, or raise when it holds a character XML cannot carry.

    Such text (NUL and other control characters, lone surrogates) could be
    built but not written and read back, so no node accepts it.

    Example:
        >>> check_text("arm\x00")
        Traceback (most recent call last):
        ...
        mjcf_model.errors.MjcfValueError: text 'arm\x00' holds U+0000, which XML cannot carry

    """
    bad = NOT_XML_CHARACTER.search(value)
    if bad is not None:
        raise MjcfValueError(
            f"{what} {_shortened(value)!r} holds U+{ord(bad.group()):04X}, which XML cannot carry"
        )
    return value


def check_name(value: str, what: str = "name") -> str:
    """Return ``value``, or raise unless it is an XML name (a tag or an attribute name).

    Example:
        >>> check_name("geom"), check_name("xmlns:mj")
        ('geom', 'xmlns:mj')
        >>> check_name("1st")
        Traceback (most recent call last):
        ...
        mjcf_model.errors.MjcfValueError: name '1st' is not an XML name

    """
    if not value or value[0] in _NOT_NAME_START or _NOT_NAME_CHARACTER.search(value):
        raise MjcfValueError(f"{what} {_shortened(value)!r} is not an XML name")
    return value


def to_str(value: str | Unparsed | None) -> str | None:
    """Accept a string (names, references, keywords, file names) that XML can carry.

    Example:
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

    Example:
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

    Example:
        >>> float_from_text(" 1e-3 ")
        0.001

    """
    (item,) = floats_from_text(1, 1, text)
    return item


def to_int(value: str | int | Unparsed | None) -> int | None:
    """Convert text or an integral number to an int.

    Example:
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

    Example:
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

    Example:
        >>> to_floats([1, 2.5])
        (1.0, 2.5)

    """
    return None if value is None else _floats(value, 0, None)


def to_ints(value: object) -> Ints | None:
    """Convert text, a sequence or an array to any number of ints.

    Example:
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

    Example:
        >>> text_reader(to_vec3)("0 0 1"), text_reader(to_int)("2")
        ((0.0, 0.0, 1.0), 2)

    """
    return _TEXT_READERS.get(converter, converter)


class OneOf:
    """An attrs validator that accepts ``None`` or one of a set of MJCF keywords.

    Example:
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

    Example:
        >>> one_of({"hinge"}).allowed
        frozenset({'hinge'})

    """
    return OneOf(choices)


def format_float(value: float) -> str:
    """Write a float as the shortest text that reads back to the same double.

    Integral values drop the ``.0`` (``1.0`` becomes ``"1"``); ``-0.0`` keeps its sign.

    Example:
        >>> format_float(0.1), format_float(2.0), format_float(-0.0), format_float(1e-08)
        ('0.1', '2', '-0', '1e-08')

    """
    if value.is_integer() and abs(value) < 1e16:
        if value == 0.0 and math.copysign(1.0, value) < 0:
            return "-0"
        return str(int(value))
    return repr(value)


def format_value(value: Value) -> str:
    """Write a field value as MJCF attribute text.

    Example:
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
    if len(value) > _CHUNK // 8:  # a piece at a time: no list of millions of strings
        step = _CHUNK // 8
        return " ".join(_format_items(value[i : i + step]) for i in range(0, len(value), step))
    return _format_items(value)


def _format_items(values: Floats | Ints) -> str:
    kinds = set(map(type, values))
    if kinds == _ONLY_FLOATS:
        # What format_float does, in C: repr is the shortest text, and an integral
        # float below 1e16 is the only one whose repr ends in ".0", which goes.
        return (" ".join(map(repr, values)) + " ").replace(".0 ", " ")[:-1]
    if kinds == _ONLY_INTS:
        return " ".join(map(str, values))
    return " ".join(format_float(v) if isinstance(v, float) else str(v) for v in values)


def plain_value(value: Any) -> Any:
    """Numpy arrays and scalars as plain Python values, lists as tuples.

    Example:
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
