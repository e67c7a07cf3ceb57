"""robosuite's geom roles, and recoloring by role.

MuJoCo gives geom groups no meaning; robosuite reads group 0 (or none) as a collision
geom and group 1 as a visual one. Its materials, categories and recoloring follow that
convention, and so does this module; the core library does not.

>>> from mjcf_model import Body, Geom
>>> body = Body(children=[Geom(name="c"), Geom(name="v", group=1)])
>>> [geom_role(g) for g in body.geoms]
['collision', 'visual']
>>> with_collision_color(body, lambda: (0.5, 0.0, 0.0, 1.0)).geoms[0].rgba
(0.5, 0.0, 0.0, 1.0)
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Literal, TypeVar, cast

from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    Node,
    get_attribute,
    with_attributes,
)
from mjcf_model.serializers.parsed_elements import written_text
from mjcf_model.tree.traversal import map_tree
from mjcf_model.values import Value

__all__ = ["GeomRole", "geom_role", "role_of_group", "with_collision_color", "with_visual_material"]

_E = TypeVar("_E", bound=Element)

#: A geom's role in robosuite's convention.
GeomRole = Literal["collision", "visual"]


def geom_role(element: AnyElement) -> GeomRole | None:
    """``"collision"`` for a geom in group 0 or none, ``"visual"`` in group 1, else ``None``.

    The group is compared as the text the writer writes (a file's own spelling while the
    value is the one read), so ``group="1.0"`` and ``group="01"`` have no role, as in
    robosuite.

    Examples:
        >>> from mjcf_model import Geom, Site
        >>> geom_role(Geom()), geom_role(Geom(group=1)), geom_role(Geom(group=3)), geom_role(Site())
        ('collision', 'visual', None, None)

    """
    if element.tag != "geom":
        return None
    return role_of_group(written_text(element, "group"))


def role_of_group(group: str | None) -> GeomRole | None:
    """The role of a geom whose ``group`` is written as ``group`` (``None``: not written).

    Examples:
        >>> role_of_group(None), role_of_group("1"), role_of_group("1.0")
        ('collision', 'visual', None)

    """
    if group is None or group == "0":
        return "collision"
    return "visual" if group == "1" else None


def with_collision_color(
    node: _E, color: Callable[[], Value], exclude: Callable[[AnyElement], Any] | None = None
) -> _E:
    """Paint every collision geom not excluded ``color()`` and remove its ``material``.

    Collision geoms are those :func:`geom_role` says so of; unchanged subtrees are the
    input's own. ``color`` is called once, at the first such geom (never when there is
    none), so its value may be text or numbers, as the caller writes colours.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="c"), Geom(name="v", group=1)])
        >>> new = with_collision_color(body, lambda: "1 0 0 1")
        >>> new.geoms[0].rgba, new.geoms[1] is body.geoms[1]
        ((1.0, 0.0, 0.0, 1.0), True)

    """
    made: list[Value] = []

    def paint(geom: AnyElement) -> dict[str, Value | None] | None:
        if exclude is not None and exclude(geom):
            return None
        if not made:
            made.append(color())
        return {"rgba": made[0], "material": None}

    return _with_role_changed(node, "collision", paint)


def with_visual_material(node: _E, material: str) -> tuple[_E, bool]:
    """``node`` with every visual geom that has no material given ``material``; whether any did.

    robosuite's ``add_material`` rule: a geom whose group is written ``1`` (``node``
    included); unchanged subtrees are the input's own.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="v", group=1), Geom(name="c")])
        >>> tree, used = with_visual_material(body, "wood")
        >>> [g.material for g in tree.geoms], used, tree.geoms[1] is body.geoms[1]
        (['wood', None], True, True)

    """
    used = False

    def give(geom: AnyElement) -> dict[str, Value | None] | None:
        nonlocal used
        if get_attribute(geom, "material") is not None:
            return None
        used = True
        return {"material": material}

    return _with_role_changed(node, "visual", give), used


def _with_role_changed(
    node: _E, role: GeomRole, change: Callable[[AnyElement], dict[str, Value | None] | None]
) -> _E:
    """``node`` with each geom of ``role`` given the attributes ``change(geom)`` returns, if any."""

    def visit(current: Node) -> Node:
        if isinstance(current, Element) and geom_role(current) == role:
            changes = change(current)
            if changes is not None:
                return with_attributes(current, changes)
        return current

    return cast(_E, map_tree(visit, node))
