"""Strategies for the pieces of nodes: names, comments, numbers and vectors MuJoCo compiles."""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from typing import TypeVar

from hypothesis import strategies as st

from mjcf_model.nodes.base import Comment, TypedElement
from mjcf_model.values import Floats

__all__ = [
    "comments",
    "names",
]


_T = TypeVar("_T")


_E = TypeVar("_E", bound=TypedElement)


_Draw = Callable[[st.SearchStrategy[_T]], _T]


_COMMENT_TEXT = st.text(
    st.characters(blacklist_categories=("Cs", "Cc"), blacklist_characters="-"), max_size=20
)


_NAME_CHARS = st.sampled_from("abcdefghijklmnopqrstuvwxyz_0123456789")


def comments() -> st.SearchStrategy[Comment]:
    """Comments with arbitrary text that XML allows (no ``--``).

    Examples:
        >>> isinstance(comments().example(), Comment)
        True

    """
    return st.builds(lambda t: Comment(text=f" {t} "), _COMMENT_TEXT)


@functools.cache
def names() -> st.SearchStrategy[str]:
    """Plausible element names: a letter followed by letters, digits and underscores."""
    return st.builds(
        lambda head, tail: head + "".join(tail),
        st.sampled_from("abcdefghijklmnopqrstuvwxyz"),
        st.lists(_NAME_CHARS, max_size=8),
    )


#: The smallest normal single-precision float. Every MuJoCo the library supports
#: compiles values from here up; before 4.0, MuJoCo rejects a number that is
#: subnormal, or that a single-precision field (``rgba``...) would round to zero.
_SMALLEST_COMPILABLE = 2.0**-126


def _compilable(value: float) -> float:
    return value if abs(value) >= _SMALLEST_COMPILABLE else 0.0


@functools.cache
def _number(low: float, high: float) -> st.SearchStrategy[float]:
    """Finite numbers in ``[low, high]`` that every supported MuJoCo compiles."""
    return st.floats(low, high, allow_nan=False, allow_infinity=False).map(_compilable)


@functools.cache
def _length(low: float = 0.01, high: float = 0.5) -> st.SearchStrategy[float]:
    return _number(low, high)


@functools.cache
def _vec(n: int, low: float = -1.0, high: float = 1.0) -> st.SearchStrategy[Floats]:
    return st.tuples(*[_number(low, high) for _ in range(n)])


#: How far from its parent a drawn element is placed, in metres.
_REACH = 3.0


@functools.cache
def _position() -> st.SearchStrategy[Floats]:
    """A position up to a few metres from the parent's origin."""
    return _vec(3, -_REACH, _REACH)


@functools.cache
def _size(low_exponent: float = -3.0, high_exponent: float = 0.0) -> st.SearchStrategy[float]:
    """A size spread evenly over orders of magnitude (a millimetre to a metre by default)."""
    return st.floats(low_exponent, high_exponent).map(lambda exponent: float(10.0**exponent))


@functools.cache
def _mass() -> st.SearchStrategy[float]:
    """A mass from ten grams to a hundred kilograms."""
    return _size(-2.0, 2.0)


@functools.cache
def _angle(units: str, limit_degrees: float = 180.0) -> st.SearchStrategy[float]:
    """An angle within ``limit_degrees`` either way, in ``units`` (``degree`` or ``radian``)."""
    limit = limit_degrees if units == "degree" else math.radians(limit_degrees)
    return _number(-limit, limit)


@functools.cache
def _euler(units: str) -> st.SearchStrategy[Floats]:
    """Euler angles in ``units``."""
    return st.tuples(_angle(units), _angle(units, 90.0), _angle(units))


@functools.cache
def _rgba() -> st.SearchStrategy[Floats]:
    return _vec(4, 0.0, 1.0)


@functools.cache
def _unit_quat() -> st.SearchStrategy[Floats]:
    return _vec(4, -1.0, 1.0).filter(lambda q: sum(v * v for v in q) > 0.1)


@functools.lru_cache(maxsize=256)
def _optional(strategy: st.SearchStrategy[_T]) -> st.SearchStrategy[_T | None]:
    """``None`` or a value of ``strategy``, one strategy object per ``strategy``.

    Hypothesis validates every strategy object it meets anew, which dominates the time a
    drawn model takes; building each combination once keeps draws fast.
    """
    return st.none() | strategy
