"""robosuite's constants: colours, tag and attribute sets, textures, with robosuite's types."""

from __future__ import annotations

import os

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

#: robosuite's named textures and their image files, in robosuite's order.
TEXTURE_FILES: dict[str, str] = {
    "WoodRed": "red-wood.png",
    "WoodGreen": "green-wood.png",
    "WoodBlue": "blue-wood.png",
    "WoodLight": "light-wood.png",
    "WoodDark": "dark-wood.png",
    "WoodTiles": "wood-tiles.png",
    "WoodPanels": "wood-varnished-panels.png",
    "WoodgrainGray": "gray-woodgrain.png",
    "PlasterCream": "cream-plaster.png",
    "PlasterPink": "pink-plaster.png",
    "PlasterYellow": "yellow-plaster.png",
    "PlasterGray": "gray-plaster.png",
    "PlasterWhite": "white-plaster.png",
    "BricksWhite": "white-bricks.png",
    "Metal": "metal.png",
    "SteelBrushed": "steel-brushed.png",
    "SteelScratched": "steel-scratched.png",
    "Brass": "brass-ambra.png",
    "Bread": "bread.png",
    "Can": "can.png",
    "Ceramic": "ceramic.png",
    "Cereal": "cereal.png",
    "Clay": "clay.png",
    "Dirt": "dirt.png",
    "Glass": "glass.png",
    "FeltGray": "gray-felt.png",
    "Lemon": "lemon.png",
}

#: Named textures and their paths relative to robosuite's assets directory.
TEXTURES: dict[str, str] = {
    texture_name: os.path.join("textures", texture_file)
    for (texture_name, texture_file) in TEXTURE_FILES.items()
}

#: The valid texture names: a live view of ``TEXTURES``' keys, as in robosuite.
ALL_TEXTURES = TEXTURES.keys()
