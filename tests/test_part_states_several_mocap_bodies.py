"""Keys of a placed part with several mocap bodies and a free joint between other joints.

Each mocap body's key pose and the free joint's key pose and linear velocity
move with the placement, entry by entry, whatever their place in the arrays;
the other joints' values stay. MuJoCo is the referee: the part compiled alone,
moved with MuJoCo's quaternion functions (``tests/support/composition_oracle.py``).
"""

from __future__ import annotations

import mujoco

from mjcf_model import attach, compiled
from serializers import loads
from tests.support.composition_oracle import PlacedPart, composition_problems

#: A hinge, a free body and a slide (the free joint's entries are in the middle of
#: ``qpos`` and ``qvel``), then three mocap bodies, each with its own key pose.
PART = """<mujoco>
  <worldbody>
    <body name="first"><joint name="h0"/><geom size=".1"/></body>
    <body name="floater" pos="0 0 1"><freejoint name="free"/><geom size=".1"/></body>
    <body name="last" pos="2 0 0"><joint name="s0" type="slide"/><geom size=".1"/></body>
    <body name="m0" mocap="true" pos="1 0 0"/>
    <body name="m1" mocap="true" pos="0 1 0" quat="0 0 0 1"/>
    <body name="m2" mocap="true" pos="0 0 1" euler="30 0 0"/>
  </worldbody>
  <keyframe>
    <key name="home" qpos="0.3 1 2 3 0 1 0 0 0.2" qvel="0.5 1 2 3 0.1 0.2 0.3 0.4"
         mpos="1 2 3 4 5 6 7 8 9" mquat="1 0 0 0 0 1 0 0 0 0 1 0"/>
  </keyframe>
</mujoco>
"""
#: A placement that turns and shifts (90 degrees about z, then a shift).
PLACE = {"pos": (0.5, -1.0, 2.0), "quat": (0.7071067811865476, 0.0, 0.0, 0.7071067811865476)}


def test_every_mocap_body_and_a_free_joint_among_others_move_with_the_placement() -> None:
    """Each of three mocap bodies and a mid-array free joint are moved; other entries stay."""
    scene = compiled(attach(loads("<mujoco/>"), loads(PART), prefix="c_", **PLACE))  # type: ignore[arg-type]
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string("<mujoco/>")),
        PlacedPart(mujoco.MjModel.from_xml_string(PART), "c_", **PLACE),  # type: ignore[arg-type]
    ]
    assert scene.nkey == 1
    assert composition_problems(parts, scene) == []
