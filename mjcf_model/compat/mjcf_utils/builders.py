"""robosuite's element constructors (``new_element``, ``new_geom``...) and their node builders.

Each node builder writes robosuite's order (keyword arguments, then the named
parameters, then ``name``) with a text rule, its first argument:
:func:`convert_to_string` for the ElementTree constructors here, robosuite's object
habit (:func:`mjcf_model.compat.objects.habits.value_text`), or ``None`` for the typed
nodes of :mod:`mjcf_model.compat.typed_builders`.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable, Iterable
from typing import Any, TypeVar

import attrs

from mjcf_model.compat.mjcf_utils.constants import RED
from mjcf_model.compat.mjcf_utils.text import convert_to_string
from mjcf_model.nodes.base import (
    AnyElement,
    AttributeMap,
    GenericElement,
    TypedElement,
    build_node,
    field_table,
    with_attributes,
)
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema.namespaces import child_key, guess_context
from mjcf_model.serializers.etree import to_etree
from mjcf_model.values import Value, format_value, plain_value, to_str

__all__ = [
    "new_actuator",
    "new_body",
    "new_element",
    "new_geom",
    "new_inertial",
    "new_joint",
    "new_site",
]

#: How a builder writes a value as attribute text; ``None``: a typed node keeps numbers.
TextRule = Callable[[Any], str] | None
#: Keyword arguments that stand for another MJCF attribute (``class`` is a Python keyword).
_KEYWORD_ATTRIBUTES = {"dclass": "class"}


_T = TypeVar("_T", bound=TypedElement)


def ordered_node(cls: type[_T], items: Iterable[tuple[str, Any]]) -> _T:
    """A ``cls`` node with MJCF attributes ``items``, written in that order.

    Text fields given a number hold its text; numpy values become plain ones.

    Examples:
        >>> from mjcf_model import Site
        >>> site = ordered_node(Site, [("size", [0.1]), ("name", "s")])
        >>> site.size, site.attribute_order
        ((0.1,), ('size', 'name'))

    """
    table, converters = field_table(cls), cls.__node_info__.converters
    changes: dict[str, Value] = {}
    for name, value in items:
        value = plain_value(value)
        if converters.get(table.get(name, "")) is to_str and not isinstance(value, str):
            value = format_value(value)
        changes[name] = value
    element = with_attributes(cls(), changes)
    return attrs.evolve(element, attribute_order=tuple(changes))


def element_node(
    tag: str, attributes: Iterable[tuple[str, Any]], text: TextRule = convert_to_string
) -> AnyElement:
    """A node with ``attributes`` in order, ``None`` values dropped, written by ``text``.

    With ``text=None`` the node is typed where ``tag`` has a class in its likely
    context (values converted; ``dclass`` stands for ``class``), else generic.
    """
    if text is None:
        items = [(_KEYWORD_ATTRIBUTES.get(k, k), v) for k, v in attributes if v is not None]
        key = child_key(guess_context(tag), tag)
        cls = CLASS_BY_KEY.get(key) if key is not None else None
        if cls is not None:
            return ordered_node(cls, items)
        return with_attributes(GenericElement(tag=tag), {k: plain_value(v) for k, v in items})
    values = {key: text(value) for key, value in attributes if value is not None}
    # Unchecked, as robosuite's ElementTree takes text XML cannot carry.
    return build_node(GenericElement, {"tag": tag, "attributes": AttributeMap.unchecked(values)})


def joint_node(text: TextRule, name: str | None = None, **kwargs: Any) -> AnyElement:
    """The node of ``new_joint``: ``kwargs``, then ``name``, written by ``text``."""
    return element_node("joint", [*kwargs.items(), ("name", name)], text)


def site_node(
    text: TextRule,
    name: str | None = None,
    rgba: Any = RED,
    pos: Any = (0, 0, 0),
    size: Any = (0.005,),
    **kwargs: Any,
) -> AnyElement:
    """The node of ``new_site``: ``kwargs``, ``pos``, ``size``, ``rgba``, ``name``."""
    named = [("pos", pos), ("size", size), ("rgba", rgba), ("name", name)]
    return element_node("site", [*kwargs.items(), *named], text)


def geom_node(
    text: TextRule,
    name: str | None,
    type: Any,
    size: Any,
    pos: Any = (0, 0, 0),
    group: Any = 0,
    **kwargs: Any,
) -> AnyElement:
    """The node of ``new_geom``: ``kwargs``, ``type``, ``size``, ``pos``, ``group``, ``name``.

    Examples:
        >>> geom_node(None, "g", "box", [0.5, 0, 1]).size
        (0.5, 0.0, 1.0)

    """
    named = [("type", type), ("size", size), ("pos", pos), ("group", group), ("name", name)]
    return element_node("geom", [*kwargs.items(), *named], text)


def body_node(
    text: TextRule, name: str | None = None, pos: Any = (0, 0, 0), **kwargs: Any
) -> AnyElement:
    """The node of ``new_body``: ``kwargs``, ``pos``, ``name``."""
    return element_node("body", [*kwargs.items(), ("pos", pos), ("name", name)], text)


def inertial_node(
    text: TextRule, pos: Any = (0, 0, 0), mass: Any = None, **kwargs: Any
) -> AnyElement:
    """The node of ``new_inertial``: ``kwargs``, ``mass``, ``pos`` (no name)."""
    return element_node("inertial", [*kwargs.items(), ("mass", mass), ("pos", pos)], text)


def new_element(tag: str, name: str | None, **kwargs: Any) -> ET.Element:
    """A new element: ``kwargs`` as attributes (``None`` dropped), then ``name`` unless ``None``.

    Raises:
        ValueError: A value ``convert_to_string`` refuses (numpy scalars, ``dict``...).

    Examples:
        >>> body = new_element("body", None, pos=[0, 0, 1], quat=None, mass=0.5, flag=True)
        >>> ET.tostring(body, encoding="unicode")
        '<body pos="0 0 1" mass="0.5" flag="true" />'

    """
    return to_etree(element_node(tag, [*kwargs.items(), ("name", name)]))


def new_joint(name: str | None, **kwargs: Any) -> ET.Element:
    """A new ``<joint>``: ``kwargs``, then ``name``.

    Examples:
        >>> ET.tostring(new_joint("j", type="free", damping="0.0005"), encoding="unicode")
        '<joint type="free" damping="0.0005" name="j" />'

    """
    return to_etree(joint_node(convert_to_string, name, **kwargs))


def new_actuator(
    name: str | None, joint: Any, act_type: str = "actuator", **kwargs: Any
) -> ET.Element:
    """A new actuator of tag ``act_type``: ``kwargs``, ``name``, then ``joint`` as given.

    Examples:
        >>> actuator = new_actuator(joint="gz", act_type="position", name="a", kp="500")
        >>> ET.tostring(actuator, encoding="unicode")
        '<position kp="500" name="a" joint="gz" />'

    """
    element = new_element(tag=act_type, name=name, **kwargs)
    element.set("joint", joint)
    return element


def new_site(
    name: str | None,
    rgba: Any = RED,
    pos: Any = (0, 0, 0),
    size: Any = (0.005,),
    **kwargs: Any,
) -> ET.Element:
    """A new ``<site>`` (a small red sphere): ``kwargs``, ``pos``, ``size``, ``rgba``, ``name``.

    Examples:
        >>> ET.tostring(new_site("s"), encoding="unicode")
        '<site pos="0 0 0" size="0.005" rgba="1 0 0 1" name="s" />'

    """
    return to_etree(site_node(convert_to_string, name, rgba, pos, size, **kwargs))


def new_geom(
    name: str | None,
    type: Any,
    size: Any,
    pos: Any = (0, 0, 0),
    group: Any = 0,
    **kwargs: Any,
) -> ET.Element:
    """A new ``<geom>``: ``kwargs``, ``type``, ``size``, ``pos``, ``group``, ``name``.

    Examples:
        >>> geom = new_geom("g", "sphere", [0.1], group=None, rgba=None, material="m")
        >>> ET.tostring(geom, encoding="unicode")
        '<geom material="m" type="sphere" size="0.1" pos="0 0 0" name="g" />'

    """
    return to_etree(geom_node(convert_to_string, name, type, size, pos, group, **kwargs))


def new_body(name: str | None, pos: Any = (0, 0, 0), **kwargs: Any) -> ET.Element:
    """A new ``<body>``: ``kwargs``, ``pos``, ``name``.

    Examples:
        >>> ET.tostring(new_body("b"), encoding="unicode")
        '<body pos="0 0 0" name="b" />'

    """
    return to_etree(body_node(convert_to_string, name, pos, **kwargs))


def new_inertial(pos: Any = (0, 0, 0), mass: Any = None, **kwargs: Any) -> ET.Element:
    """A new ``<inertial>``: ``kwargs``, then ``mass`` (if given), then ``pos``; no name.

    Examples:
        >>> ET.tostring(new_inertial(mass=1.0, diaginertia=[1, 1, 1]), encoding="unicode")
        '<inertial diaginertia="1 1 1" mass="1.0" pos="0 0 0" />'

    """
    return to_etree(inertial_node(convert_to_string, pos, mass, **kwargs))
