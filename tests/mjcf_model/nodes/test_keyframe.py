"""Tests of ``mjcf_model.nodes.keyframe``: stored states and their typed view."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Keyframe
from mjcf_model.serializers import loads
from tests.support.node_classes import loaded_from, text_round_trip_differences

#: Three keys of a slide and a hinge, one unnamed, one with a control.
KEYS = """<mujoco>
  <worldbody>
    <body><joint type="slide"/><joint name="j"/><geom size="0.1"/></body>
  </worldbody>
  <actuator><motor joint="j"/></actuator>
  <keyframe>
    <key name="low" qpos="0.1 0.2"/>
    <key qpos="0.3 0.4" time="2"/>
    <key name="pushed" qpos="0 1" ctrl="0.5"/>
  </keyframe>
</mujoco>
"""


def test_keys_follow_document_order_and_hold_mujocos_values() -> None:
    """``keys`` lists the keys as MuJoCo numbers them, each with the values MuJoCo stores."""
    keyframe = loads(KEYS).keyframe
    assert isinstance(keyframe, Keyframe)
    compiled = mujoco.MjModel.from_xml_string(KEYS)
    assert [k.name or "" for k in keyframe.keys] == [
        compiled.key(i).name for i in range(compiled.nkey)
    ]
    for index, key in enumerate(keyframe.keys):
        assert np.array_equal(key.qpos, compiled.key_qpos[index])
    assert keyframe.keys[1].time == compiled.key_time[1]
    assert keyframe.keys[2].ctrl == (compiled.key_ctrl[2][0],)
    assert loaded_from(loads(KEYS), "mjcf_model.nodes.keyframe") == {"Keyframe", "Key"}
    assert text_round_trip_differences(KEYS) == []
