"""Tests of ``mjcf_model.compat.objects.containers``."""

from __future__ import annotations

import robosuite.models.objects as rs

from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_tree,
)

# -- Generated objects (primitives, composites) of ``mjcf_model.compat.objects`` against
#    robosuite.


# -- composite objects ----------------------------------------------------------------


def test_composite_golden_bin() -> None:
    """Bin's walls: numpy-formatted densities, frictions and quaternions (golden check 10)."""
    mine, theirs = (
        ours.Bin("bin", bin_size=(0.2, 0.2, 0.1)),
        rs.Bin("bin", bin_size=(0.2, 0.2, 0.1)),
    )
    assert_same_tree(mine.get_obj(), theirs.get_obj())
    geoms = list(mine.get_obj().iter("geom"))
    assert geoms[0].get("density") == "1000.0" and geoms[0].get("friction") == "1.0 0.005 0.0001"
    assert any(g.get("quat") == "6.123233995736766e-17 0.0 0.0 1.0" for g in geoms)
