"""Sensors of the whole model, tactile arrays, user sensors and sensor plugins."""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import integer, number, reference, text
from mjcf_model.nodes.sensor.base import NoisySensor, SampledSensor, SensorElement

__all__ = [
    "Clock",
    "EKinetic",
    "EPotential",
    "SensorPlugin",
    "Tactile",
    "UserSensor",
]


@node
class EPotential(NoisySensor):
    """Potential energy."""

    tag: ClassVar[str] = "e_potential"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/e_potential",)


@node
class EKinetic(NoisySensor):
    """Kinetic energy."""

    tag: ClassVar[str] = "e_kinetic"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/e_kinetic",)


@node
class Clock(NoisySensor):
    """Simulation time."""

    tag: ClassVar[str] = "clock"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/clock",)


@node
class Tactile(SampledSensor):
    """Tactile sensor over a mesh."""

    tag: ClassVar[str] = "tactile"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tactile",)
    #: MJCF attribute ``geom``; see the MuJoCo XML reference.
    geom: str | None = reference("geom")
    #: Name of the mesh asset.
    mesh: str | None = reference("mesh")


@node
class UserSensor(SensorElement):
    """A sensor computed by user callbacks."""

    tag: ClassVar[str] = "user"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/user",)
    #: Data type of the user sensor.
    datatype: str | None = text()
    #: Dimension.
    dim: int | None = integer()
    #: Computation stage the user sensor needs.
    needstage: str | None = text()
    #: Standard deviation of noise (informational).
    noise: float | None = number()
    #: Name of the referenced object.
    objname: str | None = reference("@objtype")
    #: Type of the referenced object.
    objtype: str | None = text()


@node
class SensorPlugin(SensorElement):
    """A sensor implemented by a plugin."""

    tag: ClassVar[str] = "plugin"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/plugin",)
    #: Name of the plugin instance.
    instance: str | None = reference("plugin")
    #: Name of the referenced object.
    objname: str | None = reference("@objtype")
    #: Type of the referenced object.
    objtype: str | None = text()
    #: Identifier of the plugin library.
    plugin: str | None = text()
    #: Name of the reference frame object.
    refname: str | None = reference("@reftype")
    #: Type of the reference frame object.
    reftype: str | None = text()
