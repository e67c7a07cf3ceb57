"""Tests of the helper ``tests.support.compat_utils``."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from hypothesis import given, settings

from tests.support.compat_utils import (
    messy_trees,
    named_elements,
)

# -- compat ``mjcf_utils`` tree functions against robosuite's, on generated models and the
#    corpus.
#
# Every case runs robosuite's function and ours on copies of one tree and
# requires the same bytes from ``ET.tostring``, the same return value (elements
# compared by position) and the same exception type. Where robosuite crashes on
# valid MJCF (numbers separated by several spaces; unnamed elements and
# ``return_first`` in ``find_elements_by_substring``), ours must give what
# robosuite gives on the input it can read.


# -- generated trees ------------------------------------------------------------------------


def test_generated_trees_hold_what_the_functions_look_for() -> None:
    """The generated trees hold visual and collision geoms, slide joints, sites and actuators."""
    seen: set[str] = set()

    @settings(database=None)
    @given(messy_trees())
    def collect(tree: tuple[ET.Element, tuple[int, ...]]) -> None:
        root, _ = tree
        for element in named_elements(root):
            if element.tag == "geom":
                seen.add(f"geom group {element.get('group')}")
            if element.tag == "joint" and element.get("type") == "slide":
                seen.add("slide")
            seen.add(element.tag)

    collect()
    assert {"geom group 1", "geom group None", "slide", "site", "body", "motor"} <= seen
