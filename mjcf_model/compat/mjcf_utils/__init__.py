"""robosuite 1.5.2's ``robosuite.utils.mjcf_utils``, over the immutable model.

Every public name of robosuite's module is here with the same signature and
the same observable behaviour: the same return values (``None`` from
``find_elements`` when nothing matches, lists of the *live* ElementTree
elements), the same in-place changes (attributes set where robosuite sets them,
so ``ET.tostring`` gives the same bytes), the same number text
(``"{}".format(x)``: numpy floats print as ``0.0``). Code written for
robosuite runs unchanged after replacing the import::

    from mjcf_model.compat import mjcf_utils  # instead of robosuite.utils.mjcf_utils

Each tree function is a thin wrapper: it converts the ElementTree element to
generic nodes (``from_etree(typed=False)``, which keeps attribute text exactly),
calls a pure function on the nodes, and writes the result back onto the same
ElementTree elements (never replacing one: robosuite code holds references to
them). robosuite's quirks (prefixing by attribute name, skipping values that
already start with the prefix, sizes scaled by their count) live in those pure
functions of the ``utils_*`` modules only, not in the library.

Where robosuite crashes on valid MJCF, these functions do the right thing
instead, as each docstring says: the tree functions read numbers separated by
any white space (robosuite's ``string_to_array`` needs single spaces; that
function itself keeps robosuite's behaviour), ``find_elements_by_substring``
skips unnamed elements and honours ``return_first``, and a function that
fails leaves what it was changing (the tree, or the one element of a
``scale_*_element``) unchanged instead of half edited. Named textures and
relative paths need robosuite's asset files: robosuite is found without being
imported, and ``MjcfLookupError`` says when it is missing.

Deliberate differences that are not crashes: an ``exclude`` callable sees the
tree as it was when the function was called (robosuite has already edited the
elements before the one it asks about), and sets such as
``MUJOCO_NAMED_ATTRIBUTES`` hold robosuite's items but may iterate in another
order (which robosuite's own order depends on: how the interpreter built the
set, and the hash seed).

>>> import xml.etree.ElementTree as ET
>>> obj = ET.fromstring('<body name="can"><geom name="g" mesh="can_mesh"/></body>')
>>> add_prefix(obj, "can_")
>>> ET.tostring(obj, encoding="unicode")
'<body name="can_can"><geom name="can_g" mesh="can_mesh" /></body>'
>>> [e.get("name") for e in find_elements(obj, "geom", return_first=False)]
['can_g']
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

# ``_element_filter`` (imported above) is importable by name, as in robosuite, but,
# being private, not part of ``from mjcf_utils import *``.
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
