"""A live ElementTree view of an immutable model.

Code written for ElementTree (robosuite's, and any other) holds on to elements and edits
them. :class:`EtreeView` gives such code one ElementTree for the model's whole life: when
the model is replaced by a changed copy, the view edits the same elements in place (an
attribute set where it stands, a child added or removed), builds elements only for what
is new, and keeps what other code added to the elements.

>>> from mjcf_model import Body, Geom, with_attributes
>>> body = Body(name="arm", children=[Geom(name="g", size=[0.1])])
>>> view = EtreeView(body)
>>> geom = view.at((0,))
>>> view.update(with_attributes(body, name="forearm"))
>>> view.element.get("name"), view.at((0,)) is geom
('forearm', True)
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterator

from mjcf_model.nodes.base import AnyElement, Comment, Element, GenericElement, Node
from mjcf_model.serializers.canonical import attribute_texts
from mjcf_model.serializers.etree import converted_children, to_etree
from mjcf_model.tree.traversal import Path

__all__ = ["EtreeView", "element_index", "paired", "shallow_node", "sync_element", "write_back"]


class EtreeView:
    """One ElementTree kept showing a model that is replaced by changed copies.

    Args:
        node: The model (any element and its subtree).
        element: An ElementTree element that already shows ``node`` (robosuite's own,
            say), to keep; by default one is built from ``node`` on first use.

    """

    def __init__(self, node: AnyElement, element: ET.Element | None = None) -> None:
        self._node = node
        #: The elements built for each element's children, in model order.
        self._kids: dict[ET.Element, list[ET.Element]] = {}
        #: The root element, built on first use (a model changed often is converted once).
        self._element = None if element is None else self._record(node, element)

    @property
    def node(self) -> AnyElement:
        """The model the ElementTree currently shows."""
        return self._node

    @property
    def element(self) -> ET.Element:
        """The root ElementTree element (the same object for the view's whole life)."""
        if self._element is None:
            self._element = self._build(self._node)
        return self._element

    def at(self, path: Path) -> ET.Element:
        """The element built for the model element at ``path``."""
        element = self.element
        for index in path:
            element = self._kids[element][index]
        return element

    def update(self, node: AnyElement) -> None:
        """Make the ElementTree show ``node``, editing the existing elements in place."""
        if node is not self._node:
            if self._element is not None:
                self._patch(self._node, node, self._element)
            self._node = node

    def _build(self, node: Node) -> ET.Element:
        """The element of ``node`` and its subtree, its children recorded."""
        element = to_etree(node)
        if isinstance(node, Element):
            self._record(node, element)
        return element

    def _record(self, node: AnyElement, element: ET.Element) -> ET.Element:
        """Record the elements built for ``node``'s subtree (a stack: any depth)."""
        pending = [(node, element)]
        while pending:
            parent, built = pending.pop()
            kids = self._kids[built] = converted_children(built)
            pending.extend(
                (child, kid)
                for child, kid in zip(parent.children, kids, strict=True)
                if isinstance(child, Element)
            )
        return element

    def _forget(self, element: ET.Element) -> None:
        pending = [element]
        while pending:
            pending.extend(self._kids.pop(pending.pop(), []))

    def _patch(self, old: AnyElement, new: AnyElement, element: ET.Element) -> None:
        """Make ``element`` show ``new`` instead of ``old`` (a stack: any depth)."""
        pending = [(old, new, element)]
        while pending:
            old, new, element = pending.pop()
            if old is new:
                continue
            sync_element(element, old, new)
            if old.children is not new.children:
                pending.extend(self._patch_children(old, new, element))

    def _patch_children(
        self, old: AnyElement, new: AnyElement, element: ET.Element
    ) -> list[tuple[AnyElement, AnyElement, ET.Element]]:
        """Patch the children of ``element``; the changed children left to patch are returned."""
        kids = self._kids.get(element, [])
        pairs = list(zip(old.children, new.children, strict=False))
        if len(old.children) == len(new.children) and all(
            _same_tag(a, b) for a, b in pairs
        ):  # the same elements, some of them changed
            return [
                (a, b, kid)
                for (a, b), kid in zip(pairs, kids, strict=True)
                if a is not b and isinstance(a, Element) and isinstance(b, Element)
            ]
        # Elements came or went: keep the elements of unchanged children, build the others.
        by_identity = {id(child): index for index, child in enumerate(old.children)}
        used: set[int] = set()
        new_kids: list[ET.Element] = []
        for child in new.children:
            index = by_identity.get(id(child))
            if index is not None and index not in used:
                used.add(index)
                new_kids.append(kids[index])
            else:
                new_kids.append(self._build(child))
        dropped = [kid for index, kid in enumerate(kids) if index not in used]
        live = list(element)
        if len(live) == len(kids) and all(a is b for a, b in zip(live, kids, strict=True)):
            element[:] = new_kids
        else:  # someone else edited the children: keep their edits, apply ours
            kept = {id(kid) for kid in kids}
            for kid in dropped:
                if any(kid is e for e in live):
                    element.remove(kid)
            for kid in new_kids:
                if id(kid) not in kept:
                    element.append(kid)
        for kid in dropped:
            self._forget(kid)
        self._kids[element] = new_kids
        return []


def _same_tag(a: Node, b: Node) -> bool:
    if isinstance(a, Comment) or isinstance(b, Comment):
        return isinstance(a, Comment) and isinstance(b, Comment)
    assert isinstance(a, Element) and isinstance(b, Element)
    return a.tag == b.tag


def sync_element(element: ET.Element, old: Node, new: Node) -> None:
    """Make ``element``, which shows ``old``, show ``new``'s attributes and text, in place.

    A changed attribute is set where it stands and a new one goes last (as ``set``
    does), a removed one is deleted; attributes other code added to the live
    element stay, after the model's own.
    """
    if new is old or not isinstance(new, Element):
        return
    before = attribute_texts(old) if isinstance(old, Element) else []
    after = attribute_texts(new)
    if before != after:
        _sync_attributes(element, dict(before), after)
    if getattr(old, "text", None) != new.text:
        element.text = new.text


def _sync_attributes(element: ET.Element, old: dict[str, str], new: list[tuple[str, str]]) -> None:
    new_values = dict(new)
    for name in old:
        if name not in new_values:
            element.attrib.pop(name, None)
    for name, text in new:
        if old.get(name) != text:
            element.set(name, text)
    order = [name for name in element.attrib if name in new_values]
    if order != [name for name, _ in new]:  # reordered: the model's order, then the others'
        foreign = {k: v for k, v in element.attrib.items() if k not in new_values}
        mine = {name: element.attrib[name] for name, _ in new}
        element.attrib.clear()
        element.attrib.update(mine)
        element.attrib.update(foreign)


def write_back(element: ET.Element, old: Node, new: Node) -> None:
    """Make ``element``, which shows ``old``, show ``new``: an :class:`EtreeView` update.

    A comment has nothing a model could change: it is left as it is.

    Examples:
        >>> from mjcf_model import Geom
        >>> element = ET.Element("geom", {"size": "0.1"})
        >>> write_back(element, Geom(size=[0.1]), Geom(size=[0.2]))
        >>> element.get("size")
        '0.2'

    """
    if isinstance(old, Element) and isinstance(new, Element):
        EtreeView(old, element).update(new)


def shallow_node(element: ET.Element) -> Node:
    """The element alone (no children) as a generic node holding its exact attribute text.

    For code called once per element of a tree, which converting subtrees would make quadratic.

    Examples:
        >>> node = shallow_node(ET.fromstring('<geom size="0.10"><x/></geom>'))
        >>> node.tag, dict(node.attributes), node.children
        ('geom', {'size': '0.10'}, ())

    """
    if element.tag is ET.Comment:  # type: ignore[comparison-overlap]
        return Comment(text=element.text or "")
    return GenericElement(tag=element.tag, attributes=element.attrib)


def paired(element: ET.Element, node: Node) -> Iterator[tuple[ET.Element, Node]]:
    """``(element, node)`` for an element and each descendant, in document order.

    ``node`` is what :func:`~mjcf_model.serializers.etree.from_etree` made of ``element``.
    """
    stack = [(element, node)]
    while stack:
        current, current_node = stack.pop()
        yield current, current_node
        if isinstance(current_node, Element):
            pairs = zip(converted_children(current), current_node.children, strict=True)
            stack.extend(reversed(list(pairs)))


def element_index(element: ET.Element, node: Node) -> dict[int, ET.Element]:
    """The element of each node of ``node`` (made from ``element``), by ``id`` of the node.

    Examples:
        >>> from mjcf_model.serializers.etree import from_etree
        >>> element = ET.fromstring("<body><geom/></body>")
        >>> node = from_etree(element, typed=False)
        >>> element_index(element, node)[id(node.children[0])] is element[0]
        True

    """
    return {id(n): e for e, n in paired(element, node)}
