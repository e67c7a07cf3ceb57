"""Tests of ``mjcf_model.compat.objects.pot``."""

from __future__ import annotations

import numpy as np
import pytest
import robosuite.models.objects as rs

from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    text_of,
)

# -- The composite recipes (``Bin``, ``Lid``, ``ConeObject``, ``HammerObject``...) against
#    robosuite.
#
# Each case builds robosuite's object and ours from the same arguments and compares
# the body, the assets, every property, the recipe's own attributes and the
# arguments it gives ``CompositeObject``; hypothesis draws the parameters over their
# ranges; MuJoCo compiles and steps a world holding all nine.


def test_a_numpy_pot_color_works_here() -> None:
    """A numpy colour gives the tuple's pot (robosuite reads its truth value: ``ValueError``)."""
    color = np.array([1.0, 1.0, 0.0, 1.0])
    with pytest.raises(ValueError, match="truth value"):
        rs.PotWithHandlesObject("pot", rgba_body=color, use_texture=False)
    mine = ours.PotWithHandlesObject("pot", rgba_body=color, use_texture=False)
    same = ours.PotWithHandlesObject("pot", rgba_body=(1.0, 1.0, 0.0, 1.0), use_texture=False)
    assert text_of(mine.get_obj()) == text_of(same.get_obj())
