"""robosuite's ``add_prefix``: prefixing by attribute name, with its quirks.

robosuite does not know namespaces: it prefixes every attribute whose *name* is
in :data:`MUJOCO_NAMED_ATTRIBUTES` (or the ``attribs`` given), on every element,
unless the value already starts with the prefix. The library's
:func:`mjcf_model.prefixed` follows the namespace table instead (``refname``,
``site1``, ``objname`` by ``objtype``...) and prefixes every name exactly once,
so it gives different text; these quirks live here only, in
:func:`prefixed_attributes`, a pure function on nodes. The rule both share
with robosuite, that a value already starting with the prefix is left alone,
is :func:`already_prefixed`; the object classes use it with the namespace
table instead of the attribute list
(:func:`~mjcf_model.compat.objects.habits.robosuite_prefixed`), on purpose: there,
references robosuite's list misses are prefixed too, so MuJoCo finds them.

>>> import xml.etree.ElementTree as ET
>>> body = ET.fromstring('<body name="b"><geom name="g" mesh="p_mesh"/></body>')
>>> add_prefix(body, "p_")
>>> ET.tostring(body, encoding="unicode")
'<body name="p_b"><geom name="p_g" mesh="p_mesh" /></body>'
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable, Collection, Iterable
from typing import Any

from mjcf_model.compat.mjcf_utils.constants import MUJOCO_NAMED_ATTRIBUTES
from mjcf_model.compat.mjcf_utils.etree_sync import (
    edited,
    element_index,
    node_of,
    preorder,
    write_back,
)
from mjcf_model.nodes.base import GenericElement, Node, TypedElement, attribute_items

__all__ = ["add_prefix", "already_prefixed", "prefixed_attributes"]

#: ``exclude(node_or_value)``: whether to leave an element (or one attribute value) alone.
NodeExclude = Callable[[Node | str], bool]


def already_prefixed(value: str, prefix: str) -> bool:
    """Whether robosuite leaves ``value`` alone when prefixing: it already starts with ``prefix``.

    ``add_prefix``, ``add_material`` and the object classes all skip such names,
    so a mesh ``can_mesh`` of object ``can`` stays ``can_mesh``.

    Example:
        >>> already_prefixed("can_mesh", "can_"), already_prefixed("mesh", "can_")
        (True, False)

    """
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
    """``node`` with ``prefix`` put before the values of ``attribs``, robosuite's way.

    Elements are visited in document order (``node`` first; comments too, as
    robosuite's loop visits them). An element is considered when ``tags`` is
    ``None`` or holds its tag, and ``exclude(element)`` is not true; then each
    attribute of ``attribs`` it has gets the prefix unless the value already
    starts with ``prefix`` or ``exclude(value)`` is true. Excluding an element
    does not exclude its children. ``exclude`` is called as robosuite calls
    it: with the element, then with each value it would prefix (in the
    iteration order of ``attribs``).

    Args:
        node: The tree, as generic nodes
            (see :func:`~mjcf_model.compat.mjcf_utils.etree_sync.node_of`).
        prefix: The prefix.
        tags: The tags to prefix, or ``None`` for every element.
        attribs: The attribute names whose values get the prefix.
        exclude: Called with elements (nodes) and attribute values (strings).

    Example:
        >>> from mjcf_model import GenericElement
        >>> geom = GenericElement(tag="geom", attributes={"name": "pp", "material": "m"})
        >>> prefixed_attributes(geom, "p", None, ["name", "material"]).attributes
        AttributeMap({'name': 'pp', 'material': 'pm'})

    """
    edits: dict[tuple[int, ...], dict[str, str | None]] = {}
    for _parent, current, path in preorder(node):
        if tags is not None and not (
            isinstance(current, (TypedElement, GenericElement)) and current.tag in tags
        ):
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
    return edited(node, edits)


def add_prefix(
    root: ET.Element,
    prefix: str,
    tags: Any = "default",
    attribs: Any = "default",
    exclude: Callable[[Any], Any] | None = None,
) -> None:
    """Prefix the name attributes of ``root`` and everything below it, in place.

    robosuite's rules, kept: an attribute is prefixed when its *name* is in
    ``attribs`` (by default :data:`MUJOCO_NAMED_ATTRIBUTES`, which prefixes
    ``class``/``childclass`` references but not ``refname``, ``refsite``,
    ``site1``...), on any element, unless its value already starts with
    ``prefix`` (so a mesh ``can_mesh`` in object ``can`` stays ``can_mesh``).
    Applying it twice changes nothing more. ``exclude`` is called with
    ElementTree elements (the live ones, comments included) and with attribute
    values; excluding an element leaves its own attributes alone, not its
    children's. Attributes change in place (``set`` keeps their position).

    Unlike robosuite, an exception from ``exclude`` leaves the tree unchanged,
    and ``exclude`` sees the tree as it was before the call (robosuite has
    already prefixed the elements before the one it asks about).

    Args:
        root: The element to start from.
        prefix: The prefix.
        tags: ``"default"`` for every element, else a tag or a collection of tags.
        attribs: ``"default"`` for :data:`MUJOCO_NAMED_ATTRIBUTES`, else an
            attribute name or a collection of names.
        exclude: ``None`` or ``exclude(element_or_value) -> bool``.

    Example:
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

    node = node_of(root)
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
