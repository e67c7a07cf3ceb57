"""Remembering what the object classes compute again and again from the same immutable input.

robosuite's environments make the same objects at every reset: the same file
read, the same geoms split, the same names found, only the prefix changing.
Nodes are immutable, so what was computed from one node holds for it forever;
a :class:`Memo` keeps the last results (by value, or by the identity of the
node they were computed from) and gives them back instead of computing again.

>>> memo = Memo(2)
>>> memo.get("a", lambda: [1]) is memo.get("a", lambda: [2])
True
"""

from __future__ import annotations

from collections.abc import Callable, Hashable
from typing import Generic, TypeVar

__all__ = ["Memo"]

_V = TypeVar("_V")


class Memo(Generic[_V]):
    """The last ``size`` results, by key; the oldest goes first.

    Args:
        size: How many results are kept.

    """

    def __init__(self, size: int) -> None:
        self._size = size
        self._kept: dict[Hashable, _V] = {}
        #: The inputs of :meth:`of`, kept alive so that their identity stays theirs.
        self._inputs: dict[Hashable, object] = {}

    def get(self, key: Hashable, make: Callable[[], _V]) -> _V:
        """The result kept for ``key``, or ``make()`` (then kept).

        Example:
            >>> Memo(1).get(("x", 1), lambda: "made")
            'made'

        """
        if key in self._kept:
            return self._kept[key]
        if len(self._kept) >= self._size:
            oldest = next(iter(self._kept))
            del self._kept[oldest]
            self._inputs.pop(oldest, None)
        result = self._kept[key] = make()
        return result

    def of(self, node: object, make: Callable[[], _V], *also: Hashable) -> _V:
        """The result kept for this very ``node`` (by identity) and ``also``, or ``make()``.

        Example:
            >>> memo, node = Memo(4), object()
            >>> memo.of(node, lambda: 1), memo.of(node, lambda: 2), memo.of(object(), lambda: 3)
            (1, 1, 3)
            >>> memo.of(node, lambda: 4, "other")
            4

        """
        key = (id(node), *also)
        if self._inputs.get(key) is not node:
            self._kept.pop(key, None)
        result = self.get(key, make)
        self._inputs[key] = node
        return result
