"""The ``<sensor>`` section: one class per sensor element, grouped by what they read.

>>> JointPos(name="q", joint="elbow").joint
'elbow'
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import integer, number, numbers, reference, text
from mjcf_model.values import Floats

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


@node
class Sensor(TypedElement):
    """Section of sensors."""

    tag: ClassVar[str] = "sensor"
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


@node
class SiteSensor(NoisySensor):
    """Sensors attached to a site."""

    #: Name of the site.
    site: str | None = reference("site")


@node
class Touch(SiteSensor):
    """Sum of normal contact forces in the site's volume."""

    tag: ClassVar[str] = "touch"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/touch",)


@node
class Accelerometer(SiteSensor):
    """Linear acceleration at a site."""

    tag: ClassVar[str] = "accelerometer"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/accelerometer",)


@node
class Velocimeter(SiteSensor):
    """Linear velocity at a site."""

    tag: ClassVar[str] = "velocimeter"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/velocimeter",)


@node
class Gyro(SiteSensor):
    """Angular velocity at a site."""

    tag: ClassVar[str] = "gyro"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/gyro",)


@node
class Force(SiteSensor):
    """Interaction force at a site."""

    tag: ClassVar[str] = "force"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/force",)


@node
class Torque(SiteSensor):
    """Interaction torque at a site."""

    tag: ClassVar[str] = "torque"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/torque",)


@node
class Magnetometer(SiteSensor):
    """Magnetic flux at a site."""

    tag: ClassVar[str] = "magnetometer"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/magnetometer",)


@node
class CamProjection(SiteSensor):
    """Projection of a site onto a camera image."""

    tag: ClassVar[str] = "camprojection"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/camprojection",)
    #: Name of the camera.
    camera: str | None = reference("camera")


@node
class Rangefinder(SiteSensor):
    """Distance to the nearest surface along a ray."""

    tag: ClassVar[str] = "rangefinder"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/rangefinder",)
    #: Name of the camera.
    camera: str | None = reference("camera")
    #: Data values.
    data: str | None = text()


@node
class JointSensor(NoisySensor):
    """Sensors that read a joint."""

    #: Name of the joint.
    joint: str | None = reference("joint")


@node
class JointPos(JointSensor):
    """Joint position."""

    tag: ClassVar[str] = "jointpos"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointpos",)


@node
class JointVel(JointSensor):
    """Joint velocity."""

    tag: ClassVar[str] = "jointvel"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointvel",)


@node
class TendonSensor(NoisySensor):
    """Sensors that read a tendon."""

    #: Name of the tendon.
    tendon: str | None = reference("tendon")


@node
class TendonPos(TendonSensor):
    """Tendon length."""

    tag: ClassVar[str] = "tendonpos"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonpos",)


@node
class TendonVel(TendonSensor):
    """Tendon velocity."""

    tag: ClassVar[str] = "tendonvel"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonvel",)


@node
class ActuatorSensor(NoisySensor):
    """Sensors that read an actuator."""

    #: Name of the actuator.
    actuator: str | None = reference("actuator")


@node
class ActuatorPos(ActuatorSensor):
    """Actuator length."""

    tag: ClassVar[str] = "actuatorpos"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/actuatorpos",)


@node
class ActuatorVel(ActuatorSensor):
    """Actuator velocity."""

    tag: ClassVar[str] = "actuatorvel"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/actuatorvel",)


@node
class ActuatorFrc(ActuatorSensor):
    """Actuator force."""

    tag: ClassVar[str] = "actuatorfrc"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/actuatorfrc",)


@node
class JointActuatorFrc(JointSensor):
    """Total actuator force at a joint."""

    tag: ClassVar[str] = "jointactuatorfrc"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointactuatorfrc",)


@node
class TendonActuatorFrc(TendonSensor):
    """Total actuator force at a tendon."""

    tag: ClassVar[str] = "tendonactuatorfrc"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonactuatorfrc",)


@node
class BallQuat(JointSensor):
    """Orientation of a ball joint."""

    tag: ClassVar[str] = "ballquat"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/ballquat",)


@node
class BallAngVel(JointSensor):
    """Angular velocity of a ball joint."""

    tag: ClassVar[str] = "ballangvel"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/ballangvel",)


@node
class JointLimitPos(JointSensor):
    """Joint limit distance."""

    tag: ClassVar[str] = "jointlimitpos"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointlimitpos",)


@node
class JointLimitVel(JointSensor):
    """Joint limit velocity."""

    tag: ClassVar[str] = "jointlimitvel"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointlimitvel",)


@node
class JointLimitFrc(JointSensor):
    """Joint limit force."""

    tag: ClassVar[str] = "jointlimitfrc"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointlimitfrc",)


@node
class TendonLimitPos(TendonSensor):
    """Tendon limit distance."""

    tag: ClassVar[str] = "tendonlimitpos"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonlimitpos",)


@node
class TendonLimitVel(TendonSensor):
    """Tendon limit velocity."""

    tag: ClassVar[str] = "tendonlimitvel"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonlimitvel",)


@node
class TendonLimitFrc(TendonSensor):
    """Tendon limit force."""

    tag: ClassVar[str] = "tendonlimitfrc"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonlimitfrc",)


@node
class ObjectSensor(NoisySensor):
    """Sensors that read a frame of an object of any type."""

    #: Name of the referenced object.
    objname: str | None = reference("@objtype")
    #: Type of the referenced object.
    objtype: str | None = text()


@node
class FrameSensor(ObjectSensor):
    """Frame sensors that may report relative to another frame."""

    #: Name of the reference frame object.
    refname: str | None = reference("@reftype")
    #: Type of the reference frame object.
    reftype: str | None = text()


@node
class FramePos(FrameSensor):
    """Position of an object's frame."""

    tag: ClassVar[str] = "framepos"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framepos",)


@node
class FrameQuat(FrameSensor):
    """Orientation of an object's frame."""

    tag: ClassVar[str] = "framequat"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framequat",)


@node
class FrameXAxis(FrameSensor):
    """X axis of an object's frame."""

    tag: ClassVar[str] = "framexaxis"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framexaxis",)


@node
class FrameYAxis(FrameSensor):
    """Y axis of an object's frame."""

    tag: ClassVar[str] = "frameyaxis"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/frameyaxis",)


@node
class FrameZAxis(FrameSensor):
    """Z axis of an object's frame."""

    tag: ClassVar[str] = "framezaxis"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framezaxis",)


@node
class FrameLinVel(FrameSensor):
    """Linear velocity of an object's frame."""

    tag: ClassVar[str] = "framelinvel"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framelinvel",)


@node
class FrameAngVel(FrameSensor):
    """Angular velocity of an object's frame."""

    tag: ClassVar[str] = "frameangvel"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/frameangvel",)


@node
class FrameLinAcc(ObjectSensor):
    """Linear acceleration of an object's frame."""

    tag: ClassVar[str] = "framelinacc"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/framelinacc",)


@node
class FrameAngAcc(ObjectSensor):
    """Angular acceleration of an object's frame."""

    tag: ClassVar[str] = "frameangacc"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/frameangacc",)


@node
class SubtreeSensor(NoisySensor):
    """Sensors that read the subtree rooted at a body."""

    #: Name of the body.
    body: str | None = reference("body")


@node
class SubtreeCom(SubtreeSensor):
    """Centre of mass of a subtree."""

    tag: ClassVar[str] = "subtreecom"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/subtreecom",)


@node
class SubtreeLinVel(SubtreeSensor):
    """Linear velocity of a subtree's centre of mass."""

    tag: ClassVar[str] = "subtreelinvel"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/subtreelinvel",)


@node
class SubtreeAngMom(SubtreeSensor):
    """Angular momentum of a subtree."""

    tag: ClassVar[str] = "subtreeangmom"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/subtreeangmom",)


@node
class InsideSite(ObjectSensor):
    """Whether an object is inside a site's volume."""

    tag: ClassVar[str] = "insidesite"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/insidesite",)
    #: Which objects count as enclosed.
    enclosed: str | None = text()
    #: Name of the site.
    site: str | None = reference("site")


@node
class GeomPairSensor(NoisySensor):
    """Sensors that measure between two geoms or bodies."""

    #: Name of the first body.
    body1: str | None = reference("body")
    #: Name of the second body.
    body2: str | None = reference("body")
    #: Name of the first geom.
    geom1: str | None = reference("geom")
    #: Name of the second geom.
    geom2: str | None = reference("geom")


@node
class Distance(GeomPairSensor):
    """Distance between two geoms or bodies."""

    tag: ClassVar[str] = "distance"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/distance",)


@node
class Normal(GeomPairSensor):
    """Normal between two geoms or bodies."""

    tag: ClassVar[str] = "normal"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/normal",)


@node
class FromTo(GeomPairSensor):
    """Segment between the nearest points of two geoms or bodies."""

    tag: ClassVar[str] = "fromto"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/fromto",)


@node
class ContactSensor(GeomPairSensor):
    """Contacts matching a filter."""

    tag: ClassVar[str] = "contact"
    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/contact",)
    #: Data values.
    data: str | None = text()
    #: Number of contacts reported.
    num: int | None = integer()
    #: How contacts are reduced.
    reduce: str | None = text()
    #: Name of the site.
    site: str | None = reference("site")
    #: Name of the root body of the first subtree.
    subtree1: str | None = reference("body")
    #: Name of the root body of the second subtree.
    subtree2: str | None = reference("body")


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
