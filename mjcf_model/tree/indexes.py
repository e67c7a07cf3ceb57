"""An index of a tree's elements by tag and name, for lookups that come back.

A tree is immutable, so what is below a node never changes: the elements of each
tag, in document order, can be listed once and serve every later lookup on that
node. The reader notes the index of the tree it reads as it reads it (each element's
place in document order), and so does :func:`~mjcf_model.tree.traversal.map_elements`
for a result of the same shape as its input (every transform that only changes
attributes): a loaded or transformed model is indexed from its first lookup
(:func:`indexed`). For another tree built in code, :func:`index_of` builds the index
the second time a node is queried (a single lookup walks the tree and stops at
its first match, which building an index would not beat). An index is kept while the
node lives and forgotten with it: it holds the node by a weak reference and only the
elements below it (which never refer to their parents), so an index never keeps a
tree alive.

>>> from mjcf_model import Body, Geom
>>> body = Body(children=[Geom(name="a"), Body(children=[Geom(name="b")])])
>>> index_of(body) is None, index_of(body) is not None  # the second query builds it
(True, True)
>>> [g.name for g in index_of(body).tagged("geom")], index_of(body).named("geom", "b").name
(['a', 'b'], 'b')
"""

from __future__ import annotations

import weakref
from array import array
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from typing import Any, cast

from mjcf_model.caching import BoundedCache
from mjcf_model.nodes.base import AnyElement, Comment, Element, GenericElement, Node, TypedElement

__all__ = [
    "NotedOrder",
    "TagIndex",
    "elements_below",
    "held_index",
    "first_named",
    "index_of",
    "indexed",
    "name_of",
]


def elements_below(node: Node, tag: str | None = None) -> Iterator[AnyElement]:
    """Every element below ``node`` (of ``tag``, when given), in document order.

    The walk of the lookups: no paths, no comments, a stack of the children being
    gone through (any depth, and one step of the stack per element with children
    rather than per element); a lookup that finds what it looks for stops it early.

    Examples:
        >>> from mjcf_model import Body, Comment, Geom
        >>> body = Body(name="b", children=[Comment(text="c"), Geom(name="g"), Body()])
        >>> [e.tag for e in elements_below(body)], [e.name for e in elements_below(body, "geom")]
        (['geom', 'body'], ['g'])

    """
    if not isinstance(node, Element) or not node.children:
        return
    stack: list[Iterator[Any]] = [iter(node.children)]  # Any: no cast called per element
    push, pop = stack.append, stack.pop
    while stack:
        for child in stack[-1]:
            if child.__class__ is Comment:  # the only nodes that are not elements
                continue
            if tag is None or child.tag == tag:
                yield child
            if child.children:
                push(iter(child.children))
                break
        else:
            pop()


class TagIndex:
    """The elements below one node by tag (document order), and by name when asked.

    The node itself is not in the index (it would keep itself alive through it).
    Built by a walk (:func:`index_of`) or by the reader, which notes each element's
    place as it reads it (:meth:`from_reading`).

    Examples:
        >>> from mjcf_model import Body, Geom, Site
        >>> index = TagIndex(Body(children=[Geom(name="g"), Site(name="s"), Geom()]))
        >>> len(index.tagged("geom")), index.named("site", "s").name, index.named("geom", "s")
        (2, 's', None)
        >>> index.tagged("body")
        []

    """

    __slots__ = ("by_tag", "looked_up", "names", "order", "places")

    def __init__(self, root: Node | None) -> None:
        #: Every element below the root, in document order.
        self.order: list[AnyElement] = list(elements_below(root)) if root is not None else []
        #: The elements of each tag, in document order (a tag the reader noted: on first use).
        self.by_tag: dict[str, list[AnyElement]] = {}
        #: Per tag the reader noted and :meth:`tagged` has not yet listed, the places in
        #: :attr:`order` of its elements.
        self.places: dict[str, Sequence[int]] = {}
        for element in self.order:
            tagged = self.by_tag.get(element.tag)
            if tagged is None:
                self.by_tag[element.tag] = [element]
            else:
                tagged.append(element)
        #: Per tag, the first element of each ``name`` text (made on the second lookup).
        self.names: dict[str, dict[str, AnyElement]] = {}
        #: The tags looked up by name once (by going through their elements).
        self.looked_up: set[str] = set()

    @classmethod
    def from_reading(cls, order: list[AnyElement], places: Mapping[str, Sequence[int]]) -> TagIndex:
        """The index of elements a reader noted in document order, with the places of each tag.

        Examples:
            >>> from mjcf_model import Geom, Site
            >>> index = TagIndex.from_reading([Geom(name="g"), Site()], {"geom": [0], "site": [1]})
            >>> index.named("geom", "g").name, len(index.order)
            ('g', 2)

        """
        index = cls(None)
        index.order, index.places = order, dict(places)
        return index

    def tagged(self, tag: str) -> list[AnyElement]:
        """The elements with this tag, in document order (do not change the list)."""
        tagged = self.by_tag.get(tag)
        if tagged is None:
            places = self.places.pop(tag, None)
            if places is None:
                return []
            order = self.order
            tagged = self.by_tag[tag] = [order[place] for place in places]
        return tagged

    def named(self, tag: str, name: str) -> AnyElement | None:
        """The first element with this tag whose ``name`` attribute is ``name``.

        The first lookup of a tag by name goes through its elements and stops at the
        match; from the second on, a dict of the tag's names answers.
        """
        names = self.names.get(tag)
        if names is None:
            if tag not in self.looked_up:
                self.looked_up.add(tag)
                places = self.places.get(tag)
                if places is not None:  # not listed yet: no list made for a single lookup
                    return first_named(map(self.order.__getitem__, places), name)
                return first_named(self.tagged(tag), name)
            names = self.names[tag] = {}
            for element in reversed(self.tagged(tag)):  # the first one wins
                written = name_of(element)
                if written is not None:
                    names[written] = element
        return names.get(name)


class NotedOrder:
    r"""The elements of a tree being built, noted in document order: its index to be.

    A builder that makes a parent after its children (the reader, ``map_elements``)
    :meth:`reserve`\ s each element's place when it meets the element and puts the
    built node in :attr:`order` at that place; :meth:`index` is then the tree's index.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> notes = NotedOrder()
        >>> body, geom = notes.reserve("body"), notes.reserve("geom")
        >>> notes.order[geom] = Geom(name="g")
        >>> notes.order[body] = Body(children=[notes.order[geom]])
        >>> notes.index().named("geom", "g").name, [e.tag for e in notes.index().order]
        ('g', ['body', 'geom'])

    """

    __slots__ = ("order", "places")

    def __init__(self) -> None:
        #: The elements in document order (a reserved place holds ``None`` until filled).
        self.order: list[Any] = []
        #: The places in :attr:`order` of each tag's elements.
        self.places: dict[str, array[int]] = {}

    def reserve(self, tag: str) -> int:
        """The place of the next ``tag`` element met, in document order."""
        order = self.order
        place = len(order)
        order.append(None)
        places = self.places.get(tag)
        if places is None:
            places = self.places[tag] = array("l")
        places.append(place)
        return place

    def index(self) -> TagIndex:
        """The index of the elements noted (every place filled)."""
        return TagIndex.from_reading(self.order, self.places)


def name_of(element: AnyElement) -> str | None:
    """The ``name`` attribute's text, as :func:`~mjcf_model.tree.queries.find` compares it.

    Examples:
        >>> from mjcf_model import Geom
        >>> name_of(Geom(name="g")), name_of(Geom())
        ('g', None)

    """
    cls = element.__class__
    field = _NAME_FIELDS.get(cls, _UNKNOWN)
    if field is _UNKNOWN:
        field = _NAME_FIELDS[cls] = _name_field(cls)
    if field is None:
        if isinstance(element, GenericElement):
            return element.attributes.get("name")
        return cast(TypedElement, element).extra.get("name")
    value = element.__dict__.get(field)
    return value if value.__class__ is str else None


def first_named(elements: Iterable[AnyElement], name: str) -> AnyElement | None:
    """The first of ``elements`` whose ``name`` is ``name`` (:func:`name_of` for each, inlined).

    Examples:
        >>> from mjcf_model import Geom, Site
        >>> first_named([Geom(name="a"), Site(name="b"), Geom(name="b")], "b").tag
        'site'

    """
    fields, unknown = _NAME_FIELDS, _UNKNOWN
    for element in elements:
        field = fields.get(element.__class__, unknown)
        if field is unknown or field is None:
            if name_of(element) == name:
                return element
        elif element.__dict__.get(field) == name:
            return element
    return None


def _name_field(cls: type) -> str | None:
    """The field a typed class keeps ``name`` in; ``None`` where it is kept as text."""
    if issubclass(cls, TypedElement):
        return cls.__node_info__.table.get("name")
    return None


#: What :func:`name_of` looks up per class: the field that holds ``name``, or ``None``.
_NAME_FIELDS: dict[type, str | None] = {}
_UNKNOWN = "?"


#: Per node (by ``id``): a weak reference to it, and its index (``None`` after the first
#: query). Entries go with their node; the bound keeps many one-off queries cheap.
_INDEXES: BoundedCache[int, tuple[weakref.ref[Node], TagIndex | None]] = BoundedCache(256)


def _forgetter(key: int) -> Callable[[weakref.ref[Node]], None]:
    def forget(reference: weakref.ref[Node]) -> None:
        entry = _INDEXES.get(key)
        if entry is not None and entry[0] is reference:
            del _INDEXES[key]

    return forget


def index_of(node: Node) -> TagIndex | None:
    """The index of ``node``'s tree from its second query on; ``None`` on the first.

    Examples:
        >>> from mjcf_model import Geom
        >>> geom = Geom(name="g")
        >>> index_of(geom), type(index_of(geom)).__name__
        (None, 'TagIndex')

    """
    key = id(node)
    entry = _INDEXES.get(key)
    if entry is None or entry[0]() is not node:
        _INDEXES.remember(key, (weakref.ref(node, _forgetter(key)), None))
        return None
    index = entry[1]
    if index is None:
        index = TagIndex(node)
        _INDEXES[key] = (entry[0], index)
    return index


def held_index(node: Node) -> TagIndex | None:
    """The index ``node``'s tree already holds (read, made, or queried twice), else ``None``.

    Unlike :func:`index_of` it is not a query: it never builds an index nor counts.

    Examples:
        >>> from mjcf_model import loads, Geom
        >>> held_index(Geom()) is None, held_index(loads("<mujoco/>")) is not None
        (True, True)

    """
    entry = _INDEXES.get(id(node))
    return entry[1] if entry is not None and entry[0]() is node else None


def indexed(node: Node, index: TagIndex) -> None:
    """Give ``node`` its ``index`` now (the reader's, noted as it read the tree).

    Its lookups then use the index from the first one on.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="g")])
        >>> indexed(body, TagIndex(body))
        >>> index_of(body).named("geom", "g").name
        'g'

    """
    key = id(node)
    _INDEXES.remember(key, (weakref.ref(node, _forgetter(key)), index))
