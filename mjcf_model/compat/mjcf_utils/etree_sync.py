"""The boundary between robosuite's live ElementTree elements and the immutable nodes.

Tree functions convert with :func:`node_of`, call a pure function on the nodes, and
write the result onto the *same* elements with :func:`serializers.etree_view.write_back`
(never replacing one).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterator

from mjcf_model.nodes.base import (
    AnyElement,
    Comment,
    Element,
    GenericElement,
    Node,
    TypedElement,
    get_attribute,
)
from mjcf_model.tree.traversal import Path
from mjcf_model.values import format_value
from serializers.etree import converted_children, from_etree

__all__ = [
    "attribute",
    "element_index",
    "node_of",
    "paired",
    "preorder",
    "shallow_node",
]


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


def paired(element: ET.Element, node: Node) -> Iterator[tuple[ET.Element, Node]]:
    """``(element, node)`` for the converted element and each descendant, in document order."""
    stack = [(element, node)]
    while stack:
        current, current_node = stack.pop()
        yield current, current_node
        if isinstance(current_node, Element):
            pairs = zip(converted_children(current), current_node.children, strict=True)
            stack.extend(reversed(list(pairs)))


def element_index(element: ET.Element, node: Node) -> dict[int, ET.Element]:
    """The live element of each node of ``node_of(element)``, by ``id`` of the node."""
    return {id(n): e for e, n in paired(element, node)}


def preorder(node: Node) -> Iterator[tuple[AnyElement | None, Node, Path]]:
    """``(parent, node, path)`` for ``node`` and its descendants (comments too), in document order.

    ``path`` indexes ``children`` from ``node`` down; the parent of ``node`` is ``None``.
    """
    stack: list[tuple[AnyElement | None, Node, Path]] = [(None, node, ())]
    while stack:
        parent, current, path = stack.pop()
        yield parent, current, path
        if isinstance(current, Element):
            stack.extend(
                (current, child, (*path, index))
                for index, child in reversed(list(enumerate(current.children)))
            )
