"""Sensors that read a frame, a subtree, or a pair of geoms or bodies."""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import integer, text
from mjcf_model.nodes.sensor.base import NoisySensor

__all__ = [
    "ContactSensor",
    "Distance",
    "FrameAngAcc",
    "FrameAngVel",
    "FrameLinAcc",
    "FrameLinVel",
    "FramePos",
    "FrameQuat",
    "FrameSensor",
    "FrameXAxis",
    "FrameYAxis",
    "FrameZAxis",
    "FromTo",
    "GeomPairSensor",
    "InsideSite",
    "Normal",
    "ObjectSensor",
    "SubtreeAngMom",
    "SubtreeCom",
    "SubtreeLinVel",
    "SubtreeSensor",
]


@node
class ObjectSensor(NoisySensor):
    """Sensors that read a frame of an object of any type."""

    #: Name of the referenced object.
    objname: str | None = text()
    #: Type of the referenced object.
    objtype: str | None = text()


@node
class FrameSensor(ObjectSensor):
    """Frame sensors that may report relative to another frame."""

    #: Name of the reference frame object.
    refname: str | None = text()
    #: Type of the reference frame object.
    reftype: str | None = text()


@node
class FramePos(FrameSensor):
    """Position of an object's frame."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framepos",)


@node
class FrameQuat(FrameSensor):
    """Orientation of an object's frame."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framequat",)


@node
class FrameXAxis(FrameSensor):
    """X axis of an object's frame."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framexaxis",)


@node
class FrameYAxis(FrameSensor):
    """Y axis of an object's frame."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/frameyaxis",)


@node
class FrameZAxis(FrameSensor):
    """Z axis of an object's frame."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framezaxis",)


@node
class FrameLinVel(FrameSensor):
    """Linear velocity of an object's frame."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framelinvel",)


@node
class FrameAngVel(FrameSensor):
    """Angular velocity of an object's frame."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/frameangvel",)


@node
class FrameLinAcc(ObjectSensor):
    """Linear acceleration of an object's frame."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framelinacc",)


@node
class FrameAngAcc(ObjectSensor):
    """Angular acceleration of an object's frame."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/frameangacc",)


@node
class SubtreeSensor(NoisySensor):
    """Sensors that read the subtree rooted at a body."""

    #: Name of the body.
    body: str | None = text()


@node
class SubtreeCom(SubtreeSensor):
    """Centre of mass of a subtree."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/subtreecom",)


@node
class SubtreeLinVel(SubtreeSensor):
    """Linear velocity of a subtree's centre of mass."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/subtreelinvel",)


@node
class SubtreeAngMom(SubtreeSensor):
    """Angular momentum of a subtree."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/subtreeangmom",)


@node
class InsideSite(ObjectSensor):
    """Whether an object is inside a site's volume."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/insidesite",)
    #: Which objects count as enclosed.
    enclosed: str | None = text()
    #: Name of the site.
    site: str | None = text()


@node
class GeomPairSensor(NoisySensor):
    """Sensors that measure between two geoms or bodies."""

    #: Name of the first body.
    body1: str | None = text()
    #: Name of the second body.
    body2: str | None = text()
    #: Name of the first geom.
    geom1: str | None = text()
    #: Name of the second geom.
    geom2: str | None = text()


@node
class Distance(GeomPairSensor):
    """Distance between two geoms or bodies."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/distance",)


@node
class Normal(GeomPairSensor):
    """Normal between two geoms or bodies."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/normal",)


@node
class FromTo(GeomPairSensor):
    """Segment between the nearest points of two geoms or bodies."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/fromto",)


@node
class ContactSensor(GeomPairSensor):
    """Contacts matching a filter."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/contact",)
    #: Data values.
    data: str | None = text()
    #: Number of contacts reported.
    num: int | None = integer()
    #: How contacts are reduced.
    reduce: str | None = text()
    #: Name of the site.
    site: str | None = text()
    #: Name of the root body of the first subtree.
    subtree1: str | None = text()
    #: Name of the root body of the second subtree.
    subtree2: str | None = text()
