"""The child's default classes when :func:`mjcf_model.attach` merges it into a parent.

The child's top-level default settings become a class of their own
(``<prefix>main``), and the child's elements those settings reach name it:
bodies and frames in its world through ``childclass``, the others through
``class``.

>>> from mjcf_model import Body, Default, Geom, Motor
>>> main = Default(dclass="c_main", children=[Geom(rgba=[1, 0, 0, 1])])
>>> [node.childclass for node in classed([Body(), Body(childclass="own")], main, "body")]
['c_main', 'own']
"""

from __future__ import annotations

from collections.abc import Sequence

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    Node,
    attribute_items,
    get_attribute,
    with_attributes,
)
from mjcf_model.nodes.default import Default
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.tree.defaults import ACTUATOR_DEFAULT_TAGS

__all__ = ["classed", "merged_settings", "sets_values"]


def sets_values(default: AnyElement) -> bool:
    """Whether a top-level ``<default>`` sets anything itself (not only nested classes).

    Examples:
        >>> from mjcf_model import Geom
        >>> nested_only = Default(children=[Default(dclass="c")])
        >>> sets_values(nested_only), sets_values(Default(children=[Geom()]))
        (False, True)

    """
    return any(e.tag != "default" for e in default.elements)


def sets_classes(default: AnyElement) -> bool:
    """Whether a ``<default>`` declares nested classes."""
    return any(e.tag == "default" for e in default.elements)


def merged_settings(defaults: Sequence[AnyElement]) -> list[Node]:
    """A model's top-level defaults as one class: settings of one tag merged, later ones winning.

    MuJoCo gives a class the settings of its parent as it reads the class: what a
    later top-level section sets does not reach the classes of an earlier one, but
    it would reach them in one merged class, so such models are refused.

    Raises:
        MjcfValueError: A top-level ``<default>`` sets values after an earlier one
            declared classes.

    Examples:
        >>> from mjcf_model import Geom
        >>> merged_settings([Default(children=[Geom(rgba=[1, 0, 0, 1])]),
        ...                  Default(children=[Geom(size=[1])])])
        [Geom(size=(1.0,), rgba=(1.0, 0.0, 0.0, 1.0))]

    """
    nodes: list[Node] = []
    for index, section in enumerate(defaults):
        if index and sets_values(section) and any(sets_classes(d) for d in defaults[:index]):
            raise MjcfValueError(
                f"top-level <default> number {index + 1} sets values after an earlier one "
                "declared classes: MuJoCo does not give those classes the later values, and "
                "merged into one class they would get them; move the settings into the first "
                "top-level <default>, or into the classes that should have them"
            )
        nodes.extend(section.children)
    merged: list[Node] = []
    first: dict[str, int] = {}
    for node in nodes:
        tag = getattr(node, "tag", None)
        if not isinstance(tag, str) or tag == "default":
            merged.append(node)
        elif tag in first:
            earlier = merged[first[tag]]
            assert isinstance(earlier, Element)
            assert isinstance(node, Element)
            merged[first[tag]] = with_attributes(earlier, dict(attribute_items(node)))
        else:
            first[tag] = len(merged)
            merged.append(node)
    return merged


def _with_class(element: AnyElement, attribute: str, name: str) -> AnyElement:
    return (
        element
        if get_attribute(element, attribute) is not None
        else with_attributes(element, {attribute: name})
    )


def _reached_by(key: str, settings: frozenset[str]) -> bool:
    """Whether default settings with the tags ``settings`` reach an element of schema ``key``."""
    section, _, tag = key.rpartition("/")
    if section in ("tendon", "equality"):
        return section in settings
    if section == "actuator":
        return bool(settings & ACTUATOR_DEFAULT_TAGS)
    return tag in settings


def classed(nodes: Sequence[Node], main: Default, section: str) -> list[Node]:
    """The children of the child's ``section`` naming its class ``main`` where it applies.

    Only elements that a setting of ``main`` reaches name it: the others read the
    parent's defaults either way, and an older MuJoCo rejects ``class`` on some of
    them (``<texture>`` before 4.0). Bodies and frames in the world take it as
    ``childclass``.

    Examples:
        >>> from mjcf_model import Geom, Motor
        >>> main = Default(dclass="c_main", children=[Geom(rgba=[1, 0, 0, 1])])
        >>> [node.dclass for node in classed([Geom(), Motor()], main, "body")]
        ['c_main', None]

    """
    assert main.dclass is not None
    settings = frozenset(e.tag for e in main.elements if e.tag != "default")
    result: list[Node] = []
    for node in nodes:
        if isinstance(node, Element):
            key = f"{section}/{node.tag}"
            if section == "body" and node.tag in ("body", "frame"):
                node = _with_class(node, "childclass", main.dclass)
            elif key in SCHEMA and "class" in SCHEMA[key].attributes and _reached_by(key, settings):
                node = _with_class(node, "class", main.dclass)
        result.append(node)
    return result
