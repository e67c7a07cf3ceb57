"""Looking things up in a node tree: find elements and parents.

All queries are read-only: they return nodes of the tree itself (so ``is`` works
on the results), in document order.

>>> from mjcf_model import loads
>>> model = loads(
...     '<mujoco><worldbody><body name="arm"><geom name="a" group="1"/>'
...     '<geom name="b"/></body></worldbody></mujoco>'
... )
>>> find(model, "geom", group=1).name
'a'
>>> [g.name for g in find_all(model, "geom")]
['a', 'b']
>>> parent_of(model, find(model, "geom", name="b")).name
'arm'
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterator
from typing import cast

from mjcf_model.caching import BoundedCache
from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    GenericElement,
    Node,
    TypedElement,
    get_attribute,
)
from mjcf_model.nodes.node_info import tuple_getter
from mjcf_model.tree.indexes import elements_below, first_named, index_of, name_of
from mjcf_model.tree.traversal import walk
from mjcf_model.values import Value, format_value, plain_value

__all__ = [
    "attribute_reader",
    "attribute_values",
    "find",
    "find_all",
    "parent_of",
    "walk",
]

#: Keyword arguments that stand for another MJCF attribute (``class`` is a Python keyword).
_KEYWORD_ATTRIBUTES = {"dclass": "class"}


#: The reader :func:`attribute_values` made for each typed class and attribute names.
_READERS: BoundedCache[
    tuple[type, tuple[str, ...]], Callable[[AnyElement], tuple[Value | None, ...]]
] = BoundedCache(1024)


def attribute_values(element: AnyElement, names: tuple[str, ...]) -> tuple[Value | None, ...]:
    """The values of the MJCF attributes ``names`` (``None`` where not written), read at once.

    The same values as :func:`~mjcf_model.nodes.base.get_attribute` for each name, read
    by one reader per class and names (:func:`attribute_reader`), made on first use: the
    transforms that read several attributes of every element use it.

    Examples:
        >>> from mjcf_model import Geom
        >>> attribute_values(Geom(dclass="arm", size=[1], extra={"x": "1"}), ("class", "pos", "x"))
        ('arm', None, '1')

    """
    reader = _READERS.get((type(element), names))
    if reader is None:
        reader = _READERS.remember((type(element), names), attribute_reader(type(element), names))
    return reader(element)


def attribute_reader(
    cls: type[Element], names: tuple[str, ...]
) -> Callable[[AnyElement], tuple[Value | None, ...]]:
    """What reads the MJCF attributes ``names`` of a ``cls`` element at once, as a tuple.

    For a caller that keeps one per class (the transforms' plans) instead of looking
    one up per element.

    Examples:
        >>> from mjcf_model import Geom, GenericElement
        >>> attribute_reader(Geom, ("name", "x"))(Geom(name="g", extra={"x": "1"}))
        ('g', '1')
        >>> attribute_reader(GenericElement, ("name",))(GenericElement(tag="t", attributes={}))
        (None,)

    """
    if issubclass(cls, GenericElement):

        def read_text(element: AnyElement) -> tuple[Value | None, ...]:
            get = cast(GenericElement, element).attributes.get
            return tuple([get(name) for name in names])

        return read_text
    table = cls.__node_info__.table
    fields = tuple(table.get(name) for name in names)
    if None not in fields:
        return tuple_getter(cast(tuple[str, ...], fields))
    pairs = tuple(zip(names, fields, strict=True))

    def read(element: AnyElement) -> tuple[Value | None, ...]:
        extra = cast(TypedElement, element).extra
        return tuple(
            [extra.get(name) if field is None else getattr(element, field) for name, field in pairs]
        )

    return read


def _matches(value: Value | None, expected: object) -> bool:
    """Whether a written attribute value (``None``: not written) meets one expectation."""
    if expected is None:
        return value is None
    if value is None:
        return False
    if isinstance(expected, str):
        return format_value(value) == expected
    wanted = plain_value(expected)
    if isinstance(value, str):
        # An attribute the element keeps as text (generic element, extra attribute).
        return format_value(wanted) == value
    if isinstance(value, bool) or isinstance(wanted, bool):
        return isinstance(value, bool) and isinstance(wanted, bool) and value == wanted
    if isinstance(value, tuple):
        if not isinstance(wanted, tuple):
            wanted = (wanted,)
        return len(wanted) == len(value) and all(
            not isinstance(w, (bool, str, tuple)) and w == v
            for w, v in zip(wanted, value, strict=True)
        )
    return not isinstance(wanted, tuple) and bool(wanted == value)


def _tag_matches(element: AnyElement, tag: str | Collection[str]) -> bool:
    if isinstance(tag, str):
        return element.tag == tag
    return element.tag in tag


def _candidates(node: Node, tag: str | Collection[str], name: object) -> Iterator[AnyElement]:
    """The elements below ``node`` that may match: from its index when it has one.

    ``name``: the ``name`` text looked for, or ``None`` when the lookup is not by name;
    the elements of another name are left out (the caller still checks every attribute).
    """
    index = index_of(node)
    if index is None:
        found = (
            elements_below(node, tag)
            if isinstance(tag, str)
            else (e for e in elements_below(node) if e.tag in tag)
        )
        if isinstance(name, str):
            first = first_named(found, name)  # the walk stops there
            if first is None:
                return
            yield first
            found = (e for e in found if name_of(e) == name)  # and goes on from there
        yield from found
    elif not isinstance(tag, str):
        yield from (e for e in index.order if e.tag in tag)
    elif isinstance(name, str):
        first = index.named(tag, name)
        if first is not None:
            yield first  # the first of that name; later ones follow in document order
            yield from (e for e in index.tagged(tag) if e is not first and name_of(e) == name)
    else:
        yield from index.tagged(tag)


def _iter_matches(
    node: Node, tag: str | Collection[str], attributes: dict[str, object]
) -> Iterator[AnyElement]:
    wanted = [(_KEYWORD_ATTRIBUTES.get(k, k), v) for k, v in attributes.items()]

    def matches(element: AnyElement) -> bool:
        return all(_matches(get_attribute(element, name), expected) for name, expected in wanted)

    if isinstance(node, Element) and _tag_matches(node, tag) and matches(node):
        yield node
    for element in _candidates(node, tag, attributes.get("name")):
        if matches(element):
            yield element


def find(node: Node, tag: str | Collection[str], /, **attributes: object) -> AnyElement | None:
    """The first element, ``node`` included, in document order with this tag and attributes.

    Args:
        node: Where to start; it is itself a candidate.
        tag: The tag, or any collection of tags, to look for.
        **attributes: Attribute values the element must have. ``None`` means
            "not written". A string is compared with the attribute's MJCF text
            (``format_value`` of a typed value); anything else with the typed
            value (lists and arrays as tuples, numbers numerically, a single
            number against a one-element vector). An attribute kept as text
            (generic elements, ``extra``) is compared with the expectation's
            text. ``dclass`` stands for ``class``.

    Returns:
        The element, or ``None`` when nothing matches.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="g", size=[0.1], group=1), Geom(name="h")])
        >>> find(body, "geom", size=[0.1]).name, find(body, "geom", group="1").name
        ('g', 'g')
        >>> find(body, ("geom", "site"), group=None).name
        'h'
        >>> find(body, "joint") is None
        True

    """
    return next(_iter_matches(node, tag, attributes), None)


def find_all(node: Node, tag: str | Collection[str], /, **attributes: object) -> list[AnyElement]:
    """Every element, ``node`` included, with this tag and attributes, in document order.

    Matches like :func:`find`; an empty list when nothing matches (robosuite's
    ``find_elements`` returns ``None`` then).

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="g", dclass="vis"), Geom(name="h")])
        >>> [g.name for g in find_all(body, "geom")], find_all(body, "site")
        (['g', 'h'], [])
        >>> [g.name for g in find_all(body, "geom", dclass="vis")]
        ['g']

    """
    return list(_iter_matches(node, tag, attributes))


def parent_of(root: Node, node: Node) -> AnyElement | None:
    """The element whose ``children`` hold ``node`` itself (compared with ``is``).

    Returns ``None`` for ``root`` and for a node that is not in the tree (an
    equal copy is not the node).

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> geom = Geom(name="g")
        >>> body = Body(name="b", children=[geom])
        >>> parent_of(body, geom).name, parent_of(body, body), parent_of(body, Geom(name="g"))
        ('b', None, None)

    """
    for _path, element in walk(root):
        if any(child is node for child in element.children):
            return element
    return None
