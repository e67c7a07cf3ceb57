"""keyframes='merged': a child key of the parent's key name joins it, with or without a prefix.

Under the merged policy keys of one name are one key, so a child attached
without a prefix whose key has the parent's key name is not a name clash; a
child without keys, or a parent without named keys, are composed as usual.
Expected values come from MuJoCo compiling each part alone.
"""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import attach, compiled
from serializers import loads

PARENT = """<mujoco>
  <worldbody><body name="base"><joint name="yaw"/><geom size=".1"/></body></worldbody>
  <keyframe><key name="home" qpos="0.5"/></keyframe>
</mujoco>
"""
#: A part whose hinge starts away from zero (``ref``), with a key named like the parent's.
CHILD = """<mujoco>
  <worldbody><body name="arm"><joint name="bend" ref="20"/><geom size=".1"/></body></worldbody>
  <keyframe><key name="home" qpos="0.25"/></keyframe>
</mujoco>
"""
KEYLESS = """<mujoco>
  <worldbody><body name="arm"><joint name="bend" ref="20"/><geom size=".1"/></body></worldbody>
</mujoco>
"""
#: A parent with a joint and no keyframes.
UNKEYED = """<mujoco>
  <worldbody><body name="base"><joint name="yaw" ref="10"/><geom size=".1"/></body></worldbody>
</mujoco>
"""


def _alone(text: str) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(text)


def test_a_child_key_of_the_parents_name_joins_it_without_a_prefix() -> None:
    """Without a prefix, the child's ``home`` and the parent's are one key holding both."""
    scene = compiled(attach(loads(PARENT), loads(CHILD), keyframes="merged"))
    assert scene.nkey == 1
    expected = np.concatenate([_alone(PARENT).key("home").qpos, _alone(CHILD).key("home").qpos])
    np.testing.assert_allclose(scene.key("home").qpos, expected)


def test_a_child_without_keys_is_merged_into_the_parents_keys() -> None:
    """Under the merged policy a keyless child adds its initial state to the parent's key."""
    scene = compiled(attach(loads(PARENT), loads(KEYLESS), keyframes="merged"))
    assert scene.nkey == 1
    expected = np.concatenate([_alone(PARENT).key("home").qpos, _alone(KEYLESS).qpos0])
    np.testing.assert_allclose(scene.key("home").qpos, expected)


def test_a_child_key_joins_a_parent_without_keys() -> None:
    """Into a parent without keys, the child's key is kept, the parent's entries at ``qpos0``."""
    scene = compiled(attach(loads(UNKEYED), loads(CHILD), prefix="c_", keyframes="merged"))
    assert scene.nkey == 1
    expected = np.concatenate([_alone(UNKEYED).qpos0, _alone(CHILD).key("home").qpos])
    np.testing.assert_allclose(scene.key_qpos[0], expected)
