"""The ``<actuator>`` section: one class per actuator element.

>>> Position(name="servo", joint="elbow", kp=100).kp
100.0
"""

from mjcf_model.nodes.actuator import base, shortcuts, special
from mjcf_model.nodes.actuator.base import *  # noqa: F403
from mjcf_model.nodes.actuator.shortcuts import *  # noqa: F403
from mjcf_model.nodes.actuator.special import *  # noqa: F403

# Each module lists its classes; a class added there is exported here without more.
__all__ = [*base.__all__, *shortcuts.__all__, *special.__all__]
