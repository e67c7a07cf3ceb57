"""A parent's keys get a keyless child's entries: its initial state, where MuJoCo numbers them.

When only the parent has keyframes, the child still adds joints, so every
parent key is written whole again with the child's initial state spliced in
where the child's joints go. Attached inside a body that comes before another
jointed body, the child's joints sit between the parent's in ``qpos``: a key
left as the parent wrote it would hand the parent's values to the wrong
joints. MuJoCo compiling each part alone is the referee.
"""

from __future__ import annotations

import mujoco
import pytest

from mjcf_model import MjcfValueError, attach, compiled
from serializers import loads

PARENT = """<mujoco>
  <worldbody>
    <body name="table"><joint name="lift" type="slide"/><geom size=".1"/></body>
    <body name="lamp" pos="1 0 0"><joint name="swing"/><geom size=".1"/></body>
  </worldbody>
  <keyframe><key name="home" qpos="0.3 0.7"/><key name="away" qpos="-0.2 0.4"/></keyframe>
</mujoco>
"""
#: A part without keys whose hinge starts away from zero (``ref``), so its initial state shows.
CHILD = """<mujoco>
  <worldbody><body name="arm"><joint name="bend" ref="20"/><geom size=".05"/></body></worldbody>
</mujoco>
"""
FREE = (
    '<mujoco><worldbody><body name="ball"><freejoint/><geom size=".1"/></body></worldbody></mujoco>'
)


def test_a_keyless_child_inside_a_body_gets_its_initial_state_in_the_parents_keys() -> None:
    """Each parent key keeps its values joint by joint; the child's hinge is at its ``qpos0``."""
    scene = compiled(attach(loads(PARENT), loads(CHILD), at="table", prefix="c_"))
    parent = mujoco.MjModel.from_xml_string(PARENT)
    child = mujoco.MjModel.from_xml_string(CHILD)
    assert scene.nkey == parent.nkey
    for key in ("home", "away"):
        for joint in ("lift", "swing"):
            got = scene.key(key).qpos[scene.joint(joint).qposadr[0]]
            assert got == parent.key(key).qpos[parent.joint(joint).qposadr[0]], (key, joint)
        bend = scene.key(key).qpos[scene.joint("c_bend").qposadr[0]]
        assert bend == pytest.approx(child.qpos0[child.joint("bend").qposadr[0]]), key


def test_a_free_part_inside_a_body_names_the_attach_point() -> None:
    """A free-jointed part attached inside a body is refused, naming where it was to go."""
    with pytest.raises(
        MjcfValueError, match=r"free joints or mocap bodies at 'table': it is inside"
    ):
        attach(loads(PARENT), loads(FREE), at="table", prefix="c_")
