"""All typed node classes, one module per MJCF section."""

from __future__ import annotations

from mjcf_model.nodes import (
    asset,
    body,
    compiler,
    contact,
    custom,
    default,
    deformable,
    equality,
    geom,
    keyframe,
    plugin,
    root,
    tendon,
    visual,
)
from mjcf_model.nodes.actuator import base as actuator_base
from mjcf_model.nodes.actuator import shortcuts as actuator_shortcuts
from mjcf_model.nodes.actuator import special as actuator_special
from mjcf_model.nodes.actuator.base import *
from mjcf_model.nodes.actuator.shortcuts import *
from mjcf_model.nodes.actuator.special import *
from mjcf_model.nodes.asset import *
from mjcf_model.nodes.body import *
from mjcf_model.nodes.compiler import *
from mjcf_model.nodes.contact import *
from mjcf_model.nodes.custom import *
from mjcf_model.nodes.default import *
from mjcf_model.nodes.deformable import *
from mjcf_model.nodes.equality import *
from mjcf_model.nodes.geom import *
from mjcf_model.nodes.keyframe import *
from mjcf_model.nodes.plugin import *
from mjcf_model.nodes.root import *
from mjcf_model.nodes.sensor import base as sensor_base
from mjcf_model.nodes.sensor import frames as sensor_frames
from mjcf_model.nodes.sensor import global_sensors as sensor_global_sensors
from mjcf_model.nodes.sensor import one_object as sensor_one_object
from mjcf_model.nodes.sensor.base import *
from mjcf_model.nodes.sensor.frames import *
from mjcf_model.nodes.sensor.global_sensors import *
from mjcf_model.nodes.sensor.one_object import *
from mjcf_model.nodes.tendon import *
from mjcf_model.nodes.visual import *

# Each section module lists its node classes in its own __all__.
__all__ = (
    actuator_base.__all__
    + actuator_shortcuts.__all__
    + actuator_special.__all__
    + asset.__all__
    + body.__all__
    + compiler.__all__
    + contact.__all__
    + custom.__all__
    + default.__all__
    + deformable.__all__
    + equality.__all__
    + geom.__all__
    + keyframe.__all__
    + plugin.__all__
    + root.__all__
    + sensor_base.__all__
    + sensor_one_object.__all__
    + sensor_frames.__all__
    + sensor_global_sensors.__all__
    + tendon.__all__
    + visual.__all__
)
