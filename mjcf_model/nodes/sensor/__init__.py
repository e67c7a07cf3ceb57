"""The ``<sensor>`` section: one class per sensor element, grouped by what they read.

>>> JointPos(name="q", joint="elbow").joint
'elbow'
"""

from mjcf_model.nodes.sensor import base, frames, global_sensors, one_object
from mjcf_model.nodes.sensor.base import *  # noqa: F403
from mjcf_model.nodes.sensor.frames import *  # noqa: F403
from mjcf_model.nodes.sensor.global_sensors import *  # noqa: F403
from mjcf_model.nodes.sensor.one_object import *  # noqa: F403

# Each module lists its classes; a class added there is exported here without more.
__all__ = [*base.__all__, *one_object.__all__, *frames.__all__, *global_sensors.__all__]
