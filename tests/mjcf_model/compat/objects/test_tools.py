"""Tests of ``mjcf_model.compat.objects.tools``."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
import robosuite.models.objects as rs

from mjcf_model import MjcfValueError
from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_value,
)
from tests.support.compat_recipes import (
    CASES,
    _pair,
    assert_same_recipe,
)

# -- The composite recipes (``Bin``, ``Lid``, ``ConeObject``, ``HammerObject``...) against
#    robosuite.
#
# Each case builds robosuite's object and ours from the same arguments and compares
# the body, the assets, every property, the recipe's own attributes and the
# arguments it gives ``CompositeObject``; hypothesis draws the parameters over their
# ranges; MuJoCo compiles and steps a world holding all nine.


@pytest.mark.parametrize("seed", [0, 1, 7])
@pytest.mark.parametrize("kwargs", CASES["HammerObject"], ids=range(len(CASES["HammerObject"])))
def test_hammer_draws_what_robosuite_draws(seed: int, kwargs: dict[str, Any]) -> None:
    """Five draws, then one per ``init_quat`` read: the generators stay in step with robosuite's."""
    mine, theirs = _pair("HammerObject", kwargs, seed)
    assert_same_recipe("HammerObject", mine, theirs)
    assert mine.rng.bit_generator.state == theirs.rng.bit_generator.state
    for read in range(5):
        assert_same_value(mine.init_quat, theirs.init_quat, f"init_quat {read}")
    assert mine.rng.bit_generator.state == theirs.rng.bit_generator.state
    assert mine.rng.random() == theirs.rng.random()


def test_only_the_hammer_frame_and_stand_have_an_initial_orientation() -> None:
    """Placement samplers turn an object by ``init_quat`` when it has one: only these three."""
    for cls in CASES:
        mine, theirs = _pair(cls, {})
        assert hasattr(mine, "init_quat") == hasattr(theirs, "init_quat"), cls
    assert {cls for cls in CASES if hasattr(_pair(cls, {})[0], "init_quat")} == {
        "HammerObject",
        "HookFrame",
        "StandWithMount",
    }


def test_a_bad_hammer_shape_is_refused_after_the_draws() -> None:
    """An ``MjcfValueError`` names the two shapes, after the draws (robosuite asserts there)."""
    theirs_rng, mine_rng = np.random.default_rng(3), np.random.default_rng(3)
    with pytest.raises(AssertionError):
        rs.HammerObject("h", handle_shape="sphere", rng=theirs_rng)
    with pytest.raises(MjcfValueError, match="'box' or 'cylinder', got 'sphere'"):
        ours.HammerObject("h", handle_shape="sphere", rng=mine_rng)
    assert mine_rng.bit_generator.state == theirs_rng.bit_generator.state
