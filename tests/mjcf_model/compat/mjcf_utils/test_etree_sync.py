"""Tests of ``mjcf_model.compat.mjcf_utils.etree_sync``."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from tests.support.compat_utils import (
    E2,
    ours,
)

# -- compat ``mjcf_utils``: the same names and signatures as robosuite's, and the golden checks.
#
# The golden checks are items 1 to 6 of section 6 of the robosuite contract
# (``/work/shared/reference/robosuite_contract.md``), each run against robosuite
# 1.5.2 itself and against the exact text the contract recorded.


# -- golden check 6: add_material and recolor_collision_geoms ------------------------------


def test_tree_functions_keep_the_element_objects() -> None:
    """The tree functions change attributes on the same Element objects; none is replaced."""
    root = ET.fromstring(E2)
    before = list(root.iter())
    ours.add_prefix(root, "p_")
    ours.set_alpha(root, 0.5)
    ours.recolor_collision_geoms(root, ours.RED)
    ours.add_material(root, "p_")
    ours.scale_mjcf_model(root, ET.Element("asset"), 2, ours.get_elements, worldbody=root)
    assert all(a is b for a, b in zip(root.iter(), before, strict=True))
    assert root[0].get("rgba") == "1 0 0 1" and root[0].get("name") == "p_g"
