"""The ``<actuator>`` section: one class per actuator element.

>>> Position(name="servo", joint="elbow", kp=100).kp
100.0
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import (
    boolean,
    integer,
    keyword,
    number,
    numbers,
    reference,
    text,
    vec2,
    vec3,
)
from mjcf_model.schema.keywords import LIMITED
from mjcf_model.values import Floats

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


@node
class Actuator(TypedElement):
    """Section of actuators."""

    tag: ClassVar[str] = "actuator"
    schema_keys: ClassVar[tuple[str, ...]] = ("actuator",)


@node
class ActuatorElement(TypedElement):
    """Fields every actuator element shares."""

    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = reference("class", xml="class")
    #: Range of the control.
    ctrlrange: Floats | None = vec2()
    #: Delay, in time units.
    delay: float | None = number()
    #: Integer group, used for visualization filters and by convention.
    group: int | None = integer()
    #: Interpolation of delayed values.
    interp: str | None = text()
    #: Number of samples kept for delays.
    nsample: int | None = integer()
    #: Custom user data (numbers).
    user: Floats | None = numbers()


@node
class TransmissionActuator(ActuatorElement):
    """Actuators that drive a joint, tendon, site or slider-crank transmission."""

    #: Armature inertia added to the degree of freedom.
    armature: float | None = number()
    #: Length of the slider-crank rod.
    cranklength: float | None = number()
    #: Name of the crank site of a slider-crank.
    cranksite: str | None = reference("site")
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = numbers()
    #: Gear ratio(s) of the transmission.
    gear: Floats | None = numbers()
    #: Name of the joint.
    joint: str | None = reference("joint")
    #: Name of the joint in the parent frame (for ball-joint transmissions).
    jointinparent: str | None = reference("joint")
    #: Range of the actuator length.
    lengthrange: Floats | None = vec2()
    #: Name of the slider site of a slider-crank.
    slidersite: str | None = reference("site")
    #: Name of the tendon.
    tendon: str | None = reference("tendon")


@node
class General(TransmissionActuator):
    """A general actuator with configurable dynamics, gain and bias."""

    tag: ClassVar[str] = "general"
    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/general", "default/general")
    #: Dimension of the activation state.
    actdim: int | None = integer()
    #: Whether force uses the activation of the next step.
    actearly: bool | None = boolean()
    #: Whether the activation is clamped: ``true``, ``false`` or ``auto``.
    actlimited: str | None = keyword(LIMITED)
    #: Range of the activation.
    actrange: Floats | None = vec2()
    #: Bias parameters.
    biasprm: Floats | None = numbers()
    #: Bias type.
    biastype: str | None = text()
    #: Name of the body.
    body: str | None = reference("body")
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: Activation dynamics parameters.
    dynprm: Floats | None = numbers()
    #: Activation dynamics type.
    dyntype: str | None = text()
    #: Range of the feed-forward term.
    ffrange: Floats | None = numbers()
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Gain parameters.
    gainprm: Floats | None = numbers()
    #: Gain type.
    gaintype: str | None = text()
    #: Scale for inheriting the control range from the joint range.
    inheritrange: str | None = text()
    #: Input mode of the controller.
    input: str | None = text()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = reference("site")
    #: Name of the site.
    site: str | None = reference("site")
    #: Range of the velocity.
    velrange: Floats | None = vec2()


@node
class Motor(TransmissionActuator):
    """A direct-drive motor."""

    tag: ClassVar[str] = "motor"
    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/motor", "default/motor")
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = reference("site")
    #: Name of the site.
    site: str | None = reference("site")


@node
class Position(TransmissionActuator):
    """A position servo."""

    tag: ClassVar[str] = "position"
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
    refsite: str | None = reference("site")
    #: Name of the site.
    site: str | None = reference("site")
    #: Time constant(s).
    timeconst: float | None = number()


@node
class Velocity(TransmissionActuator):
    """A velocity servo."""

    tag: ClassVar[str] = "velocity"
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
    refsite: str | None = reference("site")
    #: Name of the site.
    site: str | None = reference("site")


@node
class IntVelocity(TransmissionActuator):
    """An integrated-velocity servo."""

    tag: ClassVar[str] = "intvelocity"
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
    refsite: str | None = reference("site")
    #: Name of the site.
    site: str | None = reference("site")


@node
class Pid(TransmissionActuator):
    """A PID controller."""

    tag: ClassVar[str] = "pid"
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
    refsite: str | None = reference("site")
    #: Name of the site.
    site: str | None = reference("site")
    #: Maximum rate of change of the control.
    slewmax: float | None = number()
    #: Range of the velocity.
    velrange: Floats | None = vec2()


@node
class Damper(TransmissionActuator):
    """An active damper."""

    tag: ClassVar[str] = "damper"
    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/damper", "default/damper")
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Velocity gain.
    kv: float | None = number()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = reference("site")
    #: Name of the site.
    site: str | None = reference("site")


@node
class Cylinder(TransmissionActuator):
    """A pneumatic or hydraulic cylinder."""

    tag: ClassVar[str] = "cylinder"
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
    refsite: str | None = reference("site")
    #: Name of the site.
    site: str | None = reference("site")
    #: Time constant(s).
    timeconst: float | None = number()


@node
class Muscle(TransmissionActuator):
    """A muscle."""

    tag: ClassVar[str] = "muscle"
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

    tag: ClassVar[str] = "dcmotor"
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
    refsite: str | None = reference("site")
    #: MJCF attribute ``resistance``; see the MuJoCo XML reference.
    resistance: str | None = text()
    #: MJCF attribute ``saturation``; see the MuJoCo XML reference.
    saturation: str | None = text()
    #: Name of the site.
    site: str | None = reference("site")
    #: MJCF attribute ``thermal``; see the MuJoCo XML reference.
    thermal: str | None = text()


@node
class ActuatorPlugin(TransmissionActuator):
    """An actuator implemented by a plugin."""

    tag: ClassVar[str] = "plugin"
    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/plugin",)
    #: Dimension of the activation state.
    actdim: int | None = integer()
    #: Whether force uses the activation of the next step.
    actearly: bool | None = boolean()
    #: Whether the activation is clamped: ``true``, ``false`` or ``auto``.
    actlimited: str | None = keyword(LIMITED)
    #: Range of the activation.
    actrange: Floats | None = vec2()
    #: Whether the control is clamped: ``true``, ``false`` or ``auto``.
    ctrllimited: str | None = keyword(LIMITED)
    #: Activation dynamics parameters.
    dynprm: Floats | None = numbers()
    #: Activation dynamics type.
    dyntype: str | None = text()
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Name of the plugin instance.
    instance: str | None = reference("plugin")
    #: Identifier of the plugin library.
    plugin: str | None = text()
    #: Name of the site.
    site: str | None = reference("site")


@node
class Orientation(ActuatorElement):
    """An orientation servo."""

    tag: ClassVar[str] = "orientation"
    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/orientation", "default/orientation")
    #: Damping ratio (instead of ``kv``).
    dampratio: float | None = number()
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Input mode of the controller.
    input: str | None = text()
    #: Name of the joint.
    joint: str | None = reference("joint")
    #: Position gain.
    kp: float | None = number()
    #: Velocity gain.
    kv: float | None = number()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = reference("site")
    #: Name of the site.
    site: str | None = reference("site")


@node
class Adhesion(ActuatorElement):
    """An adhesion actuator."""

    tag: ClassVar[str] = "adhesion"
    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/adhesion", "default/adhesion")
    #: Name of the body.
    body: str | None = reference("body")
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Gain of the adhesion force.
    gain: float | None = number()
