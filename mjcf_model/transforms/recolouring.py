"""Recolouring collision geoms, with the caller's number formatting.

>>> from mjcf_model import Body, Geom
>>> body = Body(children=[Geom(name="c"), Geom(name="v", group=1)])
>>> with_collision_colour(body, lambda: (0.5, 0.0, 0.0, 1.0)).geoms[0].rgba
(0.5, 0.0, 0.0, 1.0)
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar, cast

from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    Node,
    with_attributes,
)
from mjcf_model.tree.queries import geom_role
from mjcf_model.tree.traversal import map_tree
from mjcf_model.values import Value

__all__ = ["with_collision_colour"]

_E = TypeVar("_E", bound=Element)


def with_collision_colour(
    node: _E, colour: Callable[[], Value], exclude: Callable[[AnyElement], Any] | None = None
) -> _E:
    """Paint every collision geom not excluded ``colour()`` and remove its ``material``.

    Collision geoms are those :func:`~mjcf_model.tree.queries.geom_role` says so of;
    unchanged subtrees are the input's own. ``colour`` is called once, at the first
    such geom (never when there is none), so its value may be text or numbers, as
    the caller writes colours.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="c"), Geom(name="v", group=1)])
        >>> new = with_collision_colour(body, lambda: "1 0 0 1")
        >>> new.geoms[0].rgba, new.geoms[1] is body.geoms[1]
        ((1.0, 0.0, 0.0, 1.0), True)

    """
    made: list[Value] = []

    def visit(current: Node) -> Node:
        if (
            isinstance(current, Element)
            and geom_role(current) == "collision"
            and (exclude is None or not exclude(current))
        ):
            if not made:
                made.append(colour())
            return with_attributes(current, {"rgba": made[0], "material": None})
        return current

    return cast(_E, map_tree(visit, node))
