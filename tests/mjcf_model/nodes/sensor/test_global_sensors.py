"""Tests of ``mjcf_model.nodes.sensor.global_sensors``: clock, energies and user sensors."""

from __future__ import annotations

import mujoco

from mjcf_model import Clock, UserSensor
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

MECHANICS = FIXTURES / "mechanics.xml"
MODULE = "mjcf_model.nodes.sensor.global_sensors"


def test_whole_model_sensors_load_typed_and_compile_as_written() -> None:
    """A user sensor's ``dim`` is MuJoCo's sensor dimension; the clock is MuJoCo's clock."""
    model = load(MECHANICS)
    found = loaded_from(model, MODULE)
    assert found == {"Clock", "EKinetic", "EPotential", "UserSensor"}
    assert found <= declared_in(MODULE)
    compiled = mujoco.MjModel.from_xml_path(str(MECHANICS))
    sensors = {s.name: s for s in model.sensor.elements}
    user, clock = sensors["custom_sensor"], sensors["time"]
    assert isinstance(user, UserSensor) and isinstance(clock, Clock)
    assert user.dim == compiled.sensor("custom_sensor").dim[0]
    assert compiled.sensor("time").type[0] == mujoco.mjtSensor.mjSENS_CLOCK
    assert compiled.sensor("potential").type[0] == mujoco.mjtSensor.mjSENS_E_POTENTIAL
    assert text_round_trip_differences(MECHANICS.read_text()) == []
