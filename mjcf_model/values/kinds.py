"""What a node field may hold: numbers, tuples of them, and text kept as it was written."""

from __future__ import annotations

import re
from typing import Any

from mjcf_model.errors import MjcfValueError

__all__ = [
    "Floats",
    "Ints",
    "NAN",
    "NOT_XML_CHARACTER",
    "Unparsed",
    "Value",
    "check_name",
    "check_text",
    "float_key",
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

    Examples:
        >>> NAN == NAN, float_key(NAN) == float_key(NAN)
        (False, True)

    """
    return (value,)


_ONLY_FLOATS = frozenset({float})


_ONLY_INTS = frozenset({int})


#: Longer text is split a piece at a time, so a 50 MB attribute never becomes
#: millions of token strings at once.
_CHUNK = 1 << 20


_SPACES = (" ", "\n", "\t", "\r", "\f", "\v")


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

    Examples:
        >>> from mjcf_model import loads
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


#: One character XML 1.0 cannot carry, but for the escapes of bytes that are not UTF-8
#: (:mod:`mjcf_model.values.encoding`: MuJoCo reads those bytes, and they are written back
#: as they were read). Every pattern in the library is a single character class, which
#: cannot backtrack (tests/mjcf_model/values/test_reading.py checks this).
NOT_XML_CHARACTER = re.compile(
    "[^\t\n\r\x20-\ud7ff\udc80-\udcff\ue000-\ufffd\U00010000-\U0010ffff]"
)


_NOT_NAME_CHARACTER = re.compile(
    "[^-.0-9:A-Z_a-z\xb7\xc0-\xd6\xd8-\xf6\xf8-\u037d\u037f-\u1fff\u200c\u200d"
    "\u203f\u2040\u2070-\u218f\u2c00-\u2fef\u3001-\ud7ff\uf900-\ufdcf\ufdf0-\ufffd"
    "\U00010000-\U000effff]"
)


_NOT_NAME_START = frozenset("-.0123456789\xb7\u203f\u2040") | {chr(c) for c in range(0x300, 0x370)}


def check_text(value: str, what: str = "text") -> str:
    r"""Return ``value``, or raise when it holds a character XML cannot carry.

    Such text (NUL and other control characters, lone surrogates but the escapes
    of bytes that are not UTF-8) could be
    built but not written and read back, so no node accepts it.

    Examples:
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

    Examples:
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
