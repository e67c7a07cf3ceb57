"""Sensors of the whole model, tactile arrays, user sensors and sensor plugins."""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import integer, number, text
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

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/e_potential",)


@node
class EKinetic(NoisySensor):
    """Kinetic energy."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/e_kinetic",)


@node
class Clock(NoisySensor):
    """Simulation time."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/clock",)


@node
class Tactile(SampledSensor):
    """Tactile sensor over a mesh."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tactile",)
    #: MJCF attribute ``geom``; see the MuJoCo XML reference.
    geom: str | None = text()
    #: Name of the mesh asset.
    mesh: str | None = text()


@node
class UserSensor(SensorElement):
    """A sensor computed by user callbacks."""

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
    objname: str | None = text()
    #: Type of the referenced object.
    objtype: str | None = text()


@node
class SensorPlugin(SensorElement):
    """A sensor implemented by a plugin."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/plugin",)
    #: Name of the plugin instance.
    instance: str | None = text()
    #: Name of the referenced object.
    objname: str | None = text()
    #: Type of the referenced object.
    objtype: str | None = text()
    #: Identifier of the plugin library.
    plugin: str | None = text()
    #: Name of the reference frame object.
    refname: str | None = text()
    #: Type of the reference frame object.
    reftype: str | None = text()
