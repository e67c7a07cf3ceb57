"""Keys of a free part attached inside a frame of a parent written in radians and ``zyx`` angles.

The key poses move by the frame's world pose, with the frame's ``euler`` read as
MuJoCo reads it under the parent's ``<compiler angle eulerseq>``. MuJoCo is the
referee: the parent compiled alone gives the site's world pose, the part compiled
alone gives its key (``tests/support/composition_oracle.py``).
"""

from __future__ import annotations

import mujoco

from mjcf_model import attach, compiled
from serializers import loads
from tests.support.composition_oracle import PlacedPart, composition_problems

#: A parent in radians with ``zyx`` Euler angles, and a site inside a turned frame.
PARENT = """<mujoco>
  <compiler angle="radian" eulerseq="zyx"/>
  <worldbody>
    <frame pos="1 2 3" euler="0.3 0.5 0.7"><site name="s"/></frame>
  </worldbody>
</mujoco>
"""
#: A free body with a key that sets its pose and velocity.
PART = """<mujoco>
  <worldbody>
    <body name="box" pos="0.1 0.2 0.3"><freejoint name="free"/><geom size=".1"/></body>
  </worldbody>
  <keyframe><key name="thrown" qpos="1 -2 0.5 0 1 0 0" qvel="1 2 3 0 0 1"/></keyframe>
</mujoco>
"""


def test_keys_move_by_a_frame_read_in_the_parents_angle_units_and_euler_sequence() -> None:
    """A frame's radian ``zyx`` Euler angles place the part's keys where MuJoCo places the site."""
    scene = compiled(attach(loads(PARENT), loads(PART), at="s", prefix="c_"))
    parent = mujoco.MjModel.from_xml_string(PARENT)
    site = parent.site("s")
    placed = PlacedPart(
        mujoco.MjModel.from_xml_string(PART),
        "c_",
        pos=tuple(float(v) for v in site.pos),
        quat=tuple(float(v) for v in site.quat),
    )
    assert scene.nkey == 1
    assert composition_problems([PlacedPart(parent), placed], scene) == []
