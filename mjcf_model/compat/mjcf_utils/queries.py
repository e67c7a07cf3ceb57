"""robosuite's lookups on its ElementTree elements, and its categories over nodes too.

``sort_elements``, ``find_parent``, ``find_elements``, ``find_elements_by_substring`` and
``get_elements`` read the live elements directly, in document order, with explicit stacks
(any depth); :func:`categorized` sorts nodes by the same rule, :func:`category`.
"""

from __future__ import annotations

import functools
import xml.etree.ElementTree as ET
from collections.abc import Callable, Collection, Iterable, Iterator
from typing import Any

import attrs

from mjcf_model.compat.geom_roles import role_of_group
from mjcf_model.compat.mjcf_utils.constants import SENSOR_TYPES
from mjcf_model.nodes.base import AnyElement, Element, Node
from mjcf_model.serializers.parsed_elements import written_text
from mjcf_model.tree.traversal import walk_nodes

__all__ = [
    "find_elements",
    "find_elements_by_substring",
    "find_parent",
    "get_elements",
    "sort_elements",
]


def category(
    tag: str | None,
    attribute_of: Callable[[str], str | None],
    parent_tag: str | None,
    is_root: bool,
    sensor_tags: Collection[str] | None = SENSOR_TYPES,
) -> str | None:
    """The category robosuite gives an element (``"joints"``...), or ``None``: the one rule.

    ``tag`` is ``None`` for a comment; ``attribute_of(name)`` gives an attribute's text
    (``None``: absent); ``is_root``: the element has no parent. Any child of ``<actuator>``
    (comments too) is ``"actuators"``; a geom is contact or visual by its group
    (:func:`~mjcf_model.compat.geom_roles.role_of_group`). A sensor is an element whose tag
    is in ``sensor_tags`` (robosuite's list), or with ``None`` any child of ``<sensor>``.

    Examples:
        >>> category("joint", {"joint1": "j"}.get, "equality", False)
        >>> category("body", {}.get, "worldbody", False)
        'root_body'
        >>> category("geom", {"group": "1"}.get, None, True)
        'visual_geoms'

    """
    if parent_tag == "actuator":
        return "actuators"
    if tag == "joint":
        is_dof = attribute_of("joint") is None and attribute_of("joint1") is None
        return "joints" if is_dof else None
    if tag == "body":
        return "root_body" if is_root or parent_tag != "body" else "bodies"
    if tag == "site":
        return "sites"
    is_sensor = tag in sensor_tags if sensor_tags is not None else parent_tag == "sensor"
    if is_sensor:
        return "sensors"
    if tag == "geom":
        role = role_of_group(attribute_of("group"))
        return {"collision": "contact_geoms", "visual": "visual_geoms"}.get(role or "")
    return None


def _tag(node: Node | ET.Element | None) -> str | None:
    """The tag of an element (node or live), ``None`` for a comment or no element."""
    if isinstance(node, Element):
        return node.tag
    if isinstance(node, ET.Element) and isinstance(node.tag, str):
        return node.tag
    return None


def _element_filter(element: ET.Element, parent: ET.Element | None) -> str | None:
    """The default filter of ``sort_elements``: the :func:`category` of a live element."""
    return category(_tag(element), element.get, _tag(parent), parent is None)


def _preorder(
    root: ET.Element, parent: ET.Element | None = None
) -> Iterator[tuple[ET.Element | None, ET.Element]]:
    """``(parent, element)`` for ``root`` and every element below it, in document order."""
    stack: list[tuple[ET.Element | None, ET.Element]] = [(parent, root)]
    while stack:
        above, element = stack.pop()
        yield above, element
        stack.extend((element, child) for child in reversed(list(element)))


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
    found = {} if _elements_dict is None else _elements_dict
    chosen = _element_filter if element_filter is None else element_filter
    for above, element in _preorder(root, parent):
        key = chosen(element, above)
        if key is not None:
            found.setdefault(key, []).append(element)
    return found


def find_parent(element: ET.Element, target: Any) -> ET.Element | None:
    """The element below ``element`` whose child is ``target`` itself, or ``None``.

    Examples:
        >>> tree = ET.fromstring("<a><b><c/></b></a>")
        >>> find_parent(tree, tree[0][0]) is tree[0], find_parent(tree, tree)
        (True, None)

    """
    for _, current in _preorder(element):
        if any(child is target for child in current):
            return current
    return None


def _matching(root: ET.Element, tags: Any, attribs: dict[Any, Any] | None) -> Iterator[ET.Element]:
    """The elements of ``root`` (itself included) with a tag ``in tags`` and ``attribs``.

    Attributes are compared as text with ``!=``, as robosuite does (``None``: absent).
    """
    for _, element in _preorder(root):
        if not isinstance(element.tag, str) or element.tag not in tags:
            continue
        if attribs is None or all(element.get(k) == v for k, v in attribs.items()):
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
    found = _matching(root, tags, attribs)
    if return_first:
        return next(found, None)
    return list(found) or None


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
    named = (
        element
        for element in _matching(root, tags, attribs)
        if (name := element.get("name")) is not None and any(s in name for s in substrings)
    )
    if return_first:
        return next(named, None)
    return list(named) or None


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
    return [
        (above, element)
        for above, element in _preorder(root, _parent)
        if above is not None and element.tag == element_type
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

    The rule is :func:`category`'s, by tag alone (so ``<default>`` geoms, joints and sites
    count too), with one difference on purpose: every child of ``<sensor>`` is a sensor,
    where robosuite files only the 35 tags of its ``SENSOR_TYPES`` wherever they stand
    (newer sensors such as ``camprojection``, ``clock`` or ``contact`` are missing from it).

    Examples:
        >>> from mjcf_model import loads
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
    for parent, element, _ in walk_nodes(node):
        if isinstance(element, Element):
            attribute_of = functools.partial(written_text, element)
            key = category(element.tag, attribute_of, _tag(parent), parent is None, None)
            if key is not None:
                found[key].append(element)
    return Categories(**found)
