"""robosuite's constants: colours, tag and attribute sets, textures, with robosuite's types."""

from __future__ import annotations

import os

from mjcf_model.compat import materials

__all__ = [
    "ALL_TEXTURES",
    "BLUE",
    "CYAN",
    "ENVIRONMENT_COLLISION_COLOR",
    "GREEN",
    "GRIPPER_COLLISION_COLOR",
    "IMAGE_CONVENTION_MAPPING",
    "MOUNT_COLLISION_COLOR",
    "MUJOCO_NAMED_ATTRIBUTES",
    "OBJECT_COLLISION_COLOR",
    "RED",
    "ROBOT_COLLISION_COLOR",
    "SENSOR_TYPES",
    "TEXTURES",
    "TEXTURE_FILES",
]

RED: list[float] = [1, 0, 0, 1]
GREEN: list[float] = [0, 1, 0, 1]
BLUE: list[float] = [0, 0, 1, 1]
CYAN: list[float] = [0, 1, 1, 1]
ROBOT_COLLISION_COLOR: list[float] = [0, 0.5, 0, 1]
MOUNT_COLLISION_COLOR: list[float] = [0.5, 0.5, 0, 1]
GRIPPER_COLLISION_COLOR: list[float] = [0, 0, 0.5, 1]
OBJECT_COLLISION_COLOR: list[float] = [0.5, 0, 0, 1]
ENVIRONMENT_COLLISION_COLOR: list[float] = [0.5, 0.5, 0, 1]

#: The tags ``_element_filter`` files under ``"sensors"`` (robosuite's 35, in its order).
SENSOR_TYPES: set[str] = {
    "touch",
    "accelerometer",
    "velocimeter",
    "gyro",
    "force",
    "torque",
    "magnetometer",
    "rangefinder",
    "jointpos",
    "jointvel",
    "tendonpos",
    "tendonvel",
    "actuatorpos",
    "actuatorvel",
    "actuatorfrc",
    "ballangvel",
    "jointlimitpos",
    "jointlimitvel",
    "jointlimitfrc",
    "tendonlimitpos",
    "tendonlimitvel",
    "tendonlimitfrc",
    "framepos",
    "framequat",
    "framexaxis",
    "frameyaxis",
    "framezaxis",
    "framelinvel",
    "frameangvel",
    "framelinacc",
    "frameangacc",
    "subtreecom",
    "subtreelinvel",
    "subtreeangmom",
    "user",
}

#: The attributes ``add_prefix`` prefixes by default (robosuite's list, in its order).
MUJOCO_NAMED_ATTRIBUTES: set[str] = {
    "class",
    "childclass",
    "name",
    "objname",
    "material",
    "texture",
    "joint",
    "joint1",
    "joint2",
    "jointinparent",
    "geom",
    "geom1",
    "geom2",
    "mesh",
    "fixed",
    "actuator",
    "tendon",
    "tendon1",
    "tendon2",
    "slidesite",
    "cranksite",
    "body",
    "body1",
    "body2",
    "hfield",
    "target",
    "prefix",
    "site",
}

IMAGE_CONVENTION_MAPPING: dict[str, int] = {
    "opengl": 1,
    "opencv": -1,
}

#: robosuite's named textures and their files (a plain copy of the library's table).
TEXTURE_FILES: dict[str, str] = dict(materials.TEXTURE_FILES)

#: Named textures and their paths relative to robosuite's assets directory.
TEXTURES: dict[str, str] = {
    texture_name: os.path.join("textures", texture_file)
    for (texture_name, texture_file) in TEXTURE_FILES.items()
}

#: The valid texture names: a live view of ``TEXTURES``' keys, as in robosuite.
ALL_TEXTURES = TEXTURES.keys()
