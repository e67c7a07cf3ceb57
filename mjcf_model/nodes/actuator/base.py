"""The ``<actuator>`` section, the attributes every actuator shares, and ``<general>``."""

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
    text,
    vec2,
)
from mjcf_model.schema.keywords import LIMITED
from mjcf_model.values import Floats

__all__ = [
    "Actuator",
    "ActuatorElement",
    "General",
    "TransmissionActuator",
]


@node
class Actuator(TypedElement):
    """Section of actuators."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator",)


@node
class ActuatorElement(TypedElement):
    """Fields every actuator element shares."""

    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")
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
    cranksite: str | None = text()
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = numbers()
    #: Gear ratio(s) of the transmission.
    gear: Floats | None = numbers()
    #: Name of the joint.
    joint: str | None = text()
    #: Name of the joint in the parent frame (for ball-joint transmissions).
    jointinparent: str | None = text()
    #: Range of the actuator length.
    lengthrange: Floats | None = vec2()
    #: Name of the slider site of a slider-crank.
    slidersite: str | None = text()
    #: Name of the tendon.
    tendon: str | None = text()


@node
class General(TransmissionActuator):
    """A general actuator with configurable dynamics, gain and bias."""

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
    body: str | None = text()
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
    refsite: str | None = text()
    #: Name of the site.
    site: str | None = text()
    #: Range of the velocity.
    velrange: Floats | None = vec2()
