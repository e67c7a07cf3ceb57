"""robosuite's ``add_prefix``: prefixing by attribute name, with its quirks, over nodes."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable, Collection, Iterable
from typing import Any

from mjcf_model.compat.mjcf_utils.constants import MUJOCO_NAMED_ATTRIBUTES
from mjcf_model.nodes.base import Element, GenericElement, Node, TypedElement, attribute_items
from mjcf_model.serializers.etree import from_etree
from mjcf_model.serializers.etree_view import element_index, write_back
from mjcf_model.tree.paths import edited_at
from mjcf_model.tree.traversal import walk_nodes

__all__ = ["add_prefix"]

#: ``exclude(node_or_value)``: whether to leave an element (or one attribute value) alone.
NodeExclude = Callable[[Node | str], bool]


def already_prefixed(value: str, prefix: str) -> bool:
    """Whether robosuite leaves ``value`` alone when prefixing: it starts with ``prefix``."""
    return value.startswith(prefix)


def _texts(node: Node) -> dict[str, str]:
    """The attributes of ``node`` that are text (all of a generic node's), as a plain dict."""
    if isinstance(node, GenericElement):
        return dict(node.attributes)
    if isinstance(node, TypedElement):
        return {k: v for k, v in attribute_items(node) if isinstance(v, str)}
    return {}


def prefixed_attributes(
    node: Node,
    prefix: str,
    tags: Collection[str] | None,
    attribs: Iterable[str],
    exclude: NodeExclude | None = None,
) -> Node:
    """``node`` with ``prefix`` put before the values of ``attribs``, as ``add_prefix`` does.

    ``tags`` ``None`` means every element; ``exclude`` is called with nodes and values
    in robosuite's order.
    """
    edits: dict[tuple[int, ...], dict[str, str | None]] = {}
    for _parent, current, path in walk_nodes(node):
        if tags is not None and not (isinstance(current, Element) and current.tag in tags):
            continue
        if exclude is not None and exclude(current):
            continue
        changes: dict[str, str | None] = {}
        present = _texts(current)
        for name in attribs:
            value = present.get(name)
            if (
                value is not None
                and not already_prefixed(value, prefix)
                and (exclude is None or not exclude(value))
            ):
                changes[name] = prefix + value
        if changes:
            edits[path] = changes
    return edited_at(node, edits)


def add_prefix(
    root: ET.Element,
    prefix: str,
    tags: Any = "default",
    attribs: Any = "default",
    exclude: Callable[[Any], Any] | None = None,
) -> None:
    """Prefix the name attributes of ``root`` and everything below it, in place.

    robosuite's rules, kept: an attribute is prefixed when its *name* is in
    ``attribs`` (default :data:`MUJOCO_NAMED_ATTRIBUTES`), on any element, unless
    its value already starts with ``prefix``; ``exclude`` gets live elements
    (comments too) and values, and excluding an element spares only its own
    attributes. Unlike robosuite, ``exclude`` sees the tree as it was before the
    call, and an exception from it leaves the tree unchanged.

    Examples:
        >>> body = ET.fromstring('<body name="b"><geom name="floor"/><geom name="g"/></body>')
        >>> add_prefix(body, "p_", tags="geom", exclude=lambda x: x == "floor")
        >>> [e.get("name") for e in body.iter()]
        ['b', 'floor', 'p_g']

    """
    if tags != "default":
        tags = {tags} if type(tags) is str else set(tags)
    if attribs == "default":
        attribs = MUJOCO_NAMED_ATTRIBUTES
    attribs = {attribs} if type(attribs) is str else set(attribs)

    node = from_etree(root, typed=False)
    node_exclude: NodeExclude | None = None
    if exclude is not None:
        live = element_index(root, node)
        callback = exclude

        def node_exclude(item: Node | str) -> bool:
            return bool(callback(item if isinstance(item, str) else live[id(item)]))

    new = prefixed_attributes(
        node, prefix, None if tags == "default" else tags, attribs, node_exclude
    )
    write_back(root, node, new)
