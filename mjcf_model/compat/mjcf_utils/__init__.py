"""robosuite 1.5.2's ``robosuite.utils.mjcf_utils``, over the immutable model.

Every public name of robosuite's module is here with the same signature and the
same observable behaviour (return values, in-place edits of the live ElementTree
elements, number text), so robosuite code runs after replacing the import::

    from mjcf_model.compat import mjcf_utils  # instead of robosuite.utils.mjcf_utils

Each tree function converts the element to generic nodes, calls a pure function
on them, and writes the result back onto the same elements (never replacing one).

Deliberate differences from robosuite:

* The tree functions read numbers separated by any white space (robosuite raises
  ``ValueError`` on valid MJCF such as ``pos="0  0 1"``); ``string_to_array``
  itself keeps robosuite's behaviour.
* ``find_elements_by_substring`` skips unnamed elements (robosuite raises
  ``TypeError``) and with ``return_first`` returns the first match (robosuite
  searches the children of the first element with the tag).
* A function that raises leaves what it was changing (the tree, or the element a
  ``scale_*`` function was scaling) unchanged instead of half edited.
* An ``exclude`` callable sees the tree as it was when the function was called
  (robosuite has already edited the elements before the one it asks about).
* Named textures and relative paths need robosuite's asset files: robosuite is
  found without being imported, and ``MjcfLookupError`` says when it is missing.
* Sets such as ``MUJOCO_NAMED_ATTRIBUTES`` hold robosuite's items but may iterate
  in another order (robosuite's own depends on the interpreter and the hash seed).

>>> import xml.etree.ElementTree as ET
>>> obj = ET.fromstring('<body name="can"><geom name="g" mesh="can_mesh"/></body>')
>>> add_prefix(obj, "can_")
>>> ET.tostring(obj, encoding="unicode")
'<body name="can_can"><geom name="can_g" mesh="can_mesh" /></body>'
"""

from __future__ import annotations

from mjcf_model.compat.mjcf_utils.builders import (
    new_actuator,
    new_body,
    new_element,
    new_geom,
    new_inertial,
    new_joint,
    new_site,
)
from mjcf_model.compat.mjcf_utils.constants import (
    ALL_TEXTURES,
    BLUE,
    CYAN,
    ENVIRONMENT_COLLISION_COLOR,
    GREEN,
    GRIPPER_COLLISION_COLOR,
    IMAGE_CONVENTION_MAPPING,
    MOUNT_COLLISION_COLOR,
    MUJOCO_NAMED_ATTRIBUTES,
    OBJECT_COLLISION_COLOR,
    RED,
    ROBOT_COLLISION_COLOR,
    SENSOR_TYPES,
    TEXTURE_FILES,
    TEXTURES,
)
from mjcf_model.compat.mjcf_utils.materials import (
    CustomMaterial,
    add_material,
    recolor_collision_geoms,
    set_alpha,
)
from mjcf_model.compat.mjcf_utils.naming import add_prefix
from mjcf_model.compat.mjcf_utils.queries import (
    _element_filter as _element_filter,
)
from mjcf_model.compat.mjcf_utils.queries import (
    find_elements,
    find_elements_by_substring,
    find_parent,
    get_elements,
    sort_elements,
)
from mjcf_model.compat.mjcf_utils.scaling import (
    scale_body_element,
    scale_geom_element,
    scale_joint_element,
    scale_mesh_element,
    scale_mjcf_model,
    scale_site_element,
)
from mjcf_model.compat.mjcf_utils.text import (
    add_to_dict,
    array_to_string,
    convert_to_string,
    get_ids,
    get_size,
    normalize_scale_array,
    save_sim_model,
    string_to_array,
    xml_path_completion,
)

# ``_element_filter`` is importable by name, as in robosuite, but private: not in ``__all__``.
__all__ = [
    "ALL_TEXTURES",
    "BLUE",
    "CYAN",
    "CustomMaterial",
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
    "add_material",
    "add_prefix",
    "add_to_dict",
    "array_to_string",
    "convert_to_string",
    "find_elements",
    "find_elements_by_substring",
    "find_parent",
    "get_elements",
    "get_ids",
    "get_size",
    "new_actuator",
    "new_body",
    "new_element",
    "new_geom",
    "new_inertial",
    "new_joint",
    "new_site",
    "normalize_scale_array",
    "recolor_collision_geoms",
    "save_sim_model",
    "scale_body_element",
    "scale_geom_element",
    "scale_joint_element",
    "scale_mesh_element",
    "scale_mjcf_model",
    "scale_site_element",
    "set_alpha",
    "sort_elements",
    "string_to_array",
    "xml_path_completion",
]
