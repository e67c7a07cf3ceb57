"""Looking things up in a node tree: find elements, parents and robosuite's categories.

All queries are read-only: they return nodes of the tree itself (so ``is`` works
on the results), in document order.

>>> from serializers import loads
>>> model = loads(
...     '<mujoco><worldbody><body name="arm"><geom name="a" group="1"/>'
...     '<geom name="b"/></body></worldbody></mujoco>'
... )
>>> find(model, "geom", group=1).name
'a'
>>> [g.name for g in find_all(model, "geom")]
['a', 'b']
>>> parent_of(model, find(model, "geom", name="b")).name
'arm'
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Collection, Iterable, Iterator
from typing import Literal

import attrs

from mjcf_model.nodes.base import (
    AnyElement,
    GenericElement,
    Node,
    TypedElement,
    attribute_text,
    get_attribute,
)
from mjcf_model.tree.traversal import walk
from mjcf_model.values import Value, format_value, plain_value

__all__ = [
    "Categories",
    "GeomRole",
    "attribute_values",
    "categorized",
    "geom_role",
    "find",
    "find_all",
    "parent_of",
    "walk",
]

#: Keyword arguments that stand for another MJCF attribute (``class`` is a Python keyword).
_KEYWORD_ATTRIBUTES = {"dclass": "class"}

#: Sections whose element children robosuite files under ``actuators`` and ``sensors``.
_ACTUATOR_SECTION = "actuator"
_SENSOR_SECTION = "sensor"


#: The reader :func:`attribute_values` made for each typed class and attribute names.
_READERS: dict[tuple[type, tuple[str, ...]], Callable[[AnyElement], tuple[Value | None, ...]]] = {}


def attribute_values(element: AnyElement, names: tuple[str, ...]) -> tuple[Value | None, ...]:
    """The values of the MJCF attributes ``names`` (``None`` where not written), read at once.

    The same values as :func:`~mjcf_model.nodes.base.get_attribute` for each name, read
    by one reader per class and names, made on first use: the transforms that
    read several attributes of every element use it.

    Example:
        >>> from mjcf_model import Geom
        >>> attribute_values(Geom(dclass="arm", size=[1], extra={"x": "1"}), ("class", "pos", "x"))
        ('arm', None, '1')

    """
    if isinstance(element, GenericElement):
        get = element.attributes.get
        return tuple([get(name) for name in names])
    reader = _READERS.get((type(element), names))
    if reader is None:
        reader = _reader(type(element), names)
        _READERS[(type(element), names)] = reader
    return reader(element)


def _reader(
    cls: type[TypedElement], names: tuple[str, ...]
) -> Callable[[AnyElement], tuple[Value | None, ...]]:
    table = cls.__node_info__.table
    fields = tuple(table.get(name) for name in names)
    if len(names) > 1 and None not in fields:
        return operator.attrgetter(*fields)  # type: ignore[arg-type]
    pairs = tuple(zip(names, fields, strict=True))

    def read(element: AnyElement) -> tuple[Value | None, ...]:
        extra = element.extra  # type: ignore[union-attr]
        return tuple(
            [extra.get(name) if field is None else getattr(element, field) for name, field in pairs]
        )

    return read


def _matches(value: Value | None, expected: object) -> bool:
    """Whether a written attribute value (``None``: not written) meets one expectation."""
    if expected is None:
        return value is None
    if value is None:
        return False
    if isinstance(expected, str):
        return format_value(value) == expected
    wanted = plain_value(expected)
    if isinstance(value, str):
        # An attribute the element keeps as text (generic element, extra attribute).
        return format_value(wanted) == value
    if isinstance(value, bool) or isinstance(wanted, bool):
        return isinstance(value, bool) and isinstance(wanted, bool) and value == wanted
    if isinstance(value, tuple):
        if not isinstance(wanted, tuple):
            wanted = (wanted,)
        return len(wanted) == len(value) and all(
            not isinstance(w, (bool, str, tuple)) and w == v
            for w, v in zip(wanted, value, strict=True)
        )
    return not isinstance(wanted, tuple) and bool(wanted == value)


def _tag_matches(element: AnyElement, tag: str | Collection[str]) -> bool:
    if isinstance(tag, str):
        return element.tag == tag
    return element.tag in tag


def _iter_matches(
    node: Node, tag: str | Collection[str], attributes: dict[str, object]
) -> Iterator[AnyElement]:
    wanted = [(_KEYWORD_ATTRIBUTES.get(k, k), v) for k, v in attributes.items()]
    for _path, element in walk(node):
        if _tag_matches(element, tag) and all(
            _matches(get_attribute(element, name), expected) for name, expected in wanted
        ):
            yield element


def find(node: Node, tag: str | Collection[str], /, **attributes: object) -> AnyElement | None:
    """The first element, ``node`` included, in document order with this tag and attributes.

    Args:
        node: Where to start; it is itself a candidate.
        tag: The tag, or any collection of tags, to look for.
        **attributes: Attribute values the element must have. ``None`` means
            "not written". A string is compared with the attribute's MJCF text
            (``format_value`` of a typed value); anything else with the typed
            value (lists and arrays as tuples, numbers numerically, a single
            number against a one-element vector). An attribute kept as text
            (generic elements, ``extra``) is compared with the expectation's
            text. ``dclass`` stands for ``class``.

    Returns:
        The element, or ``None`` when nothing matches.

    Example:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="g", size=[0.1], group=1), Geom(name="h")])
        >>> find(body, "geom", size=[0.1]).name, find(body, "geom", group="1").name
        ('g', 'g')
        >>> find(body, ("geom", "site"), group=None).name
        'h'
        >>> find(body, "joint") is None
        True

    """
    return next(_iter_matches(node, tag, attributes), None)


def find_all(node: Node, tag: str | Collection[str], /, **attributes: object) -> list[AnyElement]:
    """Every element, ``node`` included, with this tag and attributes, in document order.

    Matches like :func:`find`; an empty list when nothing matches (robosuite's
    ``find_elements`` returns ``None`` then).

    Example:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="g", dclass="vis"), Geom(name="h")])
        >>> [g.name for g in find_all(body, "geom")], find_all(body, "site")
        (['g', 'h'], [])
        >>> [g.name for g in find_all(body, "geom", dclass="vis")]
        ['g']

    """
    return list(_iter_matches(node, tag, attributes))


def parent_of(root: Node, node: Node) -> AnyElement | None:
    """The element whose ``children`` hold ``node`` itself (compared with ``is``).

    Returns ``None`` for ``root`` and for a node that is not in the tree (an
    equal copy is not the node).

    Example:
        >>> from mjcf_model import Body, Geom
        >>> geom = Geom(name="g")
        >>> body = Body(name="b", children=[geom])
        >>> parent_of(body, geom).name, parent_of(body, body), parent_of(body, Geom(name="g"))
        ('b', None, None)

    """
    for _path, element in walk(root):
        if any(child is node for child in element.children):
            return element
    return None


def _elements(items: Iterable[AnyElement]) -> tuple[AnyElement, ...]:
    return tuple(items)


@attrs.frozen(kw_only=True)
class Categories:
    """The elements of a tree sorted the way robosuite's ``sort_elements`` sorts them.

    Every field lists elements in document order. See :func:`categorized` for
    the rules.

    Example:
        >>> from mjcf_model import Body, Geom
        >>> found = categorized(Body(name="b", children=[Geom(name="g")]))
        >>> [b.name for b in found.root_body], [g.name for g in found.contact_geoms]
        (['b'], ['g'])

    """

    #: Bodies whose parent is not a ``<body>`` (or that are the queried node itself).
    root_body: tuple[AnyElement, ...] = attrs.field(default=(), converter=_elements)
    #: Bodies inside another body.
    bodies: tuple[AnyElement, ...] = attrs.field(default=(), converter=_elements)
    #: Joints that are degrees of freedom (no ``joint``/``joint1`` reference attribute).
    joints: tuple[AnyElement, ...] = attrs.field(default=(), converter=_elements)
    #: Every element child of an ``<actuator>`` section.
    actuators: tuple[AnyElement, ...] = attrs.field(default=(), converter=_elements)
    #: Sites.
    sites: tuple[AnyElement, ...] = attrs.field(default=(), converter=_elements)
    #: Every element child of a ``<sensor>`` section.
    sensors: tuple[AnyElement, ...] = attrs.field(default=(), converter=_elements)
    #: Geoms in group 0 or without a group.
    contact_geoms: tuple[AnyElement, ...] = attrs.field(default=(), converter=_elements)
    #: Geoms in group 1.
    visual_geoms: tuple[AnyElement, ...] = attrs.field(default=(), converter=_elements)


def _category(element: AnyElement, parent: AnyElement | None) -> str | None:
    """The category robosuite's ``_element_filter`` gives (sensors: see :func:`categorized`)."""
    if parent is not None and parent.tag == _ACTUATOR_SECTION:
        return "actuators"
    tag = element.tag
    if tag == "joint":
        is_reference = (
            get_attribute(element, "joint") is not None
            or get_attribute(element, "joint1") is not None
        )
        return None if is_reference else "joints"
    if tag == "body":
        return "root_body" if parent is None or parent.tag != "body" else "bodies"
    if tag == "site":
        return "sites"
    if parent is not None and parent.tag == _SENSOR_SECTION:
        return "sensors"
    return _ROLE_CATEGORIES.get(geom_role(element))  # type: ignore[arg-type]


#: A geom's role in robosuite's convention, which the library follows.
GeomRole = Literal["collision", "visual"]
#: The categories of the two roles.
_ROLE_CATEGORIES = {"collision": "contact_geoms", "visual": "visual_geoms"}


def geom_role(element: AnyElement) -> GeomRole | None:
    """``"collision"`` for a geom in group 0 or none, ``"visual"`` in group 1, else ``None``.

    robosuite's convention (MuJoCo gives groups no meaning), which recolouring,
    materials and categories follow; the group is compared as written text, so
    ``group="1.0"`` has no role, as in robosuite.

    Example:
        >>> from mjcf_model import Geom, Site
        >>> geom_role(Geom()), geom_role(Geom(group=1)), geom_role(Geom(group=3)), geom_role(Site())
        ('collision', 'visual', None, None)

    """
    if element.tag != "geom":
        return None
    group = attribute_text(element, "group")
    if group is None or group == "0":
        return "collision"
    return "visual" if group == "1" else None


def categorized(node: AnyElement) -> Categories:
    """Sort the elements of ``node`` (itself included) into robosuite's categories.

    The rules are those of robosuite's ``_element_filter``, tried in this order,
    by tag alone (so ``<default>`` geoms, joints and sites count too):

    * any element child of an ``<actuator>`` section: ``actuators``;
    * a ``joint`` with neither a ``joint`` nor a ``joint1`` attribute (not a
      tendon or equality reference): ``joints``;
    * a ``body`` whose parent is not a ``<body>`` (``worldbody``, ``frame``, ...)
      or that is ``node`` itself: ``root_body``; any other body: ``bodies``;
    * a ``site``: ``sites``;
    * any element child of a ``<sensor>`` section: ``sensors``;
    * a ``geom`` whose group is not written or ``0``: ``contact_geoms``; group
      ``1``: ``visual_geoms``; other groups: neither.

    Sensors differ from robosuite on purpose: robosuite files any element whose
    tag is in its ``SENSOR_TYPES`` set (35 tags, wherever the element stands),
    so newer sensors (``camprojection``, ``clock``, ``contact``, ``distance``,
    ``e_kinetic``, ``plugin``, ...) are missing from its list. Here every
    child of ``<sensor>`` is a sensor.

    Example:
        >>> from serializers import loads
        >>> model = loads(
        ...     '<mujoco><worldbody><body name="a"><joint name="j"/>'
        ...     '<geom name="v" group="1"/><body name="b"/></body></worldbody>'
        ...     '<actuator><motor name="m" joint="j"/></actuator>'
        ...     '<sensor><clock name="t"/></sensor></mujoco>'
        ... )
        >>> found = categorized(model)
        >>> [[e.name for e in getattr(found, f)] for f in ("root_body", "bodies", "joints")]
        [['a'], ['b'], ['j']]
        >>> [e.name for e in found.visual_geoms + found.actuators + found.sensors]
        ['v', 'm', 't']

    """
    found: dict[str, list[AnyElement]] = {f.name: [] for f in attrs.fields(Categories)}
    stack: list[tuple[AnyElement, AnyElement | None]] = [(node, None)]
    while stack:
        element, parent = stack.pop()
        key = _category(element, parent)
        if key is not None:
            found[key].append(element)
        stack.extend(
            (child, element)
            for child in reversed(element.children)
            if isinstance(child, (TypedElement, GenericElement))
        )
    return Categories(**found)
