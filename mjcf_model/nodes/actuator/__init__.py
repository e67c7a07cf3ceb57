"""The ``<actuator>`` section: one class per actuator element.

>>> Position(name="servo", joint="elbow", kp=100).kp
100.0
"""

from mjcf_model.nodes.actuator.base import Actuator, ActuatorElement, General, TransmissionActuator
from mjcf_model.nodes.actuator.shortcuts import (
    Cylinder,
    Damper,
    DcMotor,
    IntVelocity,
    Motor,
    Muscle,
    Pid,
    Position,
    Velocity,
)
from mjcf_model.nodes.actuator.special import ActuatorPlugin, Adhesion, Orientation

__all__ = [
    "Actuator",
    "ActuatorElement",
    "ActuatorPlugin",
    "Adhesion",
    "Cylinder",
    "Damper",
    "DcMotor",
    "General",
    "IntVelocity",
    "Motor",
    "Muscle",
    "Orientation",
    "Pid",
    "Position",
    "TransmissionActuator",
    "Velocity",
]
