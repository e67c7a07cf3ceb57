"""``MujocoGeneratedObject`` and ``PrimitiveObject``: objects built in code, as robosuite does.

Materials may be this library's :class:`~mjcf_model.CustomMaterial` or robosuite's own.

>>> ball = PrimitiveObject("ball", size=[0.03], material="default")
>>> [child.get("name") for child in ball.asset]
['ball_tex', 'ball_mat']
"""

from __future__ import annotations

from typing import Any

import numpy as np

from mjcf_model.compat.mjcf_utils.text import array_to_string
from mjcf_model.compat.objects.base import MujocoObject, Vector, joint_specs
from mjcf_model.compat.objects.habits import (
    OBJECT_COLLISION_COLOR,
    rs_body,
    rs_geom,
    rs_joint,
    rs_site,
    value_text,
)
from mjcf_model.compat.objects.naming import robosuite_prefixed
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, GenericElement
from mjcf_model.transforms.materials import CustomMaterial
from mjcf_model.tree.traversal import with_children

__all__ = ["MujocoGeneratedObject", "PrimitiveObject"]

#: The body of a primitive, before its children: robosuite's ``new_body(name="main")``.
_MAIN_BODY = rs_body(name="main")


def material_parts(material: Any) -> tuple[str, str, bool, AnyElement, AnyElement]:
    """The material name, texture name, ``shared`` flag, and texture and material nodes."""
    if isinstance(material, CustomMaterial):
        texture: AnyElement = material.texture_node
        node: AnyElement = material.material_node
        return material.name, material.tex_name, material.shared, texture, node
    tex_attrib = {k: value_text(v) for k, v in material.tex_attrib.items()}
    mat_attrib = {k: value_text(v) for k, v in material.mat_attrib.items()}
    texture = GenericElement(tag="texture", attributes=tex_attrib)
    node = GenericElement(tag="material", attributes=mat_attrib)
    return str(material.name), tex_attrib["name"], bool(material.shared), texture, node


class MujocoGeneratedObject(MujocoObject):
    """robosuite's ``MujocoGeneratedObject``: shared materials, geom templates, materials.

    Args:
        obj_type: ``"collision"``, ``"visual"`` or ``"all"`` geoms.
        duplicate_collision_geoms: Kept for robosuite's signature.

    """

    _robosuite_class = ("robosuite.models.objects", "MujocoGeneratedObject")

    def __init__(self, obj_type: str = "all", duplicate_collision_geoms: bool = True) -> None:
        super().__init__(obj_type=obj_type, duplicate_collision_geoms=duplicate_collision_geoms)
        self.shared_materials: set[str] = set()
        self.shared_textures: set[str] = set()

    def sanity_check(self) -> None:
        """Check the arguments (subclasses do)."""

    @staticmethod
    def get_collision_attrib_template() -> dict[str, str]:
        """Attributes of a collision geom: group 0, the object collision colour."""
        return {"group": "0", "rgba": OBJECT_COLLISION_COLOR}

    @staticmethod
    def get_visual_attrib_template() -> dict[str, str]:
        """Attributes of a visual geom: no contacts, no mass, group 1."""
        return {"conaffinity": "0", "contype": "0", "mass": "1e-8", "group": "1"}

    def append_material(self, material: Any) -> None:
        """Add a material and its texture to the assets, then prefix the asset names.

        A shared material is added once and its names never get the prefix.
        """
        name, tex_name, shared, texture, node = material_parts(material)
        asset = self._node("asset")
        if name not in self.shared_materials:
            asset = with_children(asset, [*asset.children, texture, node])
        if shared:
            self.shared_materials.add(name)
            self.shared_textures.add(tex_name)
        self._replace("asset", robosuite_prefixed(asset, self.naming_prefix, self._excluded))

    def exclude_from_prefixing(self, inp: Any) -> bool:
        """Keep the names of shared materials and textures (any text equal to one)."""
        if type(inp) is not str:
            return False
        return inp in self.shared_materials or inp in self.shared_textures

    def get_bounding_box_half_size(self) -> Vector:
        """``[r, r, 0]`` minus the bottom offset (``r``: the horizontal radius)."""
        radius = self.horizontal_radius
        half: Vector = np.array([radius, radius, 0.0]) - self.bottom_offset
        return half


class PrimitiveObject(MujocoGeneratedObject):
    """robosuite's ``PrimitiveObject``: one geom (collision and/or visual), joints and a site.

    Unlike robosuite, ``material="default"`` uses MuJoCo's built-in flat texture
    (named ``<name>_tex``), not a PNG file.

    Args:
        name: Name of the object.
        size: Geom size (default ``[0.05] * 3``).
        rgba: Colour of the visual geom (default red).
        density: Density (default 1000).
        friction: Three numbers, or one (sliding; torsion and rolling stay MuJoCo's).
        solref: Contact solver reference (default ``[0.02, 1.0]``).
        solimp: Contact solver impedance (default ``[0.9, 0.95, 0.001]``).
        material: ``None``, ``"default"`` (a material of the colour ``rgba``)
            or a material (this library's ``CustomMaterial`` or robosuite's).
        joints: ``"default"`` (a free joint), ``None``, or joint attribute dicts.
        obj_type: ``"collision"``, ``"visual"`` or ``"all"``.
        duplicate_collision_geoms: Ignored, as in robosuite.

    Raises:
        MjcfValueError: ``rgba``, ``friction`` or the size has the wrong length.

    """

    _robosuite_class = ("robosuite.models.objects", "PrimitiveObject")
    #: The MuJoCo geom type (subclasses set it).
    geom_type = "box"

    def __init__(
        self,
        name: str,
        size: Any = None,
        rgba: Any = None,
        density: Any = None,
        friction: Any = None,
        solref: Any = None,
        solimp: Any = None,
        material: Any = None,
        joints: Any = "default",
        obj_type: str = "all",
        duplicate_collision_geoms: bool = True,
    ) -> None:
        super().__init__(obj_type=obj_type, duplicate_collision_geoms=duplicate_collision_geoms)
        self._name = name
        self.size = list([0.05, 0.05, 0.05] if size is None else size)
        self.rgba = list([1, 0, 0, 1] if rgba is None else rgba)
        if len(self.rgba) != 4:
            raise MjcfValueError(f"rgba must be a length 4 array, found {self.rgba!r}")
        self.density = 1000 if density is None else density
        if friction is None:
            friction = [1, 0.005, 0.0001]
        elif isinstance(friction, (float, int)):
            friction = [friction, 0.005, 0.0001]
        if len(friction) != 3:
            raise MjcfValueError(
                f"friction must be a length 3 array or a single number, found {friction!r}"
            )
        self.friction = list(friction)
        self.solref = [0.02, 1.0] if solref is None else solref
        self.solimp = [0.9, 0.95, 0.001] if solimp is None else solimp
        self.material = material
        if isinstance(material, str) and material == "default":
            self.append_material(CustomMaterial(texture=self.rgba, tex_name="tex", mat_name="mat"))
        elif material is not None:
            self.append_material(material)
        self.joint_specs = joint_specs(joints, [self.get_joint_attrib_template()])
        self.sanity_check()
        self._obj = self._get_object_subtree()
        self._get_object_properties()

    def _get_object_subtree(self) -> AnyElement:
        return self._get_object_subtree_(ob_type=self.geom_type)

    def _get_object_subtree_(self, ob_type: str = "box") -> AnyElement:
        """The body: collision geom ``g0``, visual geom ``g0_vis``, joints, ``default_site``."""
        children: list[AnyElement] = []
        base = {"name": "g0", "type": ob_type, "size": array_to_string(self.size)}
        if self.obj_type in {"collision", "all"}:
            collision: dict[str, Any] = dict(base)  # robosuite deep-copies: all text
            collision.update(self.get_collision_attrib_template())
            collision["density"] = str(self.density)
            collision["friction"] = array_to_string(self.friction)
            collision["solref"] = array_to_string(self.solref)
            collision["solimp"] = array_to_string(self.solimp)
            children.append(rs_geom(**collision))
        if self.obj_type in {"visual", "all"}:
            visual: dict[str, Any] = dict(base)
            visual.update(self.get_visual_attrib_template())
            visual["name"] += "_vis"
            if isinstance(self.material, str) and self.material == "default":
                visual["rgba"] = "0.5 0.5 0.5 1"
                visual["material"] = "mat"
            elif self.material is not None:
                visual["material"] = material_parts(self.material)[0]
            else:
                visual["rgba"] = array_to_string(self.rgba)
            children.append(rs_geom(**visual))
        children.extend(rs_joint(**spec) for spec in self.joint_specs)
        children.append(rs_site(**self._default_site()))
        return with_children(_MAIN_BODY, children)
