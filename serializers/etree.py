"""ElementTree and nodes: :func:`from_etree` and its mirror :func:`to_etree`.

Each element read goes through
:func:`mjcf_model.serializers.parsed_elements.build_element`, as in the text reader, so the two
readers cannot disagree.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any

import attrs

from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.nodes.base import AnyElement, Comment, Node
from mjcf_model.schema.namespaces import child_key, children_context, guess_context
from mjcf_model.serializers.canonical import attribute_texts
from mjcf_model.serializers.parsed_elements import build_element, element_step, element_text

__all__ = ["converted_children", "from_etree", "to_etree"]


def from_etree(element: ET.Element, *, context: str | None = None, typed: bool = True) -> Node:
    """Convert an ElementTree element (and its subtree) to nodes.

    Args:
        element: The element; ``<mujoco>`` gives a :class:`~mjcf_model.Mujoco`, any
            other element the node of that element.
        context: The schema key of the element's parent (``"body"``, ``"asset"``, ...).
            By default it is guessed from the tag, which is right except for tags
            that mean different things in different sections (``<joint>`` inside
            ``<equality>``): pass the context for those.
        typed: With ``False`` every element becomes a
            :class:`~mjcf_model.GenericElement` holding its attribute text exactly
            as given, so text MuJoCo would reject (``group="1.0"``) still converts.

    Examples:
        >>> import xml.etree.ElementTree as ET
        >>> from_etree(ET.fromstring('<geom size="0.1"/>')).size
        (0.1,)
        >>> from_etree(ET.fromstring('<geom group="1.0"/>'), typed=False).attributes["group"]
        '1.0'

    """
    if element.tag is ET.Comment:  # type: ignore[comparison-overlap]
        return Comment(text=element.text or "")
    if context is None:
        context = guess_context(element.tag)
    return _from_etree(element, context, typed)


def converted_children(element: ET.Element) -> list[ET.Element]:
    """The children :func:`from_etree` converts, in order: elements and comments.

    Examples:
        >>> parent = ET.Element("body")
        >>> parent.extend([ET.Comment(" c "), ET.Element("geom"), ET.ProcessingInstruction("pi")])
        >>> len(converted_children(parent)), len(parent)
        (2, 3)

    """
    return [child for child in element if _converted(child)]


def _converted(child: ET.Element) -> bool:
    """Whether :func:`from_etree` makes a node of ``child`` (not of a processing instruction)."""
    return child.tag is ET.Comment or isinstance(child.tag, str)  # type: ignore[comparison-overlap]


@attrs.define
class _EtreeFrame:
    """An ElementTree element being converted: its children are converted first."""

    element: ET.Element
    key: str | None
    #: The schema context of the element's children.
    inner: str | None
    #: This element's step in the element path, for errors.
    step: str
    pending: Any
    children: list[Node] = attrs.field(factory=list)
    chunks: list[str | None] = attrs.field(factory=list)
    counts: dict[str, int] = attrs.field(factory=dict)


def _from_etree(root: ET.Element, context: str | None, typed: bool) -> AnyElement:
    """Convert ``root`` and its subtree with an explicit stack, so any depth is converted."""

    def frame(element: ET.Element, context: str | None, index: int) -> _EtreeFrame:
        key = child_key(context, element.tag)
        step = element_step(element.tag, list(element.attrib.items()), index)
        return _EtreeFrame(
            element, key, children_context(key, context), step, iter(element), [], [element.text]
        )

    def path() -> str:
        return "".join(f"/{f.step}" for f in stack)

    stack = [frame(root, context, 1)]
    while True:
        top = stack[-1]
        for child in top.pending:
            if child.tag is ET.Comment:
                top.children.append(Comment(text=child.text or ""))
                top.chunks.append(child.tail)
            elif isinstance(child, ET.Element) and isinstance(child.tag, str):
                index = top.counts[child.tag] = top.counts.get(child.tag, 0) + 1
                stack.append(frame(child, top.inner, index))
                break
            else:
                top.chunks.append(child.tail)
        else:
            element = top.element
            try:
                node = build_element(
                    top.key if typed else None,
                    element.tag,
                    list(element.attrib.items()),
                    top.children,
                    element_text(top.chunks, bool(top.children)),
                    lambda error: error.located(path=path()),
                )
            except MjcfError as error:
                raise error.located(path=path()) from None
            stack.pop()
            if not stack:
                return node
            stack[-1].children.append(node)
            stack[-1].chunks.append(element.tail)


def to_etree(node: Node) -> ET.Element:
    """Convert a node and its subtree to ElementTree.

    Comments become ``ET.Comment`` elements; attribute order is kept.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> ET.tostring(to_etree(Body(name="b", children=[Geom(size=[1])])), encoding="unicode")
        '<body name="b"><geom size="1" /></body>'

    """
    root = _etree_element(node)
    stack = [(node, root)]  # an explicit stack, so any depth is converted
    while stack:
        parent, element = stack.pop()
        if not isinstance(parent, AnyElement):
            continue
        for child in parent.children:
            converted = _etree_element(child)
            element.append(converted)
            stack.append((child, converted))
    return root


def _etree_element(node: Node) -> ET.Element:
    """One node as an ElementTree element, without its children."""
    if isinstance(node, Comment):
        comment: ET.Element = ET.Comment(node.text)  # type: ignore[assignment]
        return comment
    if not isinstance(node, AnyElement):
        raise MjcfValueError(f"cannot convert {type(node).__name__}: not an element or a comment")
    element = ET.Element(node.tag, dict(attribute_texts(node)))
    element.text = node.text
    return element
