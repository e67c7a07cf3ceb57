"""Shared checks for the differential tests of ``mjcf_model.compat.objects`` against robosuite.

Trees are compared as tag, attributes (name and text, in order) and children,
white space text and tails ignored, and as ``ET.tostring`` bytes after white
space is stripped.
"""

from __future__ import annotations

import copy
import xml.etree.ElementTree as ET
from typing import Any

import numpy as np
from robosuite.models.world import MujocoWorldBase

from mjcf_model.serializers import to_etree

#: The properties every object answers, compared one by one.
PROPERTIES = (
    "name",
    "naming_prefix",
    "root_body",
    "bodies",
    "joints",
    "actuators",
    "sites",
    "sensors",
    "contact_geoms",
    "visual_geoms",
    "important_geoms",
    "important_sites",
    "important_sensors",
    "bottom_offset",
    "top_offset",
    "horizontal_radius",
)


def stripped(element: ET.Element) -> ET.Element:
    """A copy of ``element`` without white-space-only text and tails."""
    element = copy.deepcopy(element)
    for item in element.iter():
        if item.text is not None and not item.text.strip():
            item.text = None
        if item.tail is not None and not item.tail.strip():
            item.tail = None
    return element


def text_of(element: ET.Element) -> str:
    """``ET.tostring`` of ``element`` with white space stripped."""
    return ET.tostring(stripped(element), encoding="unicode")


def tree(element: ET.Element) -> tuple[Any, ...]:
    """Tag, ordered attributes, stripped text and children, recursively."""
    text = element.text.strip() if element.text and element.text.strip() else None
    return (element.tag, list(element.attrib.items()), text, [tree(c) for c in element])


def assert_same_tree(ours: ET.Element, theirs: ET.Element) -> None:
    """The two trees are equal as trees and as stripped text."""
    assert text_of(ours) == text_of(theirs)
    assert tree(ours) == tree(theirs)


def assert_same_value(ours: Any, theirs: Any, label: str) -> None:
    """Equal values: arrays element by element with the same dtype kind, others with ``==``."""
    if isinstance(theirs, np.ndarray) or isinstance(ours, np.ndarray):
        assert isinstance(ours, np.ndarray), label
        np.testing.assert_array_equal(ours, theirs, err_msg=label)
        assert ours.dtype.kind == np.asarray(theirs).dtype.kind, label
    else:
        assert ours == theirs, label
        assert type(ours) is type(theirs), label


def assert_view_matches_model(ours: Any) -> None:
    """The live ElementTree shows exactly the immutable model."""
    assert ET.tostring(ours._view.element) == ET.tostring(to_etree(ours.mjcf))


def assert_same_object(ours: Any, theirs: Any, *, asset: bool = True) -> None:
    """Same body, assets, document and every property as robosuite's object."""
    assert_same_tree(ours.get_obj(), theirs.get_obj())
    if asset:
        assert_same_tree(ours.asset, theirs.asset)
    if hasattr(theirs, "get_xml"):
        assert_same_tree(ours.root, theirs.root)
        assert [c.tag for c in ours.root] == [c.tag for c in theirs.root]
        assert ours.get_obj() is ours.root.find("./worldbody/body/body")
    for name in PROPERTIES:
        assert_same_value(getattr(ours, name), getattr(theirs, name), name)
    assert_same_value(ours.get_bounding_box_half_size(), theirs.get_bounding_box_half_size(), "bb")
    assert_same_value(ours.get_bounding_box_size(), theirs.get_bounding_box_size(), "bbox")
    for template in ("get_site_attrib_template", "get_joint_attrib_template"):
        assert getattr(ours, template)() == getattr(theirs, template)()
    assert ours.get_obj() is ours.get_obj()
    assert_view_matches_model(ours)


def assert_same_composite(mine: Any, theirs: Any) -> None:
    """Same object as robosuite's, byte for byte once white space is stripped, and bookkeeping."""
    assert_same_object(mine, theirs)
    assert text_of(mine.get_obj()) == text_of(theirs.get_obj())
    assert text_of(mine.asset) == text_of(theirs.asset)
    assert mine._object_absolute_positions.keys() == theirs._object_absolute_positions.keys()
    for key, value in theirs._object_absolute_positions.items():
        assert_same_value(mine._object_absolute_positions[key], value, key)
    assert_same_value(mine._top, theirs._top, "top")
    assert_same_value(mine._bottom, theirs._bottom, "bottom")
    assert mine.joint_specs == theirs.joint_specs and mine.site_specs == theirs.site_specs
    assert mine.object_parents == theirs.object_parents


def composite_world(objects: list[Any]) -> MujocoWorldBase:
    """A robosuite world holding ``objects``: their assets merged, their bodies appended."""
    world = MujocoWorldBase()
    for obj in objects:
        world.merge_assets(obj)
        world.worldbody.append(obj.get_obj())
    return world


_OBJECT = (
    '<mujoco><asset><mesh name="m" file="m.stl" scale="{scale}"/></asset><worldbody><body>'
    '<body name="object"><geom name="shell" type="box" size="0.1 0.1 0.1" group="0"/>'
    '<site name="tip" pos="0 0 0.1"/></body>'
    '<site name="bottom_site" pos="0 0 -0.1"/><site name="top_site" pos="0 0 0.1"/>'
    '<site name="horizontal_radius_site" pos="0.1 0 0"/></body></worldbody></mujoco>'
)
