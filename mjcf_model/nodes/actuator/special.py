"""Actuators without a joint-style transmission: plugins, ``<orientation>``, ``<adhesion>``."""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.actuator.base import ActuatorElement, TransmissionActuator
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
    "ActuatorPlugin",
    "Adhesion",
    "Orientation",
]


@node
class ActuatorPlugin(TransmissionActuator):
    """An actuator implemented by a plugin."""

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
    instance: str | None = text()
    #: Identifier of the plugin library.
    plugin: str | None = text()
    #: Name of the site.
    site: str | None = text()


@node
class Orientation(ActuatorElement):
    """An orientation servo."""

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
    joint: str | None = text()
    #: Position gain.
    kp: float | None = number()
    #: Velocity gain.
    kv: float | None = number()
    #: Name of the reference site of a Cartesian transmission.
    refsite: str | None = text()
    #: Name of the site.
    site: str | None = text()


@node
class Adhesion(ActuatorElement):
    """An adhesion actuator."""

    schema_keys: ClassVar[tuple[str, ...]] = ("actuator/adhesion", "default/adhesion")
    #: Name of the body.
    body: str | None = text()
    #: Whether the force is clamped: ``true``, ``false`` or ``auto``.
    forcelimited: str | None = keyword(LIMITED)
    #: Range of the force.
    forcerange: Floats | None = vec2()
    #: Gain of the adhesion force.
    gain: float | None = number()
