"""The last results computed from the same input (by value, or by a node's identity).

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
    """The last ``size`` results, by key; the oldest goes first."""

    def __init__(self, size: int) -> None:
        self._size = size
        self._kept: dict[Hashable, _V] = {}
        #: The inputs of :meth:`of`, kept alive so that their identity stays theirs.
        self._inputs: dict[Hashable, object] = {}

    def get(self, key: Hashable, make: Callable[[], _V]) -> _V:
        """The result kept for ``key``, or ``make()`` (then kept)."""
        if key in self._kept:
            return self._kept[key]
        if len(self._kept) >= self._size:
            oldest = next(iter(self._kept))
            del self._kept[oldest]
            self._inputs.pop(oldest, None)
        result = self._kept[key] = make()
        return result

    def of(self, node: object, make: Callable[[], _V], *also: Hashable) -> _V:
        """The result kept for this very ``node`` (by identity) and ``also``, or ``make()``."""
        key = (id(node), *also)
        if self._inputs.get(key) is not node:
            self._kept.pop(key, None)
        result = self.get(key, make)
        self._inputs[key] = node
        return result
