"""Tests of ``mjcf_model.nodes.sensor.frames``: sensors of a frame, a subtree or a pair."""

from __future__ import annotations

import mujoco

from mjcf_model import FrameQuat, SubtreeCom
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

MECHANICS = FIXTURES / "mechanics.xml"
MODULE = "mjcf_model.nodes.sensor.frames"


def test_frame_sensors_read_the_objects_and_frames_mujoco_compiles() -> None:
    """Object and reference types and names are the ones MuJoCo's sensor arrays hold."""
    model = load(MECHANICS)
    found = loaded_from(model, MODULE)
    assert {"FramePos", "FrameQuat", "FrameLinVel", "SubtreeCom", "Distance"} <= found
    assert found <= declared_in(MODULE)
    compiled = mujoco.MjModel.from_xml_path(str(MECHANICS))
    sensors = {s.name: s for s in model.sensor.elements}
    quat, com = sensors["block_quat"], sensors["arm_com"]
    assert isinstance(quat, FrameQuat) and isinstance(com, SubtreeCom)
    assert quat.objtype == "body" and quat.reftype == "body"
    assert compiled.sensor("block_quat").objtype[0] == mujoco.mjtObj.mjOBJ_BODY
    assert compiled.sensor("block_quat").objid[0] == compiled.body(quat.objname).id
    assert compiled.sensor("block_quat").refid[0] == compiled.body(quat.refname).id
    assert compiled.sensor("arm_com").objid[0] == compiled.body(com.body).id
    assert text_round_trip_differences(MECHANICS.read_text()) == []
