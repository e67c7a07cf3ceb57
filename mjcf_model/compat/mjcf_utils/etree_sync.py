"""The boundary between robosuite's live ElementTree elements and the immutable nodes.

Every tree function of the compatible ``mjcf_utils`` works the same way:

1. convert the ElementTree element with :func:`node_of` (``from_etree(typed=False)``:
   generic nodes holding the exact attribute text, so text MuJoCo would
   reject still converts and comes back unchanged);
2. call a pure function on the nodes;
3. write the result back onto the *same* ElementTree elements with
   :func:`write_back`: changed attributes are set in place (an existing key keeps
   its position, a new one goes last), removed ones deleted. Elements are never
   replaced, because robosuite code keeps references to them.

Queries map the nodes they find back to the live elements with :func:`element_index`.

>>> import xml.etree.ElementTree as ET
>>> root = ET.fromstring('<body name="b"><geom name="g" size="1"/></body>')
>>> node = node_of(root)
>>> new = edited(node, {(0,): {"name": "p_g", "rgba": "1 0 0 1"}})
>>> geom = root[0]
>>> write_back(root, node, new)
>>> ET.tostring(root, encoding="unicode"), root[0] is geom
('<body name="b"><geom name="p_g" size="1" rgba="1 0 0 1" /></body>', True)
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
    "is_element",
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


def is_element(node: Node) -> bool:
    """Whether ``node`` is an element (typed or generic), not a comment.

    Example:
        >>> is_element(GenericElement(tag="geom")), is_element(Comment(text="c"))
        (True, False)

    """
    return isinstance(node, (TypedElement, GenericElement))


def attribute(node: Node, name: str) -> str | None:
    """The text of attribute ``name`` (``None``: absent, or a comment).

    A generic node holds the text as read; a typed node's value is formatted.

    Example:
        >>> from mjcf_model import Geom
        >>> attribute(GenericElement(tag="geom", attributes={"group": "1.0"}), "group")
        '1.0'
        >>> attribute(Geom(group=1), "group"), attribute(Comment(text="c"), "group")
        ('1', None)

    """
    if isinstance(node, GenericElement):
        return node.attributes.get(name)
    if isinstance(node, TypedElement):
        value = get_attribute(node, name)
        return None if value is None else format_value(value)
    return None


def node_of(element: ET.Element) -> Node:
    """The element and its subtree as generic nodes holding the exact attribute text.

    Example:
        >>> node_of(ET.fromstring('<geom group="1.0"/>')).attributes["group"]
        '1.0'

    """
    return from_etree(element, typed=False)


def shallow_node(element: ET.Element) -> Node:
    """The element alone (no children) as a node: for functions that read one element.

    Converting the subtree would make functions called once per element of a
    tree (``scale_body_element``, ``_element_filter``) quadratic.

    Example:
        >>> body = shallow_node(ET.fromstring('<body pos="0 0 1"><geom/></body>'))
        >>> body.attributes, body.children
        (AttributeMap({'pos': '0 0 1'}), ())

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
    """``(element, node)`` for the converted element and each descendant, in document order.

    Example:
        >>> root = ET.fromstring("<a><b/></a>")
        >>> root.append(ET.Comment("c"))
        >>> [(e.tag if isinstance(e.tag, str) else "#", type(n).__name__)
        ...  for e, n in paired(root, node_of(root))]
        [('a', 'GenericElement'), ('b', 'GenericElement'), ('#', 'Comment')]

    """
    stack = [(element, node)]
    while stack:
        current, current_node = stack.pop()
        yield current, current_node
        if isinstance(current_node, Element):
            pairs = zip(_children(current), current_node.children, strict=True)
            stack.extend(reversed(list(pairs)))


def element_index(element: ET.Element, node: Node) -> dict[int, ET.Element]:
    """The live element of each node, by ``id`` of the node (nodes of ``node_of(element)``).

    Example:
        >>> root = ET.fromstring("<a><b/></a>")
        >>> node = node_of(root)
        >>> element_index(root, node)[id(node.children[0])] is root[0]
        True

    """
    return {id(n): e for e, n in paired(element, node)}


def node_index(element: ET.Element, node: Node) -> dict[int, Node]:
    """The node of each live element, by ``id`` of the element (the inverse of the above).

    Example:
        >>> root = ET.fromstring("<a><b/></a>")
        >>> node = node_of(root)
        >>> node_index(root, node)[id(root[0])] is node.children[0]
        True

    """
    return {id(e): n for e, n in paired(element, node)}


def preorder(node: Node) -> Iterator[tuple[AnyElement | None, Node, Path]]:
    """``(parent, node, path)`` for ``node`` and every descendant, comments too, in document order.

    ``path`` indexes ``children`` from ``node`` down; the parent of ``node`` is ``None``.

    Example:
        >>> root = ET.fromstring("<a><b><c/></b></a>")
        >>> root.append(ET.Comment("x"))
        >>> tree = node_of(root)
        >>> [(p.tag if p else None, getattr(n, "tag", "#"), path) for p, n, path in preorder(tree)]
        [(None, 'a', ()), ('a', 'b', (0,)), ('b', 'c', (0, 0)), ('a', '#', (1,))]

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
    """A copy of ``node`` with attribute ``edits`` applied by path, sharing unchanged subtrees.

    Example:
        >>> tree = node_of(ET.fromstring('<a><b x="1"/><c/></a>'))
        >>> new = edited(tree, {(0,): {"x": None, "y": "2"}})
        >>> new.children[0].attributes, new.children[1] is tree.children[1]
        (AttributeMap({'y': '2'}), True)
        >>> edited(tree, {}) is tree
        True

    """
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

    ``element.set`` keeps an existing attribute where it stands and puts a new
    one last, as robosuite's own ``set`` calls do.

    Example:
        >>> geom = ET.fromstring('<geom a="1" b="2"/>')
        >>> write_attributes(geom, GenericElement(tag="geom", attributes={"a": "3", "c": "4"}))
        >>> geom.attrib
        {'a': '3', 'c': '4'}

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

    Subtrees that ``new`` shares with ``old`` are skipped. The structure must be
    the same: the compatible functions only change attributes.

    Example:
        >>> root = ET.fromstring('<a><b x="1"/></a>')
        >>> old = node_of(root)
        >>> write_back(root, old, edited(old, {(0,): {"x": "2"}}))
        >>> root[0].get("x")
        '2'

    """
    stack: list[tuple[ET.Element, Node, Node]] = [(element, old, new)]
    while stack:
        current, before, after = stack.pop()
        if after is before:
            continue
        write_attributes(current, after)
        if isinstance(before, Element) and isinstance(after, Element):
            stack.extend(zip(_children(current), before.children, after.children, strict=True))
