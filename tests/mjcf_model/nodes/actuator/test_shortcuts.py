"""Tests of ``mjcf_model.nodes.actuator.shortcuts``: ``<motor>``, ``<position>``, ``<muscle>``..."""

from __future__ import annotations

import mujoco

from mjcf_model import Motor, Muscle, Position
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

MECHANICS = FIXTURES / "mechanics.xml"
MODULE = "mjcf_model.nodes.actuator.shortcuts"


def test_shortcuts_load_typed_and_their_parameters_are_mujocos() -> None:
    """Each shortcut's own parameters are what MuJoCo makes of them in ``<general>`` terms."""
    model = load(MECHANICS)
    found = loaded_from(model, MODULE)
    assert found == {"Motor", "Position", "Velocity", "Muscle", "Cylinder", "Damper", "IntVelocity"}
    assert found <= declared_in(MODULE)
    compiled = mujoco.MjModel.from_xml_path(str(MECHANICS))
    actuators = {a.name: a for a in model.actuator.elements}
    motor, position, muscle = (
        actuators["shoulder_motor"],
        actuators["elbow_pos"],
        actuators["biceps_muscle"],
    )
    assert isinstance(motor, Motor) and isinstance(position, Position)
    assert isinstance(muscle, Muscle)
    assert motor.gear == (compiled.actuator("shoulder_motor").gear[0],)
    assert position.kp == compiled.actuator("elbow_pos").gainprm[0]
    assert -position.kp == compiled.actuator("elbow_pos").biasprm[1]
    assert muscle.force == compiled.actuator("biceps_muscle").gainprm[2]
    assert muscle.lmin == compiled.actuator("biceps_muscle").gainprm[4]
    assert text_round_trip_differences(MECHANICS.read_text()) == []
