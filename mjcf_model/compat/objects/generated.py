"""Objects built in code, as robosuite does: ``MujocoGeneratedObject`` and the primitives.

Materials are ``CustomMaterial`` objects, this library's or robosuite's own; the
``"default"`` material is a flat texture of the object's colour (robosuite writes a PNG).
Drawn sizes use the compatible ``get_size``, so a seeded generator gives robosuite's sizes.

>>> ball = PrimitiveObject("ball", size=[0.03], material="default")
>>> [child.get("name") for child in ball.asset]
['ball_tex', 'ball_mat']
>>> box = BoxObject("cube", size_min=[0.02] * 3, size_max=[0.022] * 3, rng=np.random.default_rng(0))
>>> box.get_obj()[0].get("size")
'0.021273923374642907 0.02053957342752774 0.02008194704787239'
>>> float(box.horizontal_radius), box.bottom_offset.tolist()
(0.029571166570410805, [0.0, 0.0, -0.02008194704787239])
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any, ClassVar

import numpy as np

from mjcf_model.compat.materials import material_nodes
from mjcf_model.compat.mjcf_utils.builders import body_node, geom_node, joint_node, site_node
from mjcf_model.compat.mjcf_utils.constants import RED
from mjcf_model.compat.mjcf_utils.materials import flat_material
from mjcf_model.compat.mjcf_utils.text import array_to_string, get_size
from mjcf_model.compat.objects.base import MujocoObject, Vector
from mjcf_model.compat.objects.habits import OBJECT_COLLISION_RGBA_TEXT, value_text
from mjcf_model.compat.objects.naming import robosuite_prefixed
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement
from mjcf_model.tree.traversal import with_children

__all__ = [
    "BallObject",
    "BoxObject",
    "CapsuleObject",
    "CylinderObject",
    "MujocoGeneratedObject",
    "PrimitiveObject",
]

#: The bodies of a primitive and of a composite before their children (robosuite's ``new_body``).
_MAIN_BODY, _ROOT_BODY = body_node(value_text, "main"), body_node(value_text, "root")


def material_name(material: Any) -> str:
    """The name geoms give a ``CustomMaterial`` (ours or robosuite's), as robosuite reads it.

    Examples:
        >>> from mjcf_model.compat.mjcf_utils import CustomMaterial
        >>> material_name(CustomMaterial("WoodRed", "wood", "wood_mat"))
        'wood_mat'

    """
    return str(material.name)


def material_parts(material: Any) -> tuple[str, str, bool, AnyElement, AnyElement]:
    """The material name, texture name, ``shared`` flag, and texture and material nodes.

    ``material`` is a ``CustomMaterial``, ours or robosuite's: its attributes are read as
    robosuite's ``new_element`` reads them.
    """
    texture, node = material_nodes(material, text=value_text)
    return material_name(material), texture.attributes["name"], bool(material.shared), texture, node


def half_extents(geom_type: Any, size: Any) -> Any:
    """The x, y and z half-lengths of a geom's bounding box, from its type and size.

    robosuite's own expressions (its primitives' offsets and ``CompositeObject``'s placing).

    Raises:
        MjcfValueError: a geom type other than box, ellipsoid, sphere, capsule, cylinder.

    Examples:
        >>> half_extents("capsule", [0.02, 0.04])
        [0.02, 0.02, 0.06]

    """
    if geom_type in ("box", "ellipsoid"):
        return size
    if geom_type == "sphere":
        return [size[0], size[0], size[0]]
    if geom_type == "capsule":
        return [size[0], size[0], size[0] + size[1]]
    if geom_type == "cylinder":
        return [size[0], size[0], size[1]]
    raise MjcfValueError(
        f"unsupported geom type {geom_type!r}; supported: box, ellipsoid, sphere, capsule, cylinder"
    )


class MujocoGeneratedObject(MujocoObject):
    """robosuite's ``MujocoGeneratedObject``: geom templates and (shared) materials."""

    _robosuite_class = ("robosuite.models.objects", "MujocoGeneratedObject")
    joint_specs: list[dict[str, Any]]
    site_specs: list[dict[str, Any]]

    def __init__(self, obj_type: str = "all", duplicate_collision_geoms: bool = True) -> None:
        super().__init__(obj_type=obj_type, duplicate_collision_geoms=duplicate_collision_geoms)
        self.shared_materials: set[str] = set()
        self.shared_textures: set[str] = set()

    def sanity_check(self) -> None:
        """Check the arguments (subclasses do)."""

    @staticmethod
    def get_collision_attrib_template() -> dict[str, str]:
        """Attributes of a collision geom: group 0, the object collision colour."""
        return {"group": "0", "rgba": OBJECT_COLLISION_RGBA_TEXT}

    @staticmethod
    def get_visual_attrib_template() -> dict[str, str]:
        """Attributes of a visual geom: no contacts, no mass, group 1."""
        return {"conaffinity": "0", "contype": "0", "mass": "1e-8", "group": "1"}

    def _geom_pair(
        self,
        obj_type: Any,
        base: dict[str, Any],
        collision: Callable[[], dict[str, Any]],
        visual: dict[str, Any],
    ) -> list[AnyElement]:
        """The collision geom and visual geom ``<name>_vis`` that ``obj_type`` asks for.

        Each is ``base``, its template, then its own attributes (``collision()``, called
        only when that geom is made), in robosuite's order.
        """
        geoms: list[AnyElement] = []
        if obj_type in {"collision", "all"}:
            template = self.get_collision_attrib_template()
            geoms.append(geom_node(value_text, **{**base, **template, **collision()}))
        if obj_type in {"visual", "all"}:
            template = self.get_visual_attrib_template()
            geoms.append(
                geom_node(
                    value_text, **{**base, **template, **visual, "name": base["name"] + "_vis"}
                )
            )
        return geoms

    def _root_with_specs(self, more: Iterable[AnyElement] = ()) -> AnyElement:
        """A composite's ``root`` body: the joints and the sites of the specs, then ``more``."""
        children: list[AnyElement] = [joint_node(value_text, **spec) for spec in self.joint_specs]
        children.extend(site_node(value_text, **spec) for spec in self.site_specs)
        return with_children(_ROOT_BODY, [*children, *more])

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

    The defaults are robosuite's (``size`` ``[0.05] * 3``, red, ``density`` 1000...);
    ``friction`` may be one number (the sliding one). ``material``: ``None``,
    ``"default"`` (a flat material of ``rgba``) or a material (ours or robosuite's).

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
        self.rgba = list(RED if rgba is None else rgba)
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
            self.append_material(flat_material(self.rgba, "tex", "mat"))
        elif material is not None:
            self.append_material(material)
        self.joint_specs = self._named_joints(joints)
        self.sanity_check()
        self._obj = self._get_object_subtree()
        self._get_object_properties()

    def _get_object_subtree(self) -> AnyElement:
        return self._get_object_subtree_(ob_type=self.geom_type)

    def _get_object_subtree_(self, ob_type: str = "box") -> AnyElement:
        """The body: collision geom ``g0``, visual geom ``g0_vis``, joints, ``default_site``."""
        base = {"name": "g0", "type": ob_type, "size": array_to_string(self.size)}
        if isinstance(self.material, str) and self.material == "default":
            visual = {"rgba": "0.5 0.5 0.5 1", "material": "mat"}
        elif self.material is not None:
            visual = {"material": material_name(self.material)}  # its nodes: once, when added
        else:
            visual = {"rgba": array_to_string(self.rgba)}
        collision = {"density": str(self.density), "friction": array_to_string(self.friction)}
        children = self._geom_pair(
            self.obj_type,
            base,
            lambda: {
                **collision,
                "solref": array_to_string(self.solref),
                "solimp": array_to_string(self.solimp),
            },
            visual,
        )
        children.extend(joint_node(value_text, **spec) for spec in self.joint_specs)
        children.append(site_node(value_text, **self._default_site()))
        return with_children(_MAIN_BODY, children)


class _SizedPrimitive(PrimitiveObject):
    """The constructor the four primitives share: robosuite's signature, a drawn size."""

    #: robosuite's upper and lower bounds of a drawn size (their length is the size's).
    _size_max: ClassVar[tuple[float, ...]] = (0.07, 0.07, 0.07)
    _size_min: ClassVar[tuple[float, ...]] = (0.03, 0.03, 0.03)
    #: The shape named in the size check's error.
    _shape: ClassVar[str] = "box"
    #: This class's own defaults where robosuite's ``PrimitiveObject`` has others (``None``: its).
    _default_friction: ClassVar[tuple[float, ...] | None] = None
    _default_solref: ClassVar[tuple[float, ...] | None] = None
    _default_joints: ClassVar[tuple[dict[str, str], ...] | None] = None

    def __init__(
        self,
        name: str,
        size: Any = None,
        size_max: Any = None,
        size_min: Any = None,
        density: Any = None,
        friction: Any = None,
        rgba: Any = None,
        solref: Any = None,
        solimp: Any = None,
        material: Any = None,
        joints: Any = "default",
        obj_type: str = "all",
        duplicate_collision_geoms: bool = True,
        rng: Any = None,
    ) -> None:
        bounds = list(self._size_max), list(self._size_min)
        try:
            size = get_size(size, size_max, size_min, *bounds, rng=rng)
        except ValueError as error:
            raise MjcfValueError(str(error)) from error
        if self._default_joints is not None and isinstance(joints, str) and joints == "default":
            joints = [dict(joint) for joint in self._default_joints]
        if friction is None and self._default_friction is not None:
            friction = list(self._default_friction)
        if solref is None and self._default_solref is not None:
            solref = list(self._default_solref)
        super().__init__(
            name=name,
            size=size,
            rgba=rgba,
            density=density,
            friction=friction,
            solref=solref,
            solimp=solimp,
            material=material,
            joints=joints,
            obj_type=obj_type,
            duplicate_collision_geoms=duplicate_collision_geoms,
        )

    def sanity_check(self) -> None:
        """As many sizes as the bounds have."""
        count = len(self._size_max)
        if len(self.size) != count:
            raise MjcfValueError(
                f"{self._shape} size should have length {count}, found {self.size!r}"
            )

    bottom_offset = property(
        lambda self: np.array([0, 0, -1 * half_extents(self.geom_type, self.size)[2]]), doc="Below."
    )
    top_offset = property(
        lambda self: np.array([0, 0, half_extents(self.geom_type, self.size)[2]]), doc="Above."
    )
    horizontal_radius = property(lambda self: self.size[0], doc="The radius.")

    def get_bounding_box_half_size(self) -> Vector:
        """The half-lengths along x, y and z."""
        return np.array(half_extents(self.geom_type, self.size))


class BoxObject(_SizedPrimitive):
    """A box; ``size`` is three half-lengths (drawn from 0.03 to 0.07 by default)."""

    _robosuite_class = ("robosuite.models.objects", "BoxObject")
    geom_type = "box"
    horizontal_radius = property(
        lambda self: np.linalg.norm(self.size[0:2], 2), doc="The length of the x, y half-lengths."
    )


class BallObject(_SizedPrimitive):
    """A sphere; ``size`` is its radius. It takes ``rng`` (robosuite's draws unseeded)."""

    _robosuite_class = ("robosuite.models.objects", "BallObject")
    geom_type = "sphere"
    _size_max = (0.07,)
    _size_min = (0.03,)
    _shape = "ball"


class CylinderObject(_SizedPrimitive):
    """A cylinder; ``size`` is radius and half-length, with robosuite's stability defaults."""

    _robosuite_class = ("robosuite.models.objects", "CylinderObject")
    geom_type = "cylinder"
    _size_max = (0.07, 0.07)
    _size_min = (0.03, 0.03)
    _shape = "cylinder"
    _default_friction = (1, 0.01, 0.001)
    _default_solref = (0.01, 0.5)
    _default_joints = ({"type": "free", "damping": "0.0001"},)

    @staticmethod
    def get_collision_attrib_template() -> dict[str, str]:
        """The collision template with a 0.001 margin."""
        return {**MujocoGeneratedObject.get_collision_attrib_template(), "margin": "0.001"}


class CapsuleObject(_SizedPrimitive):
    """A capsule; ``size`` is radius and half-length of the cylinder part. It takes ``rng``."""

    _robosuite_class = ("robosuite.models.objects", "CapsuleObject")
    geom_type = "capsule"
    _size_max = (0.07, 0.07)
    _size_min = (0.03, 0.03)
    _shape = "capsule"
