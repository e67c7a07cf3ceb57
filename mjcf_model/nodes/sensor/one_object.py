"""Sensors that read one site, joint, tendon or actuator."""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import text
from mjcf_model.nodes.sensor.base import NoisySensor

__all__ = [
    "Accelerometer",
    "ActuatorFrc",
    "ActuatorPos",
    "ActuatorSensor",
    "ActuatorVel",
    "BallAngVel",
    "BallQuat",
    "CamProjection",
    "Force",
    "Gyro",
    "JointActuatorFrc",
    "JointLimitFrc",
    "JointLimitPos",
    "JointLimitVel",
    "JointPos",
    "JointSensor",
    "JointVel",
    "Magnetometer",
    "Rangefinder",
    "SiteSensor",
    "TendonActuatorFrc",
    "TendonLimitFrc",
    "TendonLimitPos",
    "TendonLimitVel",
    "TendonPos",
    "TendonSensor",
    "TendonVel",
    "Torque",
    "Touch",
    "Velocimeter",
]


@node
class SiteSensor(NoisySensor):
    """Sensors attached to a site."""

    #: Name of the site.
    site: str | None = text()


@node
class Touch(SiteSensor):
    """Sum of normal contact forces in the site's volume."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/touch",)


@node
class Accelerometer(SiteSensor):
    """Linear acceleration at a site."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/accelerometer",)


@node
class Velocimeter(SiteSensor):
    """Linear velocity at a site."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/velocimeter",)


@node
class Gyro(SiteSensor):
    """Angular velocity at a site."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/gyro",)


@node
class Force(SiteSensor):
    """Interaction force at a site."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/force",)


@node
class Torque(SiteSensor):
    """Interaction torque at a site."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/torque",)


@node
class Magnetometer(SiteSensor):
    """Magnetic flux at a site."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/magnetometer",)


@node
class CamProjection(SiteSensor):
    """Projection of a site onto a camera image."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/camprojection",)
    #: Name of the camera.
    camera: str | None = text()


@node
class Rangefinder(SiteSensor):
    """Distance to the nearest surface along a ray."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/rangefinder",)
    #: Name of the camera.
    camera: str | None = text()
    #: Data values.
    data: str | None = text()


@node
class JointSensor(NoisySensor):
    """Sensors that read a joint."""

    #: Name of the joint.
    joint: str | None = text()


@node
class JointPos(JointSensor):
    """Joint position."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointpos",)


@node
class JointVel(JointSensor):
    """Joint velocity."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointvel",)


@node
class TendonSensor(NoisySensor):
    """Sensors that read a tendon."""

    #: Name of the tendon.
    tendon: str | None = text()


@node
class TendonPos(TendonSensor):
    """Tendon length."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonpos",)


@node
class TendonVel(TendonSensor):
    """Tendon velocity."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonvel",)


@node
class ActuatorSensor(NoisySensor):
    """Sensors that read an actuator."""

    #: Name of the actuator.
    actuator: str | None = text()


@node
class ActuatorPos(ActuatorSensor):
    """Actuator length."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/actuatorpos",)


@node
class ActuatorVel(ActuatorSensor):
    """Actuator velocity."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/actuatorvel",)


@node
class ActuatorFrc(ActuatorSensor):
    """Actuator force."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/actuatorfrc",)


@node
class JointActuatorFrc(JointSensor):
    """Total actuator force at a joint."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointactuatorfrc",)


@node
class TendonActuatorFrc(TendonSensor):
    """Total actuator force at a tendon."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonactuatorfrc",)


@node
class BallQuat(JointSensor):
    """Orientation of a ball joint."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/ballquat",)


@node
class BallAngVel(JointSensor):
    """Angular velocity of a ball joint."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/ballangvel",)


@node
class JointLimitPos(JointSensor):
    """Joint limit distance."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointlimitpos",)


@node
class JointLimitVel(JointSensor):
    """Joint limit velocity."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointlimitvel",)


@node
class JointLimitFrc(JointSensor):
    """Joint limit force."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/jointlimitfrc",)


@node
class TendonLimitPos(TendonSensor):
    """Tendon limit distance."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonlimitpos",)


@node
class TendonLimitVel(TendonSensor):
    """Tendon limit velocity."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonlimitvel",)


@node
class TendonLimitFrc(TendonSensor):
    """Tendon limit force."""

    schema_keys: ClassVar[tuple[str, ...]] = ("sensor/tendonlimitfrc",)
