"""robosuite's lookups (sorting into categories, finding elements and parents) over nodes.

Each converts the tree, queries the nodes, and returns the live elements found.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable, Collection, Iterable, Iterator
from typing import Any

import attrs

from mjcf_model.compat.geom_roles import geom_role
from mjcf_model.compat.mjcf_utils.constants import SENSOR_TYPES
from mjcf_model.compat.mjcf_utils.etree_sync import (
    attribute,
    element_index,
    node_index,
    node_of,
    preorder,
    shallow_node,
)
from mjcf_model.nodes.base import AnyElement, Element, Node
from mjcf_model.tree.queries import find_all, parent_of
from mjcf_model.tree.traversal import walk

__all__ = [
    "Categories",
    "categorized",
    "filter_key",
    "find_elements",
    "find_elements_by_substring",
    "find_parent",
    "get_elements",
    "iter_matching",
    "sort_elements",
    "sorted_nodes",
    "typed_pairs",
]


def _tag(node: Node | None) -> str | None:
    """The tag of an element node, else ``None``."""
    return node.tag if isinstance(node, Element) else None


def filter_key(
    node: Node, parent: Node | None, sensor_tags: Collection[str] | None = SENSOR_TYPES
) -> str | None:
    """The category robosuite gives ``node`` under ``parent`` (``"joints"``...), or ``None``.

    Any child of ``<actuator>`` (comments too) is ``"actuators"``; a geom is contact or
    visual by its :func:`~mjcf_model.compat.geom_roles.geom_role`. A sensor is an element
    whose tag is in ``sensor_tags`` (robosuite's list), or with ``None`` any child of
    ``<sensor>`` (the newer sensors too).
    """
    if parent is not None and _tag(parent) == "actuator":
        return "actuators"
    tag = _tag(node)
    if tag == "joint":
        is_dof = attribute(node, "joint") is None and attribute(node, "joint1") is None
        return "joints" if is_dof else None
    if tag == "body":
        return "root_body" if parent is None or _tag(parent) != "body" else "bodies"
    if tag == "site":
        return "sites"
    is_sensor = tag in sensor_tags if sensor_tags is not None else _tag(parent) == "sensor"
    if is_sensor:
        return "sensors"
    if tag == "geom":
        assert isinstance(node, Element)
        return {"collision": "contact_geoms", "visual": "visual_geoms"}.get(geom_role(node) or "")
    return None


def _element_filter(element: ET.Element, parent: ET.Element | None) -> str | None:
    """The default filter of ``sort_elements``: :func:`filter_key` of a live element."""
    return filter_key(shallow_node(element), None if parent is None else shallow_node(parent))


def sorted_nodes(node: Node, parent: Node | None = None) -> dict[str, list[Node]]:
    """The nodes of ``node`` (itself included) by :func:`filter_key`, keys in first-seen order."""
    found: dict[str, list[Node]] = {}
    for above, current, _path in preorder(node):
        key = filter_key(current, parent if above is None else above)
        if key is not None:
            found.setdefault(key, []).append(current)
    return found


def sort_elements(
    root: ET.Element,
    parent: ET.Element | None = None,
    element_filter: Callable[[Any, Any], Any] | None = None,
    _elements_dict: dict[Any, list[Any]] | None = None,
) -> dict[Any, list[Any]]:
    """The live elements of ``root`` (itself included), in lists by filter key.

    ``element_filter(element, parent)`` (default ``_element_filter``) sees every
    live element, comments too, in document order, so it may edit them. Keys
    come in first-seen order; ``None`` keys are dropped. ``_elements_dict`` is
    robosuite's recursion argument: a dict to add to and return.

    Examples:
        >>> tree = ET.fromstring('<body><geom name="c"/><body name="in"/></body>')
        >>> {k: [e.get("name") for e in v] for k, v in sort_elements(tree).items()}
        {'root_body': [None], 'contact_geoms': ['c'], 'bodies': ['in']}

    """
    if _elements_dict is None:
        _elements_dict = {}
    node = node_of(root)
    live = element_index(root, node)
    if element_filter is None:
        parent_node = None if parent is None else shallow_node(parent)
        for key, nodes in sorted_nodes(node, parent_node).items():
            _elements_dict.setdefault(key, []).extend(live[id(n)] for n in nodes)
        return _elements_dict
    for above, current, _path in preorder(node):
        element = live[id(current)]
        key = element_filter(element, parent if above is None else live[id(above)])
        if key is not None:
            _elements_dict.setdefault(key, []).append(element)
    return _elements_dict


def find_parent(element: ET.Element, target: Any) -> ET.Element | None:
    """The element below ``element`` whose child is ``target`` itself, or ``None``.

    Examples:
        >>> tree = ET.fromstring("<a><b><c/></b></a>")
        >>> find_parent(tree, tree[0][0]) is tree[0], find_parent(tree, tree)
        (True, None)

    """
    node = node_of(element)
    target_node = node_index(element, node).get(id(target))
    if target_node is None:
        return None
    found = parent_of(node, target_node)
    return None if found is None else element_index(element, node)[id(found)]


def iter_matching(node: Node, tags: Any, attribs: dict[Any, Any] | None) -> Iterator[AnyElement]:
    """The elements of ``node`` (itself included) with a tag ``in tags`` and ``attribs``.

    Attributes are compared as text with ``!=``, as robosuite does (``None``: absent).
    """
    if isinstance(tags, str):  # a str subclass: robosuite's `in` is then a substring test
        tags = {e.tag for _, e in walk(node) if e.tag in tags}
    for element in find_all(node, tags):
        matching = True
        if attribs is not None:
            for k, v in attribs.items():
                if attribute(element, k) != v:
                    matching = False
                    break
        if matching:
            yield element


def find_elements(
    root: ET.Element, tags: Any, attribs: dict[Any, Any] | None = None, return_first: bool = True
) -> Any:
    """The first live element (or all of them) with a tag in ``tags`` and these attributes.

    ``root`` is a candidate itself; ``attribs`` values are text (``None``: absent).

    Returns:
        The element, or the list of them in document order; ``None`` (not an
        empty list) when nothing matches, as in robosuite.

    Examples:
        >>> tree = ET.fromstring('<body><geom name="a" group="1"/><geom name="b"/></body>')
        >>> find_elements(tree, "geom", {"group": None}).get("name"), find_elements(tree, "site")
        ('b', None)

    """
    tags = [tags] if type(tags) is str else tags
    node = node_of(root)
    found = iter_matching(node, tags, attribs)
    if return_first:
        first = next(found, None)
        return None if first is None else element_index(root, node)[id(first)]
    nodes = list(found)
    if not nodes:
        return None
    live = element_index(root, node)
    return [live[id(n)] for n in nodes]


def find_elements_by_substring(
    root: ET.Element,
    tags: Any,
    substrings: Any,
    attribs: dict[Any, Any] | None = None,
    return_first: bool = False,
) -> Any:
    """The elements :func:`find_elements` finds whose name contains one of ``substrings``.

    Unlike robosuite, an unnamed element does not match (robosuite raises
    ``TypeError``), and ``return_first`` returns the first match (robosuite
    searches the first element's children instead). ``None`` when nothing matches.

    Examples:
        >>> tree = ET.fromstring('<body><geom/><geom name="left_pad"/><geom name="right"/></body>')
        >>> [g.get("name") for g in find_elements_by_substring(tree, "geom", ["pad", "ri"])]
        ['left_pad', 'right']

    """
    substrings = [substrings] if type(substrings) is str else substrings
    tags = [tags] if type(tags) is str else tags
    node = node_of(root)
    named: list[AnyElement] = []
    for element in iter_matching(node, tags, attribs):
        name = attribute(element, "name")
        if name is None:
            continue
        for substring in substrings:
            if substring in name:
                named.append(element)
                break
        if named and return_first:
            break
    if not named:
        return None
    live = element_index(root, node)
    return live[id(named[0])] if return_first else [live[id(n)] for n in named]


def typed_pairs(
    node: Node, element_type: str, include_root: bool = False
) -> list[tuple[AnyElement | None, AnyElement]]:
    """``(parent, element)`` for each descendant with tag ``element_type``, in document order.

    ``node`` itself counts only with ``include_root`` (its parent is then ``None``).
    """
    return [
        (parent, current)
        for parent, current, _path in preorder(node)
        if isinstance(current, Element)
        and current.tag == element_type
        and (parent is not None or include_root)
    ]


def get_elements(
    root: ET.Element, element_type: str, _parent: ET.Element | None = None
) -> list[tuple[ET.Element, ET.Element]]:
    """``(parent, element)`` of the live descendants with tag ``element_type``, in document order.

    ``root`` itself is included only when ``_parent`` (robosuite's recursion argument) is given.

    Examples:
        >>> tree = ET.fromstring('<body name="a"><geom/><body name="b"><geom/></body></body>')
        >>> [(p.get("name"), g.tag) for p, g in get_elements(tree, "geom")]
        [('a', 'geom'), ('b', 'geom')]

    """
    node = node_of(root)
    live = element_index(root, node)
    return [
        (_parent if parent is None else live[id(parent)], live[id(child)])  # type: ignore[misc]
        for parent, child in typed_pairs(node, element_type, include_root=_parent is not None)
    ]


def _elements(items: Iterable[AnyElement]) -> tuple[AnyElement, ...]:
    return tuple(items)


@attrs.frozen(kw_only=True)
class Categories:
    """The elements of a tree sorted the way robosuite's ``sort_elements`` sorts them.

    Every field lists elements in document order. See :func:`categorized` for
    the rules.

    Examples:
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

    Examples:
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
        key = filter_key(element, parent, sensor_tags=None)
        if key is not None:
            found[key].append(element)
        stack.extend(
            (child, element) for child in reversed(element.children) if isinstance(child, Element)
        )
    return Categories(**found)
