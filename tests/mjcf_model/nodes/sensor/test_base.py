"""Tests of ``mjcf_model.nodes.sensor.base``: the ``<sensor>`` section and shared attributes."""

from __future__ import annotations

import mujoco

from mjcf_model import Sensor
from mjcf_model.nodes.sensor.base import NoisySensor, SensorElement
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

MECHANICS = FIXTURES / "mechanics.xml"


def test_the_section_and_the_attributes_every_sensor_shares_are_mujocos() -> None:
    """The section holds every sensor MuJoCo compiles; ``noise`` and ``cutoff`` are its values."""
    model = load(MECHANICS)
    assert declared_in("mjcf_model.nodes.sensor.base") == {"Sensor"}
    assert loaded_from(model, "mjcf_model.nodes.sensor.base") == {"Sensor"}
    compiled = mujoco.MjModel.from_xml_path(str(MECHANICS))
    assert isinstance(model.sensor, Sensor)
    sensors = model.sensor.elements
    assert all(isinstance(s, SensorElement) for s in sensors)
    assert [s.name for s in sensors] == [compiled.sensor(i).name for i in range(compiled.nsensor)]
    noisy = {s.name: s for s in sensors if isinstance(s, NoisySensor)}
    assert noisy["elbow_qd"].noise == compiled.sensor("elbow_qd").noise[0]
    assert {s.name: s for s in sensors}["hand_acc"].cutoff == compiled.sensor("hand_acc").cutoff[0]
    assert text_round_trip_differences(MECHANICS.read_text()) == []
