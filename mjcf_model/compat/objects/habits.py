"""robosuite's habits as node functions: number text, attribute order, what gets scaled.

Built on the compatible ``mjcf_utils`` wherever robosuite's objects call ``mjcf_utils``.

>>> print(rs_geom("g", "box", [0.5, 0, 1]).attributes["size"], "|", value_text(np.float32(0.5)))
0.5 0 1 | 0.5
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from typing import Any

import numpy as np
import numpy.typing as npt

from mjcf_model.compat.mjcf_utils import constants as utils_constants
from mjcf_model.compat.mjcf_utils.builders import body_node, geom_node, joint_node, site_node
from mjcf_model.compat.mjcf_utils.etree_sync import attribute
from mjcf_model.compat.mjcf_utils.scaling import (
    scaled_body,
    scaled_geom,
    scaled_joint,
    scaled_mesh,
    scaled_site,
)
from mjcf_model.compat.mjcf_utils.text import array_to_string, text_of, three_factors
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, GenericElement, Node, TypedElement
from mjcf_model.transforms.naming.repeated import with_texts as checked_texts
from mjcf_model.transforms.scaling.scaled import _factors as checked_factors
from mjcf_model.tree.traversal import with_children

__all__ = [
    "OBJECT_COLLISION_COLOR",
    "attribute",
    "robosuite_scaled",
    "rs_body",
    "rs_geom",
    "rs_joint",
    "rs_site",
    "value_text",
    "with_texts",
]

#: robosuite's ``OBJECT_COLLISION_COLOR``, as it writes it (``"0.5 0 0 1"``).
OBJECT_COLLISION_COLOR = array_to_string(utils_constants.OBJECT_COLLISION_COLOR)

#: ``scale_mjcf_model``'s rule per tag (robosuite's objects pass ``scale_slide_joints=False``).
_SCALING_RULES: Mapping[str, Callable[[Node, Any], Node]] = {
    "geom": scaled_geom,
    "site": scaled_site,
    "body": scaled_body,
    "joint": lambda node, factors: scaled_joint(node, factors, scale_slide_joints=False),
    "mesh": scaled_mesh,
}


def value_text(value: Any) -> str:
    """Like robosuite's ``convert_to_string``, also accepting numpy scalars (robosuite raises)."""
    if type(value) is str:  # most values are text already
        return value
    text = text_of(value, exact=False)
    if text is None:
        raise MjcfValueError(f"unsupported attribute value type: got {type(value)} ({value!r})")
    return text


def with_texts(element: AnyElement, changes: Mapping[str, str | None]) -> AnyElement:
    """``element`` with attributes set to text (``None`` removes); positions kept like ``set``."""
    return checked_texts(element, changes)


def rs_geom(
    name: str | None,
    type: str | None,
    size: Any,
    pos: Any = (0, 0, 0),
    group: Any = 0,
    **extra: Any,
) -> GenericElement:
    """Like robosuite's ``new_geom``: extra attributes, then type, size, pos, group, name."""
    return geom_node(name, type, size, pos, group, extra, value_text)


def rs_site(
    name: str | None = None,
    rgba: Any = (1, 0, 0, 1),
    pos: Any = (0, 0, 0),
    size: Any = (0.005,),
    **extra: Any,
) -> GenericElement:
    """Like robosuite's ``new_site``: extra attributes, then pos, size, rgba, name."""
    return site_node(name, rgba, pos, size, extra, value_text)


def rs_joint(name: str | None = None, **extra: Any) -> GenericElement:
    """Like robosuite's ``new_joint``: the attributes, then name."""
    return joint_node(name, extra, value_text)


def rs_body(name: str | None = None, pos: Any = (0, 0, 0), **extra: Any) -> GenericElement:
    """Like robosuite's ``new_body``: the attributes, then pos, then name."""
    return body_node(name, pos, extra, value_text)


def scale_factors(scale: Any) -> npt.NDArray[Any]:
    """Like robosuite's ``normalize_scale_array``: one number or three, as an array of three."""
    factors = three_factors(scale)
    if factors is None:
        raise MjcfValueError(f"Scale must be a scalar or a 3-element array, found {scale!r}")
    return factors


def robosuite_scaled(node: AnyElement, scale: Any, tags: Iterable[str]) -> AnyElement:
    """What robosuite's objects scale below ``node`` (tags ``tags``), written as robosuite does."""
    chosen = frozenset(tags)
    factors = np.array(checked_factors(scale_factors(scale).astype(float)))

    def visit(element: AnyElement, is_root: bool) -> AnyElement:
        children: list[Node] = [
            visit(child, False) if isinstance(child, (TypedElement, GenericElement)) else child
            for child in element.children
        ]
        element = with_children(element, children)
        rule = _SCALING_RULES.get(element.tag)
        if rule is None or element.tag not in chosen or is_root:
            return element
        try:
            new = rule(element, factors)
        except ValueError as error:
            raise MjcfValueError(f"<{element.tag}> cannot be scaled: {error}") from error
        assert isinstance(new, (TypedElement, GenericElement))
        return new

    return visit(node, True)
