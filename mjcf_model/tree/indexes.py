"""An index of a tree's elements by tag and name, for lookups that come back.

A tree is immutable, so what is below a node never changes: the elements of each
tag, in document order, can be listed once and serve every later lookup on that
node. :func:`index_of` builds the index the second time a node is queried (a
single lookup walks the tree and stops at its first match, which an index would
not beat), keeps it while the node lives, and forgets it with the node: it holds
the node by a weak reference and only the elements below it (which never refer
to their parents), so an index never keeps a tree alive.

>>> from mjcf_model import Body, Geom
>>> body = Body(children=[Geom(name="a"), Body(children=[Geom(name="b")])])
>>> index_of(body) is None, index_of(body) is not None  # the second query builds it
(True, True)
>>> [g.name for g in index_of(body).tagged("geom")], index_of(body).named("geom", "b").name
(['a', 'b'], 'b')
"""

from __future__ import annotations

import weakref
from collections.abc import Callable, Iterator

from mjcf_model.caching import BoundedCache
from mjcf_model.nodes.base import AnyElement, Element, GenericElement, Node, TypedElement

__all__ = ["TagIndex", "elements_below", "index_of"]


def elements_below(node: Node) -> Iterator[AnyElement]:
    """Every element below ``node``, in document order: the walk of the lookups.

    No paths, no comments, an explicit stack (any depth); a lookup that finds what it
    looks for stops it early.

    Examples:
        >>> from mjcf_model import Body, Comment, Geom
        >>> body = Body(name="b", children=[Comment(text="c"), Geom(name="g"), Body()])
        >>> [e.tag for e in elements_below(body)]
        ['geom', 'body']

    """
    if not isinstance(node, Element):
        return
    stack = [child for child in reversed(node.children) if isinstance(child, Element)]
    while stack:
        element = stack.pop()
        yield element
        if element.children:
            stack.extend([c for c in reversed(element.children) if isinstance(c, Element)])


class TagIndex:
    """The elements below one node by tag (document order), and by name when asked.

    The node itself is not in the index (it would keep itself alive through it).

    Examples:
        >>> from mjcf_model import Body, Geom, Site
        >>> index = TagIndex(Body(children=[Geom(name="g"), Site(name="s"), Geom()]))
        >>> len(index.tagged("geom")), index.named("site", "s").name, index.named("geom", "s")
        (2, 's', None)
        >>> index.tagged("body")
        []

    """

    __slots__ = ("by_tag", "names", "order")

    def __init__(self, root: Node) -> None:
        #: Every element below the root, in document order.
        self.order: list[AnyElement] = list(elements_below(root))
        #: The elements of each tag, in document order.
        self.by_tag: dict[str, list[AnyElement]] = {}
        for element in self.order:
            tagged = self.by_tag.get(element.tag)
            if tagged is None:
                self.by_tag[element.tag] = [element]
            else:
                tagged.append(element)
        #: Per tag, the first element of each ``name`` text (made on first use).
        self.names: dict[str, dict[str, AnyElement]] = {}

    def tagged(self, tag: str) -> list[AnyElement]:
        """The elements with this tag, in document order (do not change the list)."""
        return self.by_tag.get(tag, [])

    def named(self, tag: str, name: str) -> AnyElement | None:
        """The first element with this tag whose ``name`` attribute is ``name``."""
        names = self.names.get(tag)
        if names is None:
            names = self.names[tag] = {}
            for element in reversed(self.tagged(tag)):  # the first one wins
                written = _name_of(element)
                if written is not None:
                    names[written] = element
        return names.get(name)


def _name_of(element: AnyElement) -> str | None:
    """The ``name`` attribute's text, as :func:`~mjcf_model.tree.queries.find` compares it."""
    if isinstance(element, GenericElement):
        return element.attributes.get("name")
    assert isinstance(element, TypedElement)
    if "name" in element.__node_info__.table:
        value = element.__dict__.get("name")
        return value if type(value) is str else None
    return element.extra.get("name")


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
