"""The MJCF keyword sets that node fields validate.

Only keywords whose complete set MuJoCo publishes as an enum are checked here;
a test compares each set with the installed MuJoCo's enum, so a new keyword
fails that test rather than a user's valid model.

>>> "capsule" in GEOM_TYPES
True
"""

from __future__ import annotations

__all__ = ["GEOM_TYPES", "JOINT_TYPES", "LIGHT_TYPES", "LIMITED", "TRACKING_MODES"]

#: Geom (and site) shapes: ``mjtGeom`` up to ``mjNGEOMTYPES``.
GEOM_TYPES = frozenset(
    {"plane", "hfield", "sphere", "capsule", "ellipsoid", "cylinder", "box", "mesh", "sdf"}
)
#: Joint types: ``mjtJoint``.
JOINT_TYPES = frozenset({"free", "ball", "slide", "hinge"})
#: Light types: ``mjtLightType``.
LIGHT_TYPES = frozenset({"spot", "directional", "point", "image"})
#: Camera and light tracking modes: ``mjtCamLight``.
TRACKING_MODES = frozenset({"fixed", "track", "trackcom", "targetbody", "targetbodycom"})
#: Tri-state limit flags (``limited``, ``ctrllimited``, ...): ``mjtLimited``.
LIMITED = frozenset({"false", "true", "auto"})
