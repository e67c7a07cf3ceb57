"""``==`` and ``hash`` of nodes: by value, at any depth, without recursion.

Nodes of one class that store the same fields in the same order (two loaded
copies of a file, or nodes built alike) compare as two tuples read by one
getter per *shape*; other pairs compare field by field. Shared subtrees are
equal by identity and skipped.
"""

from __future__ import annotations

import operator
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from mjcf_model.caching import BoundedCache

if TYPE_CHECKING:
    from mjcf_model.nodes.node_info import DeclaredNode as Node

__all__ = ["Subtree", "forest_hash", "forests_equal"]


class _Shape:
    """What ``==`` and ``hash`` read from nodes of one class that store one set of fields.

    Made once per class and set of stored fields (:func:`_shape_of`) and shared, so
    two nodes store the same compared fields exactly when they have the same shape.
    """

    __slots__ = ("defaultable", "hash_getter", "hash_token", "values")

    def __init__(self, cls: type[Node], compared: tuple[str, ...]) -> None:
        defaults = cls.__node_info__.defaults
        #: The stored fields whose default is not ``None`` (``extra``): a node may
        #: store such a field holding its default, and equal one that does not.
        self.defaultable = tuple(k for k in compared if defaults.get(k) is not None)
        hashed = tuple(k for k in compared if k not in self.defaultable)
        #: The compared fields' values, from the node's ``__dict__``.
        self.values = _items_getter(compared)
        #: The values of the fields that are never stored holding their default.
        self.hash_getter = _items_getter(hashed)
        #: The class and those fields' names, hashed once.
        self.hash_token = hash((cls, hashed))


def _items_getter(keys: tuple[str, ...]) -> Callable[[dict[str, Any]], Any]:
    """Read ``keys`` of a dict at once (one value bare, several as a tuple)."""
    return operator.itemgetter(*keys) if keys else _nothing


def _nothing(_data: dict[str, Any]) -> tuple[()]:
    return ()


#: How many shapes each table keeps (hostile text could make any number).
_MAX_SHAPES = 1024
#: Per class, the shape of each tuple of stored fields, in storage order (``tuple(__dict__)``).
_SHAPES: dict[type, BoundedCache[tuple[str, ...], _Shape]] = {}
#: The one shape of each class and set of compared fields (``(cls, *sorted names)``);
#: when it empties, older shapes stay valid: only ``is`` between them fails.
_SHAPES_BY_SET: BoundedCache[tuple[Any, ...], _Shape] = BoundedCache(_MAX_SHAPES)
#: What ``_SHAPES.get`` gives for a class not met yet (never filled).
_NO_SHAPES: dict[tuple[str, ...], _Shape] = {}


def _shape_of(node: Node, keys: tuple[str, ...] | None = None) -> _Shape:
    """The shape of ``node``, whose stored fields are ``keys`` if given.

    The walks of ``==`` and ``hash`` look the shape up inline first.
    """
    cls = type(node)
    if keys is None:
        keys = tuple(node.__dict__)
    known = _SHAPES.get(cls)
    if known is None:
        known = _SHAPES[cls] = BoundedCache(_MAX_SHAPES)
    shape = known.get(keys)
    if shape is None:
        skip = cls.__node_info__.not_compared
        compared = tuple(sorted(k for k in keys if k not in skip))
        shape = _SHAPES_BY_SET.get((cls, *compared))
        if shape is None:
            shape = _SHAPES_BY_SET.remember((cls, *compared), _Shape(cls, compared))
        known.remember(keys, shape)
    return shape


def _nodes_equal(a: Node, b: Node) -> bool:
    """Whether ``a`` and ``b`` hold the same compared values (their children left out).

    The general case of :func:`_forests_equal`, for nodes that do not store the
    same fields in the same order: either class, either order, and a field one
    stores holding its default while the other leaves it out.
    """
    if type(a) is not type(b):
        return False
    shape = _shape_of(a)
    if shape is _shape_of(b):
        va, vb = shape.values(a.__dict__), shape.values(b.__dict__)
        return va is vb or va == vb  # ``is``: a field holds the one NAN object, equal to itself
    skip = type(a).__node_info__.not_compared
    names = sorted({*a.__dict__, *b.__dict__} - skip)
    return [getattr(a, n) for n in names] == [getattr(b, n) for n in names]


def forests_equal(left: tuple[Node, ...], right: tuple[Node, ...]) -> bool:
    """Whether two forests are equal by value, walked with an explicit stack.

    Nodes of one class that store the same fields in the same order (two loaded
    copies of a file, or two nodes built alike) take the fast path: one shape,
    and their values compared as two tuples in C.
    """
    shapes = _SHAPES
    stack = [(left, right)]
    while stack:
        left, right = stack.pop()
        if len(left) != len(right):
            return False
        for a, b in zip(left, right, strict=True):
            if a is b:
                continue  # shared: equal by identity
            da = a.__dict__
            db = b.__dict__
            cls = type(a)
            keys = tuple(da)
            if cls is type(b) and keys == tuple(db):
                shape = shapes.get(cls, _NO_SHAPES).get(keys) or _shape_of(a, keys)
                va = shape.values(da)
                vb = shape.values(db)
                if va is not vb and va != vb:  # ``is``: the one NAN object equals itself
                    return False
            elif not _nodes_equal(a, b):
                return False
            ca = da.get("children")
            cb = db.get("children")
            if ca is not cb:
                stack.append((ca or (), cb or ()))
    return True


def forest_hash(forest: tuple[Node, ...]) -> int:
    """The hash of a forest: every node's class, compared fields and values, and shape."""
    shapes = _SHAPES
    parts: list[Any] = []
    stack = [forest]
    while stack:
        forest = stack.pop()
        parts.append(len(forest))
        for item in forest:
            data = item.__dict__
            keys = tuple(data)
            shape = shapes.get(type(item), _NO_SHAPES).get(keys) or _shape_of(item, keys)
            parts.append(shape.hash_token)
            parts.append(shape.hash_getter(data))
            if shape.defaultable:
                stored = _not_default(item, shape.defaultable)
                if stored:
                    parts.append(stored)
            children = data.get("children")
            if children:
                stack.append(children)
    return hash(tuple(parts))


def _not_default(node: Node, names: tuple[str, ...]) -> tuple[Any, ...]:
    """The fields among ``names`` that ``node`` stores holding other than their default."""
    data, defaults = node.__dict__, type(node).__node_info__.defaults
    return tuple([(n, data[n]) for n in names if data[n] != defaults[n]])


class Subtree:
    """What ``==`` and ``hash`` see of an element's ``children``: the whole forest below.

    Comparing and hashing walk the forest with an explicit stack, not by
    recursion, so trees of any depth compare and hash (MuJoCo reads bodies
    nested 496 deep; an include chain makes deeper ones). Shared subtrees are
    skipped by identity.
    """

    __slots__ = ("children",)

    def __init__(self, children: tuple[Node, ...]) -> None:
        #: The children of the element compared.
        self.children = children

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Subtree):
            return NotImplemented
        return self.children is other.children or forests_equal(self.children, other.children)

    def __hash__(self) -> int:
        return forest_hash(self.children)
