"""MuJoCo's actuator shortcuts (``<motor>``, ``<position>``...): ``<general>`` with parameters."""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.actuator.base import TransmissionActuator
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import (
    keyword,
    number,
    numbers,
    text,
    vec2,
    vec3,
)
from mjcf_model.schema.keywords import LIMITED
from mjcf_model.values import Floats

__all__ = [
    "Cylinder",
    "Damper",
    "DcMotor",
    "IntVelocity",
    "Motor",
    "Muscle",
    "Pid",
    "Position",
    "Velocity",
]


@node
class Motor(TransmissionActuator):
    """A direct-drive motor."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/motor", "default/motor")
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = text()
    #: Name of the site.
    site: str | None = text()


@node
class Position(TransmissionActuator):
    """A position servo."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/position", "default/position")
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: Damping ratio (instead of ``kv``).
    dampratio: float | None = number()
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Scale for inheriting the control range from the joint range.
    inheritrange: str | None = text()
    #: Position gain.
    kp: float | None = number()
    #: Velocity gain.
    kv: float | None = number()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = text()
    #: Name of the site.
    site: str | None = text()
    #: Time constant(s).
    timeconst: float | None = number()


@node
class Velocity(TransmissionActuator):
    """A velocity servo."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/velocity", "default/velocity")
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Velocity gain.
    kv: float | None = number()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = text()
    #: Name of the site.
    site: str | None = text()


@node
class IntVelocity(TransmissionActuator):
    """An integrated-velocity servo."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/intvelocity", "default/intvelocity")
    #: Whether the activation is clamped: ``true``, ``false`` or ``auto``.
    actlimited: str | None = keyword(LIMITED)
    #: Range of the activation.
    actrange: Floats | None = vec2()
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: Damping ratio (instead of ``kv``).
    dampratio: float | None = number()
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Scale for inheriting the control range from the joint range.
    inheritrange: str | None = text()
    #: Position gain.
    kp: float | None = number()
    #: Velocity gain.
    kv: float | None = number()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = text()
    #: Name of the site.
    site: str | None = text()


@node
class Pid(TransmissionActuator):
    """A PID controller."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/pid", "default/pid")
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: Damping ratio (instead of ``kv``).
    dampratio: float | None = number()
    #: Range of the feed-forward term.
    ffrange: Floats | None = numbers()
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Bound of the integral term.
    imax: float | None = number()
    #: Scale for inheriting the control range from the joint range.
    inheritrange: str | None = text()
    #: Input mode of the controller.
    input: str | None = text()
    #: Integral gain.
    ki: float | None = number()
    #: Position gain.
    kp: float | None = number()
    #: Velocity gain.
    kv: float | None = number()
    #: Range of the position error.
    posrange: Floats | None = numbers()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = text()
    #: Name of the site.
    site: str | None = text()
    #: Maximum rate of change of the control.
    slewmax: float | None = number()
    #: Range of the velocity.
    velrange: Floats | None = vec2()


@node
class Damper(TransmissionActuator):
    """An active damper."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/damper", "default/damper")
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Velocity gain.
    kv: float | None = number()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = text()
    #: Name of the site.
    site: str | None = text()


@node
class Cylinder(TransmissionActuator):
    """A pneumatic or hydraulic cylinder."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/cylinder", "default/cylinder")
    #: Cylinder area.
    area: float | None = number()
    #: Cylinder bias parameters.
    bias: Floats | None = vec3()
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: Cylinder diameter (instead of ``area``).
    diameter: float | None = number()
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = text()
    #: Name of the site.
    site: str | None = text()
    #: Time constant(s).
    timeconst: float | None = number()


@node
class Muscle(TransmissionActuator):
    """A muscle."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/muscle", "default/muscle")
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: Peak force.
    force: float | None = number()
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Passive force at lmax.
    fpmax: float | None = number()
    #: Active force at saturating lengthening velocity.
    fvmax: float | None = number()
    #: Upper bound of the operating range.
    lmax: float | None = number()
    #: Lower bound of the operating range.
    lmin: float | None = number()
    #: Lower and upper limits.
    range: Floats | None = vec2()
    #: Scale factor(s).
    scale: float | None = number()
    #: Smoothing width of the activation time constant.
    tausmooth: float | None = number()
    #: Time constant(s).
    timeconst: Floats | None = vec2()
    #: Shortening velocity at which force drops to zero.
    vmax: float | None = number()


@node
class DcMotor(TransmissionActuator):
    """A DC motor model."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/dcmotor", "default/dcmotor")
    #: MJCF attribute ``cogging``; see the MuJoCo XML reference.
    cogging: str | None = text()
    #: MJCF attribute ``controller``; see the MuJoCo XML reference.
    controller: str | None = text()
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: MJCF attribute ``inductance``; see the MuJoCo XML reference.
    inductance: str | None = text()
    #: Input mode of the controller.
    input: str | None = text()
    #: MJCF attribute ``lugre``; see the MuJoCo XML reference.
    lugre: str | None = text()
    #: MJCF attribute ``motorconst``; see the MuJoCo XML reference.
    motorconst: str | None = text()
    #: MJCF attribute ``nominal``; see the MuJoCo XML reference.
    nominal: str | None = text()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = text()
    #: MJCF attribute ``resistance``; see the MuJoCo XML reference.
    resistance: str | None = text()
    #: MJCF attribute ``saturation``; see the MuJoCo XML reference.
    saturation: str | None = text()
    #: Name of the site.
    site: str | None = text()
    #: MJCF attribute ``thermal``; see the MuJoCo XML reference.
    thermal: str | None = text()
