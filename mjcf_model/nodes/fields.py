"""The field helpers node classes are declared with: one per kind of MJCF attribute.

Each returns an attrs field whose converter reads MJCF text or Python values
(:mod:`mjcf_model.values`) and whose default is ``None`` ("not written").

>>> vec3().converter("0 0 1")
(0.0, 0.0, 1.0)
"""

from __future__ import annotations

from collections.abc import Callable, Collection
from typing import Any

import attrs

from mjcf_model.values import (
    float_key,
    one_of,
    to_bool,
    to_float,
    to_floats,
    to_int,
    to_ints,
    to_str,
    to_vec1to2,
    to_vec1to3,
    to_vec1to5,
    to_vec2,
    to_vec3,
    to_vec4,
    to_vec6,
)

__all__ = [
    "boolean",
    "integer",
    "integers",
    "keyword",
    "number",
    "numbers",
    "text",
    "vec1to2",
    "vec1to3",
    "vec1to5",
    "vec2",
    "vec3",
    "vec4",
    "vec6",
]


def _field(converter: Callable[[Any], Any], xml: str | None, **more: Any) -> Any:
    metadata = more.pop("metadata", {})
    if xml is not None:
        metadata = {**metadata, "xml": xml}
    return attrs.field(default=None, converter=converter, metadata=metadata, **more)


def text(*, xml: str | None = None) -> Any:
    """A text attribute (a name, a file, a free-form string); ``xml`` if MJCF spells it otherwise.

    Examples:
        >>> text(xml="class").metadata["xml"]
        'class'

    """
    return _field(to_str, xml)


def keyword(choices: Collection[str], *, xml: str | None = None) -> Any:
    """A text attribute that takes one of MJCF's keywords.

    Examples:
        >>> from mjcf_model import Joint
        >>> "hinge" in attrs.fields(Joint).type.validator.allowed
        True

    """
    return _field(to_str, xml, validator=one_of(choices))


def number() -> Any:
    """One real number (``==`` holds NaN equal to NaN).

    Examples:
        >>> number().converter("1e-3")
        0.001

    """
    return _field(to_float, None, eq=float_key)


def integer() -> Any:
    """One integer.

    Examples:
        >>> integer().converter("3")
        3

    """
    return _field(to_int, None)


def boolean() -> Any:
    """MJCF's ``"true"``/``"false"``.

    Examples:
        >>> boolean().converter("true")
        True

    """
    return _field(to_bool, None)


def numbers() -> Any:
    """Any number of real numbers.

    Examples:
        >>> numbers().converter("1 2")
        (1.0, 2.0)

    """
    return _field(to_floats, None)


def integers() -> Any:
    """Any number of integers.

    Examples:
        >>> integers().converter("1 2")
        (1, 2)

    """
    return _field(to_ints, None)


def vec2() -> Any:
    """Exactly two real numbers (ranges).

    Examples:
        >>> vec2().converter("-1 1")
        (-1.0, 1.0)

    """
    return _field(to_vec2, None)


def vec3() -> Any:
    """Exactly three real numbers (positions, axes).

    Examples:
        >>> vec3().converter([0, 0, 1])
        (0.0, 0.0, 1.0)

    """
    return _field(to_vec3, None)


def vec4() -> Any:
    """Exactly four real numbers (quaternions, colours).

    Examples:
        >>> vec4().converter("1 0 0 0")
        (1.0, 0.0, 0.0, 0.0)

    """
    return _field(to_vec4, None)


def vec6() -> Any:
    """Exactly six real numbers (``fromto``, ``xyaxes``).

    Examples:
        >>> len(vec6().converter("0 0 0 1 1 1"))
        6

    """
    return _field(to_vec6, None)


def vec1to2() -> Any:
    """One or two real numbers (``solref``).

    Examples:
        >>> vec1to2().converter("0.02")
        (0.02,)

    """
    return _field(to_vec1to2, None)


def vec1to3() -> Any:
    """One to three real numbers (``size``, ``friction``).

    Examples:
        >>> vec1to3().converter("0.1 0.2")
        (0.1, 0.2)

    """
    return _field(to_vec1to3, None)


def vec1to5() -> Any:
    """One to five real numbers (``solimp``).

    Examples:
        >>> vec1to5().converter("0.9 0.95")
        (0.9, 0.95)

    """
    return _field(to_vec1to5, None)
