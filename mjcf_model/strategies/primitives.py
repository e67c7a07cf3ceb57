"""Strategies for the pieces of nodes: names, comments, numbers and vectors MuJoCo compiles."""

from __future__ import annotations

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

    Example:
        >>> isinstance(comments().example(), Comment)
        True

    """
    return st.builds(lambda t: Comment(text=f" {t} "), _COMMENT_TEXT)


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


def _number(low: float, high: float) -> st.SearchStrategy[float]:
    """Finite numbers in ``[low, high]`` that every supported MuJoCo compiles."""
    return st.floats(low, high, allow_nan=False, allow_infinity=False).map(_compilable)


def _length(low: float = 0.01, high: float = 0.5) -> st.SearchStrategy[float]:
    return _number(low, high)


def _vec(n: int, low: float = -1.0, high: float = 1.0) -> st.SearchStrategy[Floats]:
    return st.tuples(*[_number(low, high) for _ in range(n)])


def _rgba() -> st.SearchStrategy[Floats]:
    return _vec(4, 0.0, 1.0)


def _unit_quat() -> st.SearchStrategy[Floats]:
    return _vec(4, -1.0, 1.0).filter(lambda q: sum(v * v for v in q) > 0.1)
