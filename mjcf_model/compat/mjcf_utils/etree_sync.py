"""The boundary between robosuite's live ElementTree elements and the immutable nodes.

Tree functions convert with :func:`node_of`, call a pure function on the nodes, and
write the result onto the *same* elements with :func:`write_back` (never replacing one).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterator, Mapping

from mjcf_model.nodes.base import (
    AnyElement,
    Comment,
    Element,
    GenericElement,
    Node,
    TypedElement,
    get_attribute,
)
from mjcf_model.nodes.base import with_attributes as _with_attributes
from mjcf_model.tree.traversal import Path, with_children
from mjcf_model.values import format_value
from serializers import from_etree

__all__ = [
    "Edits",
    "attribute",
    "edited",
    "element_index",
    "node_index",
    "node_of",
    "paired",
    "preorder",
    "shallow_node",
    "write_attributes",
    "write_back",
]

#: Attribute changes by element path (``None`` removes an attribute).
Edits = Mapping[Path, Mapping[str, str | None]]


def attribute(node: Node, name: str) -> str | None:
    """The text of attribute ``name`` (``None``: absent, or a comment); a typed value formatted."""
    if isinstance(node, GenericElement):
        return node.attributes.get(name)
    if isinstance(node, TypedElement):
        value = get_attribute(node, name)
        return None if value is None else format_value(value)
    return None


def node_of(element: ET.Element) -> Node:
    """The element and its subtree as generic nodes holding the exact attribute text."""
    return from_etree(element, typed=False)


def shallow_node(element: ET.Element) -> Node:
    """The element alone (no children) as a node.

    For functions called once per element of a tree, which converting subtrees would make quadratic.
    """
    if element.tag is ET.Comment:  # type: ignore[comparison-overlap]
        return Comment(text=element.text or "")
    return GenericElement(tag=element.tag, attributes=element.attrib)


def _children(element: ET.Element) -> list[ET.Element]:
    """The children ``from_etree`` converts (elements and comments), in order."""
    return [
        child
        for child in element
        if child.tag is ET.Comment or isinstance(child.tag, str)  # type: ignore[comparison-overlap]
    ]


def paired(element: ET.Element, node: Node) -> Iterator[tuple[ET.Element, Node]]:
    """``(element, node)`` for the converted element and each descendant, in document order."""
    stack = [(element, node)]
    while stack:
        current, current_node = stack.pop()
        yield current, current_node
        if isinstance(current_node, Element):
            pairs = zip(_children(current), current_node.children, strict=True)
            stack.extend(reversed(list(pairs)))


def element_index(element: ET.Element, node: Node) -> dict[int, ET.Element]:
    """The live element of each node of ``node_of(element)``, by ``id`` of the node."""
    return {id(n): e for e, n in paired(element, node)}


def node_index(element: ET.Element, node: Node) -> dict[int, Node]:
    """The node of each live element, by ``id`` of the element (inverse of ``element_index``)."""
    return {id(e): n for e, n in paired(element, node)}


def preorder(node: Node) -> Iterator[tuple[AnyElement | None, Node, Path]]:
    """``(parent, node, path)`` for ``node`` and its descendants (comments too), in document order.

    ``path`` indexes ``children`` from ``node`` down; the parent of ``node`` is ``None``.
    """
    stack: list[tuple[AnyElement | None, Node, Path]] = [(None, node, ())]
    while stack:
        parent, current, path = stack.pop()
        yield parent, current, path
        if isinstance(current, (TypedElement, GenericElement)):
            stack.extend(
                (current, child, (*path, index))
                for index, child in reversed(list(enumerate(current.children)))
            )


def edited(node: Node, edits: Edits) -> Node:
    """A copy of ``node`` with attribute ``edits`` applied by path, sharing unchanged subtrees."""
    if not edits:
        return node
    touched = {path[:depth] for path in edits for depth in range(len(path) + 1)}

    def rebuild(current: Node, path: Path) -> Node:
        if path not in touched:
            return current
        if isinstance(current, (TypedElement, GenericElement)):
            if current.children:
                children = [rebuild(c, (*path, i)) for i, c in enumerate(current.children)]
                current = with_children(current, children)
            changes = edits.get(path)
            if changes:
                current = _with_attributes(current, changes)
        return current

    return rebuild(node, ())


def write_attributes(element: ET.Element, node: Node) -> None:
    """Make ``element``'s attributes those of ``node``: set changed ones, delete removed ones.

    ``set`` keeps an existing attribute in place and puts a new one last, as robosuite's does.
    """
    if not isinstance(node, GenericElement):
        return
    new = node.attributes
    for key in [key for key in element.attrib if key not in new]:
        del element.attrib[key]
    for key, value in new.items():
        if element.get(key) != value:
            element.set(key, value)


def write_back(element: ET.Element, old: Node, new: Node) -> None:
    """Write the changes from ``old`` (``node_of(element)``) to ``new`` onto the live elements.

    Subtrees ``new`` shares with ``old`` are skipped; only attributes may differ.
    """
    stack: list[tuple[ET.Element, Node, Node]] = [(element, old, new)]
    while stack:
        current, before, after = stack.pop()
        if after is before:
            continue
        write_attributes(current, after)
        if isinstance(before, Element) and isinstance(after, Element):
            stack.extend(zip(_children(current), before.children, after.children, strict=True))
