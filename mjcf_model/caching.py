"""The library's one kind of cache: a dict that holds at most ``limit`` entries.

The caches the readers, walks and converters keep are keyed by things input can
make any number of (tags, sets of attribute names, shapes of stored fields, files),
so each is bounded: when full it empties itself and fills again. Hostile input then
costs some answers computed twice, never memory.

>>> cache = BoundedCache[str, int](limit=2)
>>> cache.remember("a", 1), cache.remember("b", 2), cache.get("a")
(1, 2, 1)
>>> cache.remember("c", 3), sorted(cache)
(3, ['c'])
>>> cache.recall("c", lambda: 4), cache.recall("d", lambda: 4)
(3, 4)
"""

from __future__ import annotations

from collections.abc import Callable, Hashable
from typing import Any, TypeVar

__all__ = ["BoundedCache", "IdentityCache"]

_K = TypeVar("_K")
_V = TypeVar("_V")


class BoundedCache(dict[_K, _V]):
    """A dict of remembered answers that empties itself when it holds ``limit`` of them.

    Look answers up as in any dict (``get``, ``[]``: the dict's own, as fast as one);
    store them with :meth:`remember`, which keeps the bound.
    """

    __slots__ = ("limit",)

    def __init__(self, limit: int) -> None:
        """An empty cache that will hold at most ``limit`` answers."""
        super().__init__()
        #: How many answers the cache holds before it empties itself.
        self.limit = limit

    def remember(self, key: _K, value: _V) -> _V:
        """Store ``value`` under ``key`` (emptying the cache first if it is full); return it."""
        if len(self) >= self.limit:
            self.clear()
        self[key] = value
        return value

    def recall(self, key: _K, compute: Callable[[], _V]) -> _V:
        """The answer remembered for ``key``, or ``compute()``, remembered (``None`` too)."""
        if key in self:
            return self[key]
        return self.remember(key, compute())


class IdentityCache(BoundedCache[tuple[Hashable, ...], tuple[Any, _V]]):
    """Answers about objects by their identity, each object kept alive while remembered.

    An ``id`` is reused once its object is gone; keeping the object with its answer means
    an answer is only ever given for the very object it was computed for.

    Examples:
        >>> cache = IdentityCache[int](limit=4)
        >>> tree = ["a"]
        >>> cache.recall_for(tree, lambda: 1), cache.recall_for(tree, lambda: 2)
        (1, 1)
        >>> cache.recall_for(["a"], lambda: 3), cache.recall_for(tree, lambda: 4, "other")
        (3, 4)

    """

    __slots__ = ()

    def recall_for(self, thing: object, compute: Callable[[], _V], *also: Hashable) -> _V:
        """The answer remembered for this very ``thing`` (and ``also``), or ``compute()``."""
        key = (id(thing), *also)
        found = self.get(key)
        if found is None or found[0] is not thing:
            found = self.remember(key, (thing, compute()))
        return found[1]
