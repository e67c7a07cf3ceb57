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
"""

from __future__ import annotations

from typing import TypeVar

__all__ = ["BoundedCache"]

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
