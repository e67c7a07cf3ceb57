"""Tests of ``mjcf_model.compat.objects.base``."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any

import pytest
import robosuite.models.objects as rs

from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_tree,
)

# -- XML objects of ``mjcf_model.compat.objects`` against robosuite 1.5.2's, case by case. -----


# -- robosuite's shipped objects ------------------------------------------------------


def test_set_scale_of_another_body_scales_it_in_place_as_robosuite_does() -> None:
    """``set_scale(scale, obj=body)`` scales that live body in place, and the object's meshes."""
    trees = []
    for module in (rs, ours):
        can = module.CanObject("can")
        other = module.BoxObject("box", size=[0.1, 0.1, 0.1]).get_obj()
        can.set_scale([1, 2, 3], obj=other)
        trees.append((other, can.asset))
    (theirs, their_asset), (mine, my_asset) = trees
    assert_same_tree(mine, theirs)
    assert_same_tree(my_asset, their_asset)


# -- Generated objects (primitives, composites) of ``mjcf_model.compat.objects`` against
#    robosuite.


def test_mujoco_object_scale_argument_works() -> None:
    """Robosuite's MujocoObject(scale=2) raises TypeError; here the scale waits for the body."""
    with pytest.raises(TypeError):
        rs.MujocoObject(scale=2)
    assert ours.MujocoObject(scale=2).obj_type == "all"
    later = ours.MujocoObject()
    later.set_scale(2)  # robosuite: TypeError (no body yet); here it waits for the body
    assert later._pending_scale == 2

    def peg(base: type, **kwargs: Any) -> Any:
        class Peg(base):  # type: ignore[misc, valid-type]
            def __init__(self) -> None:
                super().__init__(**kwargs)
                self._name = "peg"
                self._obj = self._get_object_subtree()
                self._get_object_properties()

            def exclude_from_prefixing(self, inp: Any) -> bool:
                return False

            def _get_object_subtree(self) -> ET.Element:
                body = ET.Element("body", name="main")
                ET.SubElement(body, "geom", type="box", size="0.1 0.1 0.1", group="0", name="g0")
                site = ET.SubElement(body, "site", self.get_site_attrib_template())
                site.set("name", "default_site")
                return body

        return Peg()

    theirs, mine = peg(rs.MujocoObject), peg(ours.MujocoObject)
    assert_same_tree(mine.get_obj(), theirs.get_obj())
    assert (mine.contact_geoms, mine.sites) == (theirs.contact_geoms, theirs.sites)
    theirs.set_scale(2)
    mine.set_scale(2)
    assert_same_tree(mine.get_obj(), theirs.get_obj())
    assert_same_tree(peg(ours.MujocoObject, scale=2).get_obj(), theirs.get_obj())
