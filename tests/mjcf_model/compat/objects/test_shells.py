"""Tests of ``mjcf_model.compat.objects.shells``."""

from __future__ import annotations

import copy

import pytest
import robosuite.models.objects as rs
from robosuite.utils.mjcf_utils import CustomMaterial as TheirMaterial

from mjcf_model import MjcfValueError
from mjcf_model.compat import CustomMaterial
from mjcf_model.compat import objects as ours
from tests.support.compat_recipes import (
    _STEEL,
    assert_same_recipe,
)

# -- The composite recipes (``Bin``, ``Lid``, ``ConeObject``, ``HammerObject``...) against
#    robosuite.
#
# Each case builds robosuite's object and ours from the same arguments and compares
# the body, the assets, every property, the recipe's own attributes and the
# arguments it gives ``CompositeObject``; hypothesis draws the parameters over their
# ranges; MuJoCo compiles and steps a world holding all nine.


@pytest.mark.parametrize("cls", ["ConeObject", "HollowCylinderObject"])
@pytest.mark.parametrize("material_class", [CustomMaterial, TheirMaterial], ids=["ours", "theirs"])
def test_shell_materials_of_either_library_give_robosuites_shell(
    cls: str, material_class: type
) -> None:
    """A cone or ring takes this library's material or robosuite's; robosuite takes its own."""
    mine = getattr(ours, cls)("obj", material=material_class(**copy.deepcopy(_STEEL)))
    theirs = getattr(rs, cls)("obj", material=TheirMaterial(**copy.deepcopy(_STEEL)))
    assert_same_recipe(cls, mine, theirs)
    assert {g.get("material") for g in mine.get_obj().iter("geom") if g.get("group") == "1"} == {
        "obj_steel_mat"
    }


def test_a_cone_refuses_what_is_not_a_material() -> None:
    """Any ``CustomMaterial`` works, anything else says so (robosuite asserts its own class)."""
    with pytest.raises(AssertionError):
        rs.ConeObject("c", material="steel_mat")
    with pytest.raises(MjcfValueError, match="material must be a CustomMaterial, got 'steel_mat'"):
        ours.ConeObject("c", material="steel_mat")
