"""A free or mocap part attached at the world, unmoved, keeps its key values bit for bit.

With no placement there is nothing to move: each value of the part's key is the
one MuJoCo compiles for the part alone, signed zeros included (``-0`` in a key
stays ``-0``). MuJoCo is the referee: the part compiled alone.
"""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import attach, compiled
from serializers import loads

#: A free body and a mocap body whose key writes negative zeros.
PART = """<mujoco>
  <worldbody>
    <body pos="0 0 1"><freejoint/><geom size=".1"/></body>
    <body mocap="true" pos="1 1 0"/>
  </worldbody>
  <keyframe><key name="k" qpos="-0 0 2 1 -0 0 0" mpos="-0 2 0"/></keyframe>
</mujoco>
"""


def test_a_part_attached_unmoved_keeps_its_keys_bit_for_bit() -> None:
    """At the world with no placement, key ``qpos`` and ``mpos`` equal MuJoCo's exactly."""
    alone = mujoco.MjModel.from_xml_string(PART)
    assert np.signbit(alone.key_qpos[0][0]) and np.signbit(alone.key_mpos[0][0])
    scene = compiled(attach(loads("<mujoco/>"), loads(PART), prefix="c_"))
    key = scene.key("c_k")
    assert key.qpos.tobytes() == alone.key_qpos[0].tobytes()
    assert key.mpos.tobytes() == alone.key_mpos[0].tobytes()
    assert key.mquat.tobytes() == alone.key_mquat[0].tobytes()
