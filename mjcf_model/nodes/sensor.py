"""The ``<sensor>`` section: one class per sensor element, grouped by what they read.

>>> JointPos(name="q", joint="elbow").joint
'elbow'
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.values import Floats, float_key, to_float, to_floats, to_int, to_str

__all__ = [
    "Accelerometer",
    "ActuatorFrc",
    "ActuatorPos",
    "ActuatorSensor",
    "ActuatorVel",
    "BallAngVel",
    "BallQuat",
    "CamProjection",
    "Clock",
    "ContactSensor",
    "Distance",
    "EKinetic",
    "EPotential",
    "Force",
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
    "Gyro",
    "InsideSite",
    "JointActuatorFrc",
    "JointLimitFrc",
    "JointLimitPos",
    "JointLimitVel",
    "JointPos",
    "JointSensor",
    "JointVel",
    "Magnetometer",
    "NoisySensor",
    "Normal",
    "ObjectSensor",
    "Rangefinder",
    "SampledSensor",
    "Sensor",
    "SensorElement",
    "SensorPlugin",
    "SiteSensor",
    "SubtreeAngMom",
    "SubtreeCom",
    "SubtreeLinVel",
    "SubtreeSensor",
    "Tactile",
    "TendonActuatorFrc",
    "TendonLimitFrc",
    "TendonLimitPos",
    "TendonLimitVel",
    "TendonPos",
    "TendonSensor",
    "TendonVel",
    "Torque",
    "Touch",
    "UserSensor",
    "Velocimeter",
]


@attrs.frozen(kw_only=True, repr=False)
class Sensor(TypedElement):
    """Section of sensors."""

    tag: ClassVar[str] = "sensor"


@attrs.frozen(kw_only=True, repr=False)
class SensorElement(TypedElement):
    """Fields every sensor element shares."""

    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Cutoff (spot angle for lights; output clamp for sensors).
    cutoff: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Custom user data (numbers).
    user: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class SampledSensor(SensorElement):
    """Sensors with delay and sampling settings."""

    #: Delay, in time units.
    delay: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Interpolation of delayed values.
    interp: str | None = attrs.field(default=None, converter=to_str)
    #: Sampling interval (and phase).
    interval: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Number of samples kept for delays.
    nsample: int | None = attrs.field(default=None, converter=to_int)


@attrs.frozen(kw_only=True, repr=False)
class NoisySensor(SampledSensor):
    """Sampled sensors that declare a noise level."""

    #: Standard deviation of noise (informational).
    noise: float | None = attrs.field(default=None, converter=to_float, eq=float_key)


@attrs.frozen(kw_only=True, repr=False)
class SiteSensor(NoisySensor):
    """Sensors attached to a site."""

    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Touch(SiteSensor):
    """Sum of normal contact forces in the site's volume."""

    tag: ClassVar[str] = "touch"


@attrs.frozen(kw_only=True, repr=False)
class Accelerometer(SiteSensor):
    """Linear acceleration at a site."""

    tag: ClassVar[str] = "accelerometer"


@attrs.frozen(kw_only=True, repr=False)
class Velocimeter(SiteSensor):
    """Linear velocity at a site."""

    tag: ClassVar[str] = "velocimeter"


@attrs.frozen(kw_only=True, repr=False)
class Gyro(SiteSensor):
    """Angular velocity at a site."""

    tag: ClassVar[str] = "gyro"


@attrs.frozen(kw_only=True, repr=False)
class Force(SiteSensor):
    """Interaction force at a site."""

    tag: ClassVar[str] = "force"


@attrs.frozen(kw_only=True, repr=False)
class Torque(SiteSensor):
    """Interaction torque at a site."""

    tag: ClassVar[str] = "torque"


@attrs.frozen(kw_only=True, repr=False)
class Magnetometer(SiteSensor):
    """Magnetic flux at a site."""

    tag: ClassVar[str] = "magnetometer"


@attrs.frozen(kw_only=True, repr=False)
class CamProjection(SiteSensor):
    """Projection of a site onto a camera image."""

    tag: ClassVar[str] = "camprojection"
    #: Name of the camera.
    camera: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Rangefinder(SiteSensor):
    """Distance to the nearest surface along a ray."""

    tag: ClassVar[str] = "rangefinder"
    #: Name of the camera.
    camera: str | None = attrs.field(default=None, converter=to_str)
    #: Data values.
    data: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class JointSensor(NoisySensor):
    """Sensors that read a joint."""

    #: Name of the joint.
    joint: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class JointPos(JointSensor):
    """Joint position."""

    tag: ClassVar[str] = "jointpos"


@attrs.frozen(kw_only=True, repr=False)
class JointVel(JointSensor):
    """Joint velocity."""

    tag: ClassVar[str] = "jointvel"


@attrs.frozen(kw_only=True, repr=False)
class TendonSensor(NoisySensor):
    """Sensors that read a tendon."""

    #: Name of the tendon.
    tendon: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class TendonPos(TendonSensor):
    """Tendon length."""

    tag: ClassVar[str] = "tendonpos"


@attrs.frozen(kw_only=True, repr=False)
class TendonVel(TendonSensor):
    """Tendon velocity."""

    tag: ClassVar[str] = "tendonvel"


@attrs.frozen(kw_only=True, repr=False)
class ActuatorSensor(NoisySensor):
    """Sensors that read an actuator."""

    #: Name of the actuator.
    actuator: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class ActuatorPos(ActuatorSensor):
    """Actuator length."""

    tag: ClassVar[str] = "actuatorpos"


@attrs.frozen(kw_only=True, repr=False)
class ActuatorVel(ActuatorSensor):
    """Actuator velocity."""

    tag: ClassVar[str] = "actuatorvel"


@attrs.frozen(kw_only=True, repr=False)
class ActuatorFrc(ActuatorSensor):
    """Actuator force."""

    tag: ClassVar[str] = "actuatorfrc"


@attrs.frozen(kw_only=True, repr=False)
class JointActuatorFrc(JointSensor):
    """Total actuator force at a joint."""

    tag: ClassVar[str] = "jointactuatorfrc"


@attrs.frozen(kw_only=True, repr=False)
class TendonActuatorFrc(TendonSensor):
    """Total actuator force at a tendon."""

    tag: ClassVar[str] = "tendonactuatorfrc"


@attrs.frozen(kw_only=True, repr=False)
class BallQuat(JointSensor):
    """Orientation of a ball joint."""

    tag: ClassVar[str] = "ballquat"


@attrs.frozen(kw_only=True, repr=False)
class BallAngVel(JointSensor):
    """Angular velocity of a ball joint."""

    tag: ClassVar[str] = "ballangvel"


@attrs.frozen(kw_only=True, repr=False)
class JointLimitPos(JointSensor):
    """Joint limit distance."""

    tag: ClassVar[str] = "jointlimitpos"


@attrs.frozen(kw_only=True, repr=False)
class JointLimitVel(JointSensor):
    """Joint limit velocity."""

    tag: ClassVar[str] = "jointlimitvel"


@attrs.frozen(kw_only=True, repr=False)
class JointLimitFrc(JointSensor):
    """Joint limit force."""

    tag: ClassVar[str] = "jointlimitfrc"


@attrs.frozen(kw_only=True, repr=False)
class TendonLimitPos(TendonSensor):
    """Tendon limit distance."""

    tag: ClassVar[str] = "tendonlimitpos"


@attrs.frozen(kw_only=True, repr=False)
class TendonLimitVel(TendonSensor):
    """Tendon limit velocity."""

    tag: ClassVar[str] = "tendonlimitvel"


@attrs.frozen(kw_only=True, repr=False)
class TendonLimitFrc(TendonSensor):
    """Tendon limit force."""

    tag: ClassVar[str] = "tendonlimitfrc"


@attrs.frozen(kw_only=True, repr=False)
class ObjectSensor(NoisySensor):
    """Sensors that read a frame of an object of any type."""

    #: Name of the referenced object.
    objname: str | None = attrs.field(default=None, converter=to_str)
    #: Type of the referenced object.
    objtype: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class FrameSensor(ObjectSensor):
    """Frame sensors that may report relative to another frame."""

    #: Name of the reference frame object.
    refname: str | None = attrs.field(default=None, converter=to_str)
    #: Type of the reference frame object.
    reftype: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class FramePos(FrameSensor):
    """Position of an object's frame."""

    tag: ClassVar[str] = "framepos"


@attrs.frozen(kw_only=True, repr=False)
class FrameQuat(FrameSensor):
    """Orientation of an object's frame."""

    tag: ClassVar[str] = "framequat"


@attrs.frozen(kw_only=True, repr=False)
class FrameXAxis(FrameSensor):
    """X axis of an object's frame."""

    tag: ClassVar[str] = "framexaxis"


@attrs.frozen(kw_only=True, repr=False)
class FrameYAxis(FrameSensor):
    """Y axis of an object's frame."""

    tag: ClassVar[str] = "frameyaxis"


@attrs.frozen(kw_only=True, repr=False)
class FrameZAxis(FrameSensor):
    """Z axis of an object's frame."""

    tag: ClassVar[str] = "framezaxis"


@attrs.frozen(kw_only=True, repr=False)
class FrameLinVel(FrameSensor):
    """Linear velocity of an object's frame."""

    tag: ClassVar[str] = "framelinvel"


@attrs.frozen(kw_only=True, repr=False)
class FrameAngVel(FrameSensor):
    """Angular velocity of an object's frame."""

    tag: ClassVar[str] = "frameangvel"


@attrs.frozen(kw_only=True, repr=False)
class FrameLinAcc(ObjectSensor):
    """Linear acceleration of an object's frame."""

    tag: ClassVar[str] = "framelinacc"


@attrs.frozen(kw_only=True, repr=False)
class FrameAngAcc(ObjectSensor):
    """Angular acceleration of an object's frame."""

    tag: ClassVar[str] = "frameangacc"


@attrs.frozen(kw_only=True, repr=False)
class SubtreeSensor(NoisySensor):
    """Sensors that read the subtree rooted at a body."""

    #: Name of the body.
    body: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class SubtreeCom(SubtreeSensor):
    """Centre of mass of a subtree."""

    tag: ClassVar[str] = "subtreecom"


@attrs.frozen(kw_only=True, repr=False)
class SubtreeLinVel(SubtreeSensor):
    """Linear velocity of a subtree's centre of mass."""

    tag: ClassVar[str] = "subtreelinvel"


@attrs.frozen(kw_only=True, repr=False)
class SubtreeAngMom(SubtreeSensor):
    """Angular momentum of a subtree."""

    tag: ClassVar[str] = "subtreeangmom"


@attrs.frozen(kw_only=True, repr=False)
class InsideSite(ObjectSensor):
    """Whether an object is inside a site's volume."""

    tag: ClassVar[str] = "insidesite"
    #: Which objects count as enclosed.
    enclosed: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class GeomPairSensor(NoisySensor):
    """Sensors that measure between two geoms or bodies."""

    #: Name of the first body.
    body1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the second body.
    body2: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the first geom.
    geom1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the second geom.
    geom2: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Distance(GeomPairSensor):
    """Distance between two geoms or bodies."""

    tag: ClassVar[str] = "distance"


@attrs.frozen(kw_only=True, repr=False)
class Normal(GeomPairSensor):
    """Normal between two geoms or bodies."""

    tag: ClassVar[str] = "normal"


@attrs.frozen(kw_only=True, repr=False)
class FromTo(GeomPairSensor):
    """Segment between the nearest points of two geoms or bodies."""

    tag: ClassVar[str] = "fromto"


@attrs.frozen(kw_only=True, repr=False)
class ContactSensor(GeomPairSensor):
    """Contacts matching a filter."""

    tag: ClassVar[str] = "contact"
    #: Data values.
    data: str | None = attrs.field(default=None, converter=to_str)
    #: Number of contacts reported.
    num: int | None = attrs.field(default=None, converter=to_int)
    #: How contacts are reduced.
    reduce: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the root body of the first subtree.
    subtree1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the root body of the second subtree.
    subtree2: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class EPotential(NoisySensor):
    """Potential energy."""

    tag: ClassVar[str] = "e_potential"


@attrs.frozen(kw_only=True, repr=False)
class EKinetic(NoisySensor):
    """Kinetic energy."""

    tag: ClassVar[str] = "e_kinetic"


@attrs.frozen(kw_only=True, repr=False)
class Clock(NoisySensor):
    """Simulation time."""

    tag: ClassVar[str] = "clock"


@attrs.frozen(kw_only=True, repr=False)
class Tactile(SampledSensor):
    """Tactile sensor over a mesh."""

    tag: ClassVar[str] = "tactile"
    #: MJCF attribute ``geom``; see the MuJoCo XML reference.
    geom: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the mesh asset.
    mesh: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class UserSensor(SensorElement):
    """A sensor computed by user callbacks."""

    tag: ClassVar[str] = "user"
    #: Data type of the user sensor.
    datatype: str | None = attrs.field(default=None, converter=to_str)
    #: Dimension.
    dim: int | None = attrs.field(default=None, converter=to_int)
    #: Computation stage the user sensor needs.
    needstage: str | None = attrs.field(default=None, converter=to_str)
    #: Standard deviation of noise (informational).
    noise: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the referenced object.
    objname: str | None = attrs.field(default=None, converter=to_str)
    #: Type of the referenced object.
    objtype: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class SensorPlugin(SensorElement):
    """A sensor implemented by a plugin."""

    tag: ClassVar[str] = "plugin"
    #: Name of the plugin instance.
    instance: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the referenced object.
    objname: str | None = attrs.field(default=None, converter=to_str)
    #: Type of the referenced object.
    objtype: str | None = attrs.field(default=None, converter=to_str)
    #: Identifier of the plugin library.
    plugin: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the reference frame object.
    refname: str | None = attrs.field(default=None, converter=to_str)
    #: Type of the reference frame object.
    reftype: str | None = attrs.field(default=None, converter=to_str)
