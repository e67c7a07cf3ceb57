"""The ``<sensor>`` section and the attributes every sensor element shares."""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import integer, number, numbers, text
from mjcf_model.values import Floats

__all__ = [
    "NoisySensor",
    "SampledSensor",
    "Sensor",
    "SensorElement",
]


@node
class Sensor(TypedElement):
    """Section of sensors."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor",)


@node
class SensorElement(TypedElement):
    """Fields every sensor element shares."""

    #: Name, unique within its namespace.
    name: str | None = text()
    #: Cutoff (spot angle for lights; output clamp for sensors).
    cutoff: float | None = number()
    #: Custom user data (numbers).
    user: Floats | None = numbers()


@node
class SampledSensor(SensorElement):
    """Sensors with delay and sampling settings."""

    #: Delay, in time units.
    delay: float | None = number()
    #: Interpolation of delayed values.
    interp: str | None = text()
    #: Sampling interval (and phase).
    interval: Floats | None = numbers()
    #: Number of samples kept for delays.
    nsample: int | None = integer()


@node
class NoisySensor(SampledSensor):
    """Sampled sensors that declare a noise level."""

    #: Standard deviation of noise (informational).
    noise: float | None = number()
