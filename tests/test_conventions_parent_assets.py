"""A child converted to the parent's angles may use the parent's assets (it compiles attached)."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import attach, compiled
from serializers import dumps, loads

PARENT = (
    '<mujoco><compiler angle="radian"/><asset><material name="red" rgba="1 0 0 1"/></asset>'
    "<worldbody/></mujoco>"
)
#: In degrees, with a material only the parent declares: it does not compile alone.
CHILD = (
    '<mujoco><worldbody><body name="a" euler="0 0 90"><joint/>'
    '<geom size="0.1" material="red"/></body></worldbody></mujoco>'
)


def test_a_child_using_the_parents_material_is_converted_without_compiling_it_alone() -> None:
    """Only the angle setting differs: the body turns as MuJoCo turns it, the geom is red."""
    scene = compiled(attach(loads(PARENT), loads(CHILD)))
    by_hand = PARENT.replace(
        "<worldbody/>",
        '<worldbody><body name="a" euler="0 0 1.5707963267948966"><joint/>'
        '<geom size="0.1" material="red"/></body></worldbody>',
    )
    expected = mujoco.MjModel.from_xml_string(by_hand)
    np.testing.assert_allclose(scene.body_quat, expected.body_quat, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(scene.geom_matid, expected.geom_matid)
    assert "<keyframe" not in dumps(attach(loads(PARENT), loads(CHILD)))
