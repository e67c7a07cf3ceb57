"""Tests of ``mjcf_model.nodes.sensor.one_object``: sensors that read one object."""

from __future__ import annotations

import mujoco

from mjcf_model import JointPos, TendonPos, Touch
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

MECHANICS = FIXTURES / "mechanics.xml"
MODULE = "mjcf_model.nodes.sensor.one_object"


def test_each_sensor_reads_the_object_it_names_as_mujoco_compiles_it() -> None:
    """The object a sensor names is the one MuJoCo attaches it to, of the type it reads."""
    model = load(MECHANICS)
    found = loaded_from(model, MODULE)
    assert {"JointPos", "JointVel", "TendonPos", "Touch", "Accelerometer", "Rangefinder"} <= found
    assert found <= declared_in(MODULE)
    compiled = mujoco.MjModel.from_xml_path(str(MECHANICS))
    sensors = {s.name: s for s in model.sensor.elements}
    joint, tendon, touch = sensors["shoulder_q"], sensors["biceps_len"], sensors["hand_touch"]
    assert isinstance(joint, JointPos) and isinstance(tendon, TendonPos)
    assert isinstance(touch, Touch)
    assert compiled.sensor("shoulder_q").objid[0] == compiled.joint(joint.joint).id
    assert compiled.sensor("biceps_len").objid[0] == compiled.tendon(tendon.tendon).id
    assert compiled.sensor("hand_touch").objid[0] == compiled.site(touch.site).id
    assert compiled.sensor("hand_touch").type[0] == mujoco.mjtSensor.mjSENS_TOUCH
    assert text_round_trip_differences(MECHANICS.read_text()) == []
