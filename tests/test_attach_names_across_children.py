"""Names across the children of one attach_all: later children meet the earlier ones' names.

An asset that two children both declare as the same element is kept once (the
module docstring of mjcf_model/transforms/composition/attaching.py); any other
name a later child shares with an earlier one is a clash, as if it were the
parent's. MuJoCo compiling each part alone says what the scene's objects hold.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model import MjcfValueError, Mujoco, attach_all, compiled
from serializers import loads

CUP = """<mujoco>
  <asset><material name="red" rgba="1 0 0 1"/></asset>
  <worldbody><body name="cup"><geom name="cup_geom" size=".1" material="red"/></body></worldbody>
</mujoco>
"""
BOWL = """<mujoco>
  <asset><material name="red" rgba="1 0 0 1"/></asset>
  <worldbody><body name="bowl"><geom name="bowl_geom" size=".2" material="red"/></body></worldbody>
</mujoco>
"""


def test_an_asset_two_unprefixed_children_share_is_kept_once() -> None:
    """Two children declaring the same material: one material, used by both children's geoms."""
    scene = compiled(attach_all(Mujoco(), [(loads(CUP), ""), (loads(BOWL), "")]))
    alone = mujoco.MjModel.from_xml_string(CUP)
    assert scene.nmat == 1
    assert scene.geom("cup_geom").matid == scene.geom("bowl_geom").matid == scene.material("red").id
    np.testing.assert_allclose(scene.material("red").rgba, alone.material("red").rgba)


def test_a_child_attached_twice_with_one_prefix_clashes() -> None:
    """The same child twice under one prefix: its body names clash; use another prefix."""
    with pytest.raises(MjcfValueError, match=r"already has \(body: a_cup.*attach it with a prefix"):
        attach_all(Mujoco(), [(loads(CUP), "a_"), (loads(CUP), "a_")])
