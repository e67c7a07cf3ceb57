"""The values a composed key writes: zeros that are not the initial state, and nothing MuJoCo fills.

A key sets the whole state: ``qpos`` is always written, so a key holding every
joint at zero is not completed to ``qpos0``; a mocap pose differing from the
initial one is written even when it is all zeros (MuJoCo keeps a key's
``mquat`` as written). What MuJoCo would fill with the same value is left
out: velocities, controls, activations and ``time`` that are zero, and mocap
poses equal to the initial ones (``SceneKeys.nodes`` in
mjcf_model/transforms/composition/keyframes.py). Expected values come from
MuJoCo compiling each part alone (tests/support/composition_oracle.py).
"""

from __future__ import annotations

import mujoco

from mjcf_model import Mujoco, attach, compiled
from mjcf_model.nodes.base import get_attribute
from serializers import loads
from tests.support.composition_oracle import PlacedPart, composition_problems

#: A parent with no mocap body, whose hinge starts at zero.
PARENT = """<mujoco>
  <worldbody><body name="base"><joint name="yaw"/><geom size=".1"/></body></worldbody>
  <keyframe><key name="home" qpos="0.5"/></keyframe>
</mujoco>
"""
#: A part whose key sets its hinge to zero (``qpos0`` is 20 degrees) and its mocap pose to zeros.
CHILD = """<mujoco>
  <worldbody>
    <body name="arm"><joint name="bend" ref="20"/><geom size=".1"/></body>
    <body name="target" mocap="true" pos="0 1 0"><geom size=".05" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
  <keyframe><key name="zero" qpos="0" mpos="0 0 0" mquat="0 0 0 0"/></keyframe>
</mujoco>
"""


def _scene() -> Mujoco:
    return attach(loads(PARENT), loads(CHILD), prefix="c_")


def test_a_key_of_zeros_stays_zeros_in_the_scene() -> None:
    """The child's all-zero ``qpos``, ``mpos`` and ``mquat`` key is not completed to the initial."""
    scene = compiled(_scene())
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string(PARENT)),
        PlacedPart(mujoco.MjModel.from_xml_string(CHILD), "c_"),
    ]
    assert composition_problems(parts, scene) == []
    zero = scene.key("c_zero")
    assert zero.qpos.tolist() == [0.0, 0.0] and scene.qpos0[1] != 0.0
    assert zero.mpos.tolist() == [0.0] * 3 and zero.mquat.tolist() == [0.0] * 4


def test_the_parents_key_leaves_out_what_mujoco_fills_with_the_same_values() -> None:
    """The parent's ``home``: ``qpos`` written; no zero velocity, control or time, no mocap pose."""
    keyframe = _scene().keyframe
    assert keyframe is not None
    keys = {get_attribute(key, "name"): key for key in keyframe.keys}
    home, zero = keys["home"], keys["c_zero"]
    assert get_attribute(home, "qpos") is not None
    for attribute in ("qvel", "act", "ctrl", "mpos", "mquat", "time"):
        assert get_attribute(home, attribute) is None, attribute
    assert get_attribute(zero, "mpos") is not None and get_attribute(zero, "mquat") is not None
