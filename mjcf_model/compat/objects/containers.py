"""robosuite's boxes with walls: ``Bin``, ``Lid`` and ``StandWithMount``.

>>> Bin("bin").base_geoms, Lid("lid").handle_geoms, StandWithMount("stand").init_quat.tolist()
(['bin_base'], ['lid_handle'], [0.0, 0.707107, 0.0, 0.707107])
"""

from __future__ import annotations

from typing import Any

import numpy as np

from mjcf_model.compat.objects.base import Vector
from mjcf_model.compat.objects.composite import CompositeObject
from mjcf_model.compat.objects.recipes import (
    WALL_TURNS,
    add_geom,
    centred,
    looks,
    marker_site,
    textured,
    wall_offsets,
)

__all__ = ["Bin", "Lid", "StandWithMount"]

#: The see-through white of transparent walls and lids.
_GLASS = {"geom_rgbas": (1.0, 1.0, 1.0, 0.3), "geom_materials": None}


class Bin(CompositeObject):
    """robosuite's ``Bin``: a dark wood base and four walls, open at the top.

    Args:
        name: Name of the object.
        bin_size: Full size (x, y, z).
        wall_thickness: Thickness of the base and the walls.
        transparent_walls: See-through white walls (no material).
        friction: Friction of every geom (``None``: robosuite's default).
        density: Density of every geom.
        use_texture: Dark wood; otherwise ``rgba``.
        rgba: Colour without texture.

    """

    _robosuite_class = ("robosuite.models.objects", "Bin")

    def __init__(
        self,
        name: str,
        bin_size: Any = (0.3, 0.3, 0.15),
        wall_thickness: float = 0.01,
        transparent_walls: bool = True,
        friction: Any = None,
        density: Any = 1000.0,
        use_texture: bool = True,
        rgba: Any = (0.2, 0.1, 0.0, 1.0),
    ) -> None:
        self._name = name
        self.bin_size = np.array(bin_size)
        self.wall_thickness = wall_thickness
        self.transparent_walls = transparent_walls
        self.friction = friction if friction is None else np.array(friction)
        self.density = density
        self.use_texture = use_texture
        self.rgba = rgba
        self.bin_mat_name = "dark_wood_mat"
        super().__init__(**self._get_geom_attrs())
        self.append_material(textured("WoodDark", "dark_wood", self.bin_mat_name))

    def _get_geom_attrs(self) -> dict[str, Any]:
        """The arguments of ``CompositeObject`` (robosuite's method of the same name)."""
        size, thickness = self.bin_size, self.wall_thickness
        wood = looks(self.use_texture, self.bin_mat_name, self.rgba)
        wall = _GLASS if self.transparent_walls else wood
        arguments: dict[str, Any] = {}
        base = (np.array((size[0], size[1], thickness)) - np.array((thickness, thickness, 0))) / 2
        where = (0, 0, -(size[2] - thickness) / 2)
        add_geom(arguments, "base", "box", where, base, **wood, geom_frictions=self.friction)
        xs, ys = wall_offsets((size[0] - thickness) / 2, (size[1] - thickness) / 2)
        widths = np.array([size[0], size[1], size[0], size[1]])
        for i, (x, y, width, turn) in enumerate(zip(xs, ys, widths, WALL_TURNS, strict=True)):
            wall_size = (thickness / 2, width / 2, size[2] / 2)
            add_geom(
                arguments, f"wall{i}", "box", (x, y, 0), wall_size, turn, **wall,
                geom_frictions=self.friction,
            )  # fmt: skip
        return {**arguments, **centred(self.name, size / 2.0, density=self.density)}

    @property
    def base_geoms(self) -> list[str]:
        """The base geom's name."""
        return [self.correct_naming("base")]


class Lid(CompositeObject):
    """robosuite's ``Lid``: a flat top with a box handle on it (twice the top's density).

    Args:
        name: Name of the object.
        lid_size: Full size of the top (x, y, z).
        handle_size: Full size of the handle.
        transparent: A see-through white top (no material).
        friction: Friction of every geom (``None``: robosuite's default).
        density: Density of the top.
        use_texture: Dark wood; otherwise ``rgba``.
        rgba: Colour without texture.

    """

    _robosuite_class = ("robosuite.models.objects", "Lid")

    def __init__(
        self,
        name: str,
        lid_size: Any = (0.3, 0.3, 0.01),
        handle_size: Any = (0.02, 0.08, 0.03),
        transparent: bool = True,
        friction: Any = None,
        density: Any = 250.0,
        use_texture: bool = True,
        rgba: Any = (0.2, 0.1, 0.0, 1.0),
    ) -> None:
        self._name = name
        self.lid_size = np.array(lid_size)
        self.handle_size = np.array(handle_size)
        self.transparent = transparent
        self.friction = friction if friction is None else np.array(friction)
        self.density = density
        self.use_texture = use_texture
        self.rgba = rgba
        self.lid_mat_name = "dark_wood_mat"
        super().__init__(**self._get_geom_attrs())
        self.append_material(textured("WoodDark", "dark_wood", self.lid_mat_name))

    def _get_geom_attrs(self) -> dict[str, Any]:
        """The arguments of ``CompositeObject`` (robosuite's method of the same name)."""
        top, handle = self.lid_size, self.handle_size
        full = np.array([top[0], top[1], top[2] + handle[2]])
        wood = looks(self.use_texture, self.lid_mat_name, self.rgba)
        top_looks = _GLASS if self.transparent else wood
        arguments: dict[str, Any] = {}
        for geom_name, where, size, looking, density in (
            ("top", (0, 0, (-full[2] + top[2]) / 2), np.array((full[0], full[1], top[2])) / 2,
             top_looks, self.density),
            ("handle", (0, 0, (full[2] - handle[2]) / 2), handle / 2, wood, self.density * 2),
        ):  # fmt: skip
            add_geom(
                arguments, geom_name, "box", where, size, **looking,
                geom_frictions=self.friction, density=density,
            )  # fmt: skip
        return {**arguments, **centred(self.name, full / 2.0)}

    @property
    def handle_geoms(self) -> list[str]:
        """The handle geom's name."""
        return [self.correct_naming("handle")]


class StandWithMount(CompositeObject):
    """robosuite's ``StandWithMount``: a brass base with a square mount of four walls.

    Args:
        name: Name of the object.
        size: Full size of the base's box (x, y, z).
        mount_location: Where the mount stands on the base (x, y).
        mount_width: Outer width of the mount.
        wall_thickness: Thickness of the mount's walls.
        base_thickness: Thickness of the base.
        initialize_on_side: ``init_quat`` lays the stand on its side.
        add_hole_vis: A green visual square marks the mount's hole (``hole_vis_vis``).
        friction: Friction of every geom (``None``: robosuite's default).
        density: Density of every geom.
        solref: Contact ``solref`` of every geom.
        solimp: Contact ``solimp`` of every geom.
        use_texture: Brass; otherwise ``rgba``.
        rgba: Colour without texture.

    """

    _robosuite_class = ("robosuite.models.objects", "StandWithMount")

    def __init__(
        self,
        name: str,
        size: Any = (0.3, 0.3, 0.15),
        mount_location: Any = (0.0, 0.0),
        mount_width: float = 0.05,
        wall_thickness: float = 0.01,
        base_thickness: float = 0.01,
        initialize_on_side: bool = True,
        add_hole_vis: bool = False,
        friction: Any = None,
        density: Any = 1000.0,
        solref: Any = (0.02, 1.0),
        solimp: Any = (0.9, 0.95, 0.001),
        use_texture: bool = True,
        rgba: Any = (0.2, 0.1, 0.0, 1.0),
    ) -> None:
        self._name = name
        self.size = np.array(size)
        self.mount_location = np.array(mount_location)
        self.mount_width = mount_width
        self.wall_thickness = wall_thickness
        self.base_thickness = base_thickness
        self.initialize_on_side = initialize_on_side
        self.add_hole_vis = add_hole_vis
        self.friction = friction if friction is None else np.array(friction)
        self.solref = solref
        self.solimp = solimp
        self.density = density
        self.use_texture = use_texture
        self.rgba = rgba
        self.mat_name = "brass_mat"
        super().__init__(**self._get_geom_attrs())
        self.append_material(textured("Brass", "brass", self.mat_name))

    def _get_geom_attrs(self) -> dict[str, Any]:
        """The arguments of ``CompositeObject`` (robosuite's method of the same name)."""
        size, mount, wall, base = (
            self.size, self.mount_location, self.wall_thickness, self.base_thickness,
        )  # fmt: skip
        brass = looks(self.use_texture, self.mat_name, self.rgba)
        brass = {**brass, "geom_frictions": self.friction}
        arguments: dict[str, Any] = {}
        base_size = np.array((size[0], size[1], base)) / 2
        add_geom(arguments, "base", "box", (0, 0, -(size[2] - base) / 2), base_size, **brass)
        inner = (self.mount_width - wall) / 2
        xs, ys = wall_offsets(inner, inner)
        wall_size = (wall / 2, self.mount_width / 2, (size[2] - base) / 2)
        for i, (x, y, turn) in enumerate(
            zip(xs + mount[0], ys + mount[1], WALL_TURNS, strict=True)
        ):
            add_geom(arguments, f"wall{i}", "box", (x, y, base / 2), wall_size, turn, **brass)
        more = {"density": self.density, "solref": self.solref, "solimp": self.solimp}
        if self.add_hole_vis:  # the geoms' types become a list, with one visual-only geom
            arguments["obj_types"] = ["all"] * len(arguments["geom_types"])
            side, where = 0.7 * inner, (mount[0], mount[1], size[2] / 2 - wall / 2)
            add_geom(
                arguments, "hole_vis", "box", where, (side, side, wall / 2),
                geom_rgbas=(0.0, 1.0, 0.0, 0.5), geom_materials=None,
                geom_frictions=self.friction, obj_types="visual",
            )  # fmt: skip
        arguments["sites"] = [marker_site("mount_site", (0, 0, size[2] / 2))]
        base_arguments = centred(self.name, size / 2.0, **more)
        if self.add_hole_vis:
            del base_arguments["obj_types"]
        return {**arguments, **base_arguments}

    @property
    def init_quat(self) -> Vector:
        """On its side (``x y z w``), or upright (an integer array, as robosuite's)."""
        if self.initialize_on_side:
            return np.array([0, 0.707107, 0, 0.707107])
        return np.array([0, 0, 0, 1])

    @property
    def base_geoms(self) -> list[str]:
        """The base geom's name."""
        return [self.correct_naming("base")]
