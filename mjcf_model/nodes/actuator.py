"""The ``<actuator>`` section: one class per actuator element.

>>> Position(name="servo", joint="elbow", kp=100).kp
100.0
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.keywords import LIMITED
from mjcf_model.values import (
    Floats,
    float_key,
    one_of,
    to_bool,
    to_float,
    to_floats,
    to_int,
    to_str,
    to_vec2,
    to_vec3,
)

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


@attrs.frozen(kw_only=True, repr=False)
class Actuator(TypedElement):
    """Section of actuators."""

    tag: ClassVar[str] = "actuator"


@attrs.frozen(kw_only=True, repr=False)
class ActuatorElement(TypedElement):
    """Fields every actuator element shares."""

    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})
    #: Range of the control.
    ctrlrange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Delay, in time units.
    delay: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Integer group, used for visualization filters and by convention.
    group: int | None = attrs.field(default=None, converter=to_int)
    #: Interpolation of delayed values.
    interp: str | None = attrs.field(default=None, converter=to_str)
    #: Number of samples kept for delays.
    nsample: int | None = attrs.field(default=None, converter=to_int)
    #: Custom user data (numbers).
    user: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class TransmissionActuator(ActuatorElement):
    """Actuators that drive a joint, tendon, site or slider-crank transmission."""

    #: Armature inertia added to the degree of freedom.
    armature: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Length of the slider-crank rod.
    cranklength: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the crank site of a slider-crank.
    cranksite: str | None = attrs.field(default=None, converter=to_str)
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Gear ratio(s) of the transmission.
    gear: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Name of the joint.
    joint: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the joint in the parent frame (for ball-joint transmissions).
    jointinparent: str | None = attrs.field(default=None, converter=to_str)
    #: Range of the actuator length.
    lengthrange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Name of the slider site of a slider-crank.
    slidersite: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the tendon.
    tendon: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class General(TransmissionActuator):
    """A general actuator with configurable dynamics, gain and bias."""

    tag: ClassVar[str] = "general"
    #: Dimension of the activation state.
    actdim: int | None = attrs.field(default=None, converter=to_int)
    #: Whether force uses the activation of the next step.
    actearly: bool | None = attrs.field(default=None, converter=to_bool)
    #: Whether the activation is clamped: ``true``, ``false`` or ``auto``.
    actlimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Range of the activation.
    actrange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Bias parameters.
    biasprm: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Bias type.
    biastype: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the body.
    body: str | None = attrs.field(default=None, converter=to_str)
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Activation dynamics parameters.
    dynprm: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Activation dynamics type.
    dyntype: str | None = attrs.field(default=None, converter=to_str)
    #: Range of the feed-forward term.
    ffrange: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Gain parameters.
    gainprm: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Gain type.
    gaintype: str | None = attrs.field(default=None, converter=to_str)
    #: Scale for inheriting the control range from the joint range.
    inheritrange: str | None = attrs.field(default=None, converter=to_str)
    #: Input mode of the controller.
    input: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)
    #: Range of the velocity.
    velrange: Floats | None = attrs.field(default=None, converter=to_vec2)


@attrs.frozen(kw_only=True, repr=False)
class Motor(TransmissionActuator):
    """A direct-drive motor."""

    tag: ClassVar[str] = "motor"
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Position(TransmissionActuator):
    """A position servo."""

    tag: ClassVar[str] = "position"
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Damping ratio (instead of ``kv``).
    dampratio: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Scale for inheriting the control range from the joint range.
    inheritrange: str | None = attrs.field(default=None, converter=to_str)
    #: Position gain.
    kp: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Velocity gain.
    kv: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)
    #: Time constant(s).
    timeconst: float | None = attrs.field(default=None, converter=to_float, eq=float_key)


@attrs.frozen(kw_only=True, repr=False)
class Velocity(TransmissionActuator):
    """A velocity servo."""

    tag: ClassVar[str] = "velocity"
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Velocity gain.
    kv: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class IntVelocity(TransmissionActuator):
    """An integrated-velocity servo."""

    tag: ClassVar[str] = "intvelocity"
    #: Whether the activation is clamped: ``true``, ``false`` or ``auto``.
    actlimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Range of the activation.
    actrange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Damping ratio (instead of ``kv``).
    dampratio: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Scale for inheriting the control range from the joint range.
    inheritrange: str | None = attrs.field(default=None, converter=to_str)
    #: Position gain.
    kp: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Velocity gain.
    kv: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Pid(TransmissionActuator):
    """A PID controller."""

    tag: ClassVar[str] = "pid"
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Damping ratio (instead of ``kv``).
    dampratio: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Range of the feed-forward term.
    ffrange: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Bound of the integral term.
    imax: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Scale for inheriting the control range from the joint range.
    inheritrange: str | None = attrs.field(default=None, converter=to_str)
    #: Input mode of the controller.
    input: str | None = attrs.field(default=None, converter=to_str)
    #: Integral gain.
    ki: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Position gain.
    kp: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Velocity gain.
    kv: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Range of the position error.
    posrange: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)
    #: Maximum rate of change of the control.
    slewmax: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Range of the velocity.
    velrange: Floats | None = attrs.field(default=None, converter=to_vec2)


@attrs.frozen(kw_only=True, repr=False)
class Damper(TransmissionActuator):
    """An active damper."""

    tag: ClassVar[str] = "damper"
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Velocity gain.
    kv: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Cylinder(TransmissionActuator):
    """A pneumatic or hydraulic cylinder."""

    tag: ClassVar[str] = "cylinder"
    #: Cylinder area.
    area: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Cylinder bias parameters.
    bias: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Cylinder diameter (instead of ``area``).
    diameter: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)
    #: Time constant(s).
    timeconst: float | None = attrs.field(default=None, converter=to_float, eq=float_key)


@attrs.frozen(kw_only=True, repr=False)
class Muscle(TransmissionActuator):
    """A muscle."""

    tag: ClassVar[str] = "muscle"
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Peak force.
    force: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Passive force at lmax.
    fpmax: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Active force at saturating lengthening velocity.
    fvmax: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Upper bound of the operating range.
    lmax: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Lower bound of the operating range.
    lmin: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Lower and upper limits.
    range: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Scale factor(s).
    scale: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Smoothing width of the activation time constant.
    tausmooth: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Time constant(s).
    timeconst: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Shortening velocity at which force drops to zero.
    vmax: float | None = attrs.field(default=None, converter=to_float, eq=float_key)


@attrs.frozen(kw_only=True, repr=False)
class DcMotor(TransmissionActuator):
    """A DC motor model."""

    tag: ClassVar[str] = "dcmotor"
    #: MJCF attribute ``cogging``; see the MuJoCo XML reference.
    cogging: str | None = attrs.field(default=None, converter=to_str)
    #: MJCF attribute ``controller``; see the MuJoCo XML reference.
    controller: str | None = attrs.field(default=None, converter=to_str)
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: MJCF attribute ``inductance``; see the MuJoCo XML reference.
    inductance: str | None = attrs.field(default=None, converter=to_str)
    #: Input mode of the controller.
    input: str | None = attrs.field(default=None, converter=to_str)
    #: MJCF attribute ``lugre``; see the MuJoCo XML reference.
    lugre: str | None = attrs.field(default=None, converter=to_str)
    #: MJCF attribute ``motorconst``; see the MuJoCo XML reference.
    motorconst: str | None = attrs.field(default=None, converter=to_str)
    #: MJCF attribute ``nominal``; see the MuJoCo XML reference.
    nominal: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = attrs.field(default=None, converter=to_str)
    #: MJCF attribute ``resistance``; see the MuJoCo XML reference.
    resistance: str | None = attrs.field(default=None, converter=to_str)
    #: MJCF attribute ``saturation``; see the MuJoCo XML reference.
    saturation: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)
    #: MJCF attribute ``thermal``; see the MuJoCo XML reference.
    thermal: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class ActuatorPlugin(TransmissionActuator):
    """An actuator implemented by a plugin."""

    tag: ClassVar[str] = "plugin"
    #: Dimension of the activation state.
    actdim: int | None = attrs.field(default=None, converter=to_int)
    #: Whether force uses the activation of the next step.
    actearly: bool | None = attrs.field(default=None, converter=to_bool)
    #: Whether the activation is clamped: ``true``, ``false`` or ``auto``.
    actlimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Range of the activation.
    actrange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Activation dynamics parameters.
    dynprm: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Activation dynamics type.
    dyntype: str | None = attrs.field(default=None, converter=to_str)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Name of the plugin instance.
    instance: str | None = attrs.field(default=None, converter=to_str)
    #: Identifier of the plugin library.
    plugin: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Orientation(ActuatorElement):
    """An orientation servo."""

    tag: ClassVar[str] = "orientation"
    #: Damping ratio (instead of ``kv``).
    dampratio: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Input mode of the controller.
    input: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the joint.
    joint: str | None = attrs.field(default=None, converter=to_str)
    #: Position gain.
    kp: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Velocity gain.
    kv: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Adhesion(ActuatorElement):
    """An adhesion actuator."""

    tag: ClassVar[str] = "adhesion"
    #: Name of the body.
    body: str | None = attrs.field(default=None, converter=to_str)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the force.
    forcerange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Gain of the adhesion force.
    gain: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
