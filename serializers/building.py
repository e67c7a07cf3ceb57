"""Turning one parsed element (tag, attributes, children) into a node.

Both readers, the text reader and :func:`serializers.from_etree`, hand every
element to :func:`build_element`, so the two cannot disagree.

>>> node = build_element("body/geom", "geom", [("name", "g"), ("size", "0.1")], [], None)
>>> node.name, node.size
('g', (0.1,))
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from mjcf_model.base import (
    AnyElement,
    GenericElement,
    Node,
    TypedElement,
    build_node,
    field_table,
)
from mjcf_model.errors import MjcfValueError
from mjcf_model.registry import CLASS_BY_KEY

__all__ = ["build_element", "element_step", "element_text"]


def element_text(chunks: Sequence[str | None], has_children: bool) -> str | None:
    r"""The text an element keeps from its character data chunks.

    An element with only text keeps it exactly (``<text>`` content). Where text
    stands between child elements (mixed content, which MuJoCo ignores), each
    chunk is stripped and the non-blank ones are joined by a space, so that
    re-indenting on write does not change the text. White space alone is ``None``.

    Example:
        >>> element_text(["  a b "], False), element_text(["\n  ", " > ", "\n"], True)
        ('  a b ', '>')

    """
    if has_children:
        joined = " ".join(c.strip() for c in chunks if c and c.strip())
        return joined or None
    text = "".join(c for c in chunks if c)
    return text if text.strip() else None


def element_step(tag: str, attributes: Sequence[tuple[str, str]], index: int) -> str:
    """One step of an element path: ``body[@name='arm']`` or ``geom[3]`` (1-based).

    Example:
        >>> element_step("body", [("name", "arm")], 1), element_step("geom", [], 3)
        ("body[@name='arm']", 'geom[3]')

    """
    for key, value in attributes:
        if key == "name":
            return f"{tag}[@name={value!r}]"
    return tag if index == 1 else f"{tag}[{index}]"


def build_element(
    key: str | None,
    tag: str,
    attributes: Sequence[tuple[str, str]],
    children: Sequence[Node],
    text: str | None,
) -> AnyElement:
    """Build the node for one element from its parsed parts.

    Args:
        key: The element's schema key (see :func:`mjcf_model.namespaces.child_key`).
        tag: The XML tag.
        attributes: ``(name, text)`` pairs in source order.
        children: The already built child nodes.
        text: Character data, or ``None`` when there is none but white space.

    Raises:
        MjcfValueError: An attribute value does not fit its field; the message
            names the attribute (the caller adds file, line and path).

    """
    cls = CLASS_BY_KEY.get(key) if key is not None else None
    if cls is None or cls.tag != tag:
        return GenericElement(tag=tag, attributes=attributes, children=children, text=text)
    table = field_table(cls)
    fields: dict[str, Any] = {}
    extra: list[tuple[str, str]] = []
    for name, value in attributes:
        field = table.get(name)
        if field is None:
            extra.append((name, value))
        else:
            fields[field] = value
    fields["attribute_order"] = tuple(name for name, _ in attributes)
    if extra:
        fields["extra"] = extra
    if children:
        fields["children"] = children
    if text is not None:
        fields["text"] = text
    try:
        return build_node(cls, fields)
    except MjcfValueError:
        raise _blame_attribute(cls, table, attributes) from None


def _blame_attribute(
    cls: type[TypedElement], table: dict[str, str], attributes: Sequence[tuple[str, str]]
) -> MjcfValueError:
    """Find the attribute whose value the class rejects (only on the error path)."""
    for name, value in attributes:
        field = table.get(name)
        if field is None:
            continue
        single: dict[str, Any] = {field: value}
        try:
            cls(**single)
        except MjcfValueError as error:
            return MjcfValueError(f"attribute {name!r}: {error.detail}")
    return MjcfValueError(f"<{cls.tag}> rejects the combination of its attributes")
