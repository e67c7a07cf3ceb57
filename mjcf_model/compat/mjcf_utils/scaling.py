"""robosuite's scaling: pure functions on one node each, and the in-place ``scale_*`` wrappers.

>>> geom = ET.fromstring('<geom pos="0 0 1" size="0.1"/>')
>>> scale_geom_element(geom, np.array([1, 2, 3]))
>>> geom.get("pos"), geom.get("size")
('0.0 0.0 3.0', '0.2')
"""

from __future__ import annotations

import functools
import xml.etree.ElementTree as ET
from collections.abc import Callable
from typing import Any

import numpy as np
import numpy.typing as npt

from mjcf_model.compat.mjcf_utils.text import array_to_string, normalize_scale_array, parse_numbers
from mjcf_model.nodes.base import Element, Node, attribute_text, with_attributes
from mjcf_model.serializers.etree_view import shallow_node, sync_element

__all__ = [
    "scale_body_element",
    "scale_geom_element",
    "scale_joint_element",
    "scale_mesh_element",
    "scale_mjcf_model",
    "scale_site_element",
]


def _changed(node: Node, changes: dict[str, str]) -> Node:
    """``node`` with ``changes`` (if any) applied."""
    if not changes or not isinstance(node, Element):
        return node
    return with_attributes(node, changes)


def _scaled_pos(node: Node, scale_array: Any, changes: dict[str, str]) -> None:
    """Put the scaled ``pos`` (if any) in ``changes``."""
    pos = attribute_text(node, "pos")
    if pos is not None:
        changes["pos"] = array_to_string(parse_numbers(pos) * scale_array)


def _scaled_size(node: Node, scale_array: Any, what: str, changes: dict[str, str]) -> None:
    """Put the scaled ``size`` in ``changes``: by axis, by the x-y mean and z, or by the mean."""
    size = attribute_text(node, "size")
    if size is None:
        return
    values = parse_numbers(size)
    if len(values) == 3:
        values = values * scale_array
    elif len(values) == 2:
        values[0] *= np.mean(scale_array[:2])
        values[1] *= scale_array[2]
    elif len(values) == 1:
        values *= np.mean(scale_array)
    else:
        raise ValueError(f"Unsupported {what} size dimensions.")
    changes["size"] = array_to_string(values)


def _scaled_pos_size(node: Node, scale_array: Any, what: str) -> Node:
    """``node`` with ``pos`` and ``size`` scaled."""
    changes: dict[str, str] = {}
    _scaled_pos(node, scale_array, changes)
    _scaled_size(node, scale_array, what, changes)
    return _changed(node, changes)


def scaled_geom(node: Node, scale_array: Any) -> Node:
    """A geom node with ``pos`` and ``size`` scaled robosuite's way (size by count, not type)."""
    return _scaled_pos_size(node, scale_array, "geom")


def scaled_site(node: Node, scale_array: Any) -> Node:
    """A site node with ``pos`` and ``size`` scaled like a geom's."""
    return _scaled_pos_size(node, scale_array, "site")


def scaled_mesh(node: Node, scale_array: Any) -> Node:
    """A mesh node whose ``scale`` (``1 1 1`` when absent, then written last) is multiplied."""
    scale = attribute_text(node, "scale")
    values = parse_numbers(scale) if scale is not None else np.ones(3)
    values *= scale_array
    return _changed(node, {"scale": array_to_string(values)})


def scaled_body(node: Node, scale_array: Any) -> Node:
    """A body node with ``pos`` scaled."""
    changes: dict[str, str] = {}
    _scaled_pos(node, scale_array, changes)
    return _changed(node, changes)


def _axis_factor(axis_text: str, scale_array: Any) -> Any:
    """The length of the scaled unit axis (x for a zero axis)."""
    axis = parse_numbers(axis_text)
    norm = np.linalg.norm(axis)
    unit = axis / norm if norm > 0 else np.array([1.0, 0.0, 0.0])
    return np.linalg.norm(unit * scale_array)


def scaled_joint(node: Node, scale_array: Any, scale_slide_joints: bool = True) -> Node:
    """A joint node with ``pos`` scaled, and a slide joint's ``range`` by the scaled axis length."""
    changes: dict[str, str] = {}
    _scaled_pos(node, scale_array, changes)
    if scale_slide_joints:
        joint_type = attribute_text(node, "type")
        joint_range = attribute_text(node, "range")
        if joint_range is not None and joint_type == "slide":
            axis = attribute_text(node, "axis")
            factor = _axis_factor("1 0 0" if axis is None else axis, scale_array)
            changes["range"] = array_to_string(parse_numbers(joint_range) * factor)
    return _changed(node, changes)


def _scale_in_place(
    scaled: Callable[[Node, Any], Node], element: ET.Element, scale_array: Any
) -> None:
    """Write ``scaled`` of the live ``element`` back onto it."""
    old = shallow_node(element)
    sync_element(element, old, scaled(old, scale_array))


def _in_place(scaled: Callable[[Node, Any], Node], what: str) -> Callable[[ET.Element, Any], None]:
    """A ``scale_<tag>_element``: ``scaled`` on one live element, written back in place."""

    def scale_element(element: ET.Element, scale_array: Any) -> None:
        _scale_in_place(scaled, element, scale_array)

    tag = scaled.__name__.removeprefix("scaled_")
    scale_element.__name__ = scale_element.__qualname__ = f"scale_{tag}_element"
    scale_element.__doc__ = f"Scale {what} in place (see :func:`{scaled.__name__}`)."
    return scale_element


scale_geom_element = _in_place(scaled_geom, "a geom's ``pos`` and ``size``")
scale_mesh_element = _in_place(scaled_mesh, "a mesh's ``scale``")
scale_body_element = _in_place(scaled_body, "a body's ``pos``")
scale_site_element = _in_place(scaled_site, "a site's ``pos`` and ``size``")


def scale_joint_element(
    element: ET.Element, scale_array: Any, scale_slide_joints: bool = True
) -> None:
    """Scale a joint's ``pos`` (and a slide joint's ``range``) in place (see :func:`scaled_joint`).

    Examples:
        >>> joint = ET.fromstring('<joint type="slide" axis="0 0 1" range="-1 1"/>')
        >>> scale_joint_element(joint, np.array([1, 1, 3]))
        >>> joint.get("range")
        '-3.0 3.0'

    """
    _scale_in_place(
        functools.partial(scaled_joint, scale_slide_joints=scale_slide_joints), element, scale_array
    )


def scale_mjcf_model(
    obj: ET.Element,
    asset_root: ET.Element,
    scale: Any,
    get_elements_func: Callable[[ET.Element, str], Any],
    worldbody: ET.Element | None = None,
    scale_slide_joints: bool = True,
) -> npt.NDArray[Any]:
    """Scale an object in place, robosuite's way; returns the three factors used.

    In robosuite's order: the geoms ``get_elements_func(obj, "geom")`` returns, every
    ``mesh`` directly under ``asset_root``, the bodies and joints of ``obj``, and the
    sites of ``worldbody`` if given. Unlike robosuite, any white space separates
    numbers, and a ``ValueError`` leaves the element it came from unchanged.

    Examples:
        >>> from mjcf_model.compat.mjcf_utils.queries import get_elements
        >>> obj = ET.fromstring('<body pos="0 0 1">'
        ...                     '<body pos="1 0 0"><geom size="1"/></body></body>')
        >>> scale_mjcf_model(obj, ET.Element("asset"), 2, get_elements)
        array([2, 2, 2])
        >>> ET.tostring(obj, encoding="unicode")
        '<body pos="0 0 1"><body pos="2.0 0.0 0.0"><geom size="2.0" /></body></body>'

    """
    scale_array = normalize_scale_array(scale)
    for _, element in get_elements_func(obj, "geom"):
        scale_geom_element(element, scale_array)
    for element in asset_root.findall("mesh"):
        scale_mesh_element(element, scale_array)
    for _, element in get_elements_func(obj, "body"):
        scale_body_element(element, scale_array)
    for _, element in get_elements_func(obj, "joint"):
        scale_joint_element(element, scale_array, scale_slide_joints)
    if worldbody is not None:
        for _, element in get_elements_func(worldbody, "site"):
            scale_site_element(element, scale_array)
    return scale_array
