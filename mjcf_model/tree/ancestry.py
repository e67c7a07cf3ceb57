"""The ancestors the tree walks hand to their visitors: root first, shared between levels.

>>> from mjcf_model import Body
>>> root = Ancestors().extended(Body(name="root"))
>>> [body.name for body in root.extended(Body(name="arm"))], len(root)
(['root', 'arm'], 1)
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from typing import Any, TypeVar, overload

from mjcf_model.nodes.base import AnyElement

__all__ = ["Ancestors", "fold_ancestors"]

_V = TypeVar("_V")


class Ancestors(Sequence[AnyElement]):
    """The elements from the root down to a parent, as the walks hand them to visitors.

    Each level extends its parent's ancestors in constant time and shares them,
    so walking a chain of any depth stays linear; the last ancestors and
    ``reversed`` are read without copying.

    Examples:
        >>> from mjcf_model import Body
        >>> a = Ancestors().extended(Body(name="root")).extended(Body(name="arm"))
        >>> len(a), a[-1].name, [b.name for b in a]
        (2, 'arm', ['root', 'arm'])

    """

    __slots__ = ("_folds", "_items", "_last", "_length", "_parent")

    def __init__(self, parent: Ancestors | None = None, last: AnyElement | None = None) -> None:
        self._parent = parent
        self._last = last
        self._length: int = 0 if parent is None else parent._length + 1
        self._items: tuple[AnyElement, ...] | None = None if parent is not None else ()
        self._folds: dict[object, Any] | None = None

    def folded(self, step: Callable[[_V, AnyElement], _V], initial: _V) -> _V:
        """``step`` folded over the ancestors root first, from ``initial``; once per level.

        Each level keeps its result (keyed by ``step``, so one ``step`` always
        goes with the same ``initial``), so what an element inherits from its
        ancestors (a ``childclass``) costs constant time per level however deep
        the tree is.

        Examples:
            >>> from mjcf_model import Body
            >>> a = Ancestors().extended(Body(name="root")).extended(Body(name="arm"))
            >>> a.folded(lambda names, body: (*names, body.name), ())
            ('root', 'arm')

        """
        if self._folds is not None and step in self._folds:  # the common case: known
            known: _V = self._folds[step]
            return known
        pending: list[Ancestors] = []
        level: Ancestors | None = self
        value = initial
        while level is not None and level._last is not None:
            folds = level._folds
            if folds is not None and step in folds:
                value = folds[step]
                break
            pending.append(level)
            level = level._parent
        for level in reversed(pending):
            value = step(value, level._last)  # type: ignore[arg-type]
            if level._folds is None:
                level._folds = {}
            level._folds[step] = value
        return value

    def extended(self, element: AnyElement) -> Ancestors:
        """These ancestors followed by ``element``."""
        return Ancestors(self, element)

    def __len__(self) -> int:
        return self._length

    def __reversed__(self) -> Iterator[AnyElement]:
        node: Ancestors | None = self
        while node is not None and node._last is not None:
            yield node._last
            node = node._parent

    def __iter__(self) -> Iterator[AnyElement]:
        return iter(self.as_tuple())

    def as_tuple(self) -> tuple[AnyElement, ...]:
        """The ancestors as a tuple, root first (built once)."""
        if self._items is None:
            items = list(reversed(self))
            items.reverse()
            self._items = tuple(items)
        return self._items

    @overload
    def __getitem__(self, index: int) -> AnyElement: ...
    @overload
    def __getitem__(self, index: slice) -> tuple[AnyElement, ...]: ...
    def __getitem__(self, index: int | slice) -> AnyElement | tuple[AnyElement, ...]:
        if index == -1 and self._last is not None:
            return self._last
        return self.as_tuple()[index]

    def __eq__(self, other: object) -> bool:
        if isinstance(other, (Ancestors, tuple)):
            return self.as_tuple() == tuple(other)
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self.as_tuple())

    def __repr__(self) -> str:
        return f"Ancestors({self.as_tuple()!r})"


def fold_ancestors(
    ancestors: Sequence[AnyElement], step: Callable[[_V, AnyElement], _V], initial: _V
) -> _V:
    """``step`` folded over ``ancestors`` root first, from ``initial``.

    On :class:`Ancestors` (what the walks hand out) this is :meth:`Ancestors.folded`,
    constant time per level; any other sequence is folded from the start.

    Examples:
        >>> from mjcf_model import Body
        >>> def childclass(inherited, element):
        ...     return element.childclass or inherited
        >>> chain = [Body(childclass="a"), Body(), Body(childclass="b"), Body()]
        >>> fold_ancestors(chain[:2], childclass, None), fold_ancestors(chain, childclass, None)
        ('a', 'b')

    """
    if isinstance(ancestors, Ancestors):
        return ancestors.folded(step, initial)
    value = initial
    for ancestor in ancestors:
        value = step(value, ancestor)
    return value
