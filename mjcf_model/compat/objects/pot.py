"""robosuite's ``PotWithHandlesObject``: an open box with a handle on each side.

>>> pot = PotWithHandlesObject("pot")
>>> pot.handle0_geoms, pot.important_sites["center"]
(['pot_handle0_c', 'pot_handle0_-', 'pot_handle0_+'], 'pot_center')
"""

from __future__ import annotations

from typing import Any

import numpy as np

from mjcf_model.compat.mjcf_utils.constants import BLUE, GREEN, RED
from mjcf_model.compat.mjcf_utils.text import array_to_string
from mjcf_model.compat.objects.base import Vector
from mjcf_model.compat.objects.composite import CompositeObject
from mjcf_model.compat.objects.recipes import (
    WALL_TURNS,
    add_geom,
    centred,
    looks,
    textured,
    wall_offsets,
)

__all__ = ["PotWithHandlesObject"]


def _color(given: Any, default: list[float]) -> Any:
    """A given colour as an array (robosuite's), or ``default`` for none (or an empty one)."""
    return default if given is None or len(given) == 0 else np.array(given)


class PotWithHandlesObject(CompositeObject):
    """robosuite's ``PotWithHandlesObject``: an open box with a handle on each side (y).

    Args:
        name: Name of the object.
        body_half_size: Half-size of the pot's box.
        handle_radius: Half-thickness of the handles' bars.
        handle_length: How far a handle reaches out.
        handle_width: Width of a handle.
        handle_friction: Sliding friction of the handles.
        density: Density of every geom.
        use_texture: Red, green and blue wood; otherwise the colours below.
        rgba_body: Colour of the pot (default red).
        rgba_handle_0: Colour of handle 0, on +y (default green).
        rgba_handle_1: Colour of handle 1, on -y (default blue).
        solid_handle: Each handle is one box instead of a bar and two arms.
        thickness: Thickness of the base and the walls.

    ``total_size`` is 3 x 3, as in robosuite (its size computation stacks a vector).
    A numpy colour works here (robosuite: ``ValueError``).

    """

    _robosuite_class = ("robosuite.models.objects", "PotWithHandlesObject")

    def __init__(
        self,
        name: str,
        body_half_size: Any = (0.07, 0.07, 0.07),
        handle_radius: float = 0.01,
        handle_length: float = 0.09,
        handle_width: float = 0.09,
        handle_friction: float = 1.0,
        density: Any = 1000,
        use_texture: bool = True,
        rgba_body: Any = None,
        rgba_handle_0: Any = None,
        rgba_handle_1: Any = None,
        solid_handle: bool = False,
        thickness: float = 0.01,
    ) -> None:
        self._name = name
        self.body_half_size = np.array(body_half_size)
        self.thickness = thickness
        self.handle_radius = handle_radius
        self.handle_length = handle_length
        self.handle_width = handle_width
        self.handle_friction = handle_friction
        self.density = density
        self.use_texture = use_texture
        self.rgba_body = _color(rgba_body, RED)
        self.rgba_handle_0 = _color(rgba_handle_0, GREEN)
        self.rgba_handle_1 = _color(rgba_handle_1, BLUE)
        self.solid_handle = solid_handle
        self._handles: tuple[list[str], list[str]] = ([], [])
        self.pot_base = ["base"]
        self._important_sites: dict[str, str] = {}
        super().__init__(**self._get_geom_attrs())
        for texture, tex_name, mat_name in (
            ("WoodRed", "redwood", "pot_mat"),
            ("WoodGreen", "greenwood", "handle0_mat"),
            ("WoodBlue", "bluewood", "handle1_mat"),
        ):
            self.append_material(textured(texture, tex_name, mat_name, texrepeat="1 1"))

    def _get_geom_attrs(self) -> dict[str, Any]:
        """The arguments of ``CompositeObject`` (robosuite's method of the same name)."""
        half, thickness = self.body_half_size, self.thickness
        radius, length, width = self.handle_radius, self.handle_length, self.handle_width
        full = np.array((half, half + length * 2, half))
        arguments: dict[str, Any] = {}
        wood = looks(self.use_texture, "pot_mat", self.rgba_body)
        body = {**wood, "geom_frictions": None, "density": self.density}
        base = np.array([half[0], half[1], thickness / 2])
        add_geom(arguments, "base", "box", (0, 0, -half[2] + thickness / 2), base, **body)
        xs, ys = wall_offsets(half[0] - thickness / 2, half[1] - thickness / 2)
        widths = np.array([half[0], half[1], half[0], half[1]])
        for i, (x, y, wall_width, turn) in enumerate(zip(xs, ys, widths, WALL_TURNS, strict=True)):
            wall = np.array([thickness / 2, wall_width, half[2]])
            add_geom(arguments, f"body{i}", "box", (x, y, 0), wall, turn, **body)
        height = half[2] - radius
        sites: list[dict[str, Any]] = []
        colors = (self.rgba_handle_0, self.rgba_handle_1)
        for i, (names, side, rgba) in enumerate(
            zip(self._handles, (1.0, -1.0), colors, strict=True)
        ):
            names.clear()
            centre = np.array((0, side * (half[1] + length), height))
            handle = {
                **looks(self.use_texture, f"handle{i}_mat", rgba),
                "geom_frictions": (self.handle_friction, 0.005, 0.0001),
                "density": self.density,
            }
            bars: list[tuple[str, Any, Any]]
            if self.solid_handle:
                bars = [(f"handle{i}", centre, np.array([width / 2, length / 2, radius]))]
            else:  # a bar across, and an arm from each of its ends to the pot
                arm, reach = np.array([radius, length / 2, radius]), side * (half[1] + length / 2)
                bars = [
                    (f"handle{i}_c", centre, np.array([width / 2 + radius, radius, radius])),
                    (f"handle{i}_-", (-1.0 * width / 2, reach, height), arm),
                    (f"handle{i}_+", (1.0 * width / 2, reach, height), arm),
                ]
            for bar_name, place, bar_size in bars:
                names.append(bar_name)
                add_geom(arguments, bar_name, "box", place, bar_size, **handle)
            site: dict[str, Any] = self.get_site_attrib_template()
            site.update(
                name=f"handle{i}",
                pos=array_to_string(centre - side * np.array([0, 0.005, 0])),
                size="0.005",
                rgba=rgba,
            )
            sites.append(site)
            self._important_sites[f"handle{i}"] = self.naming_prefix + f"handle{i}"
        sites.append({**self.get_site_attrib_template(), "name": "center", "size": "0.005"})
        self._important_sites["center"] = self.naming_prefix + "center"
        return {**arguments, **centred(self.name, full / 2.0), "sites": sites}

    @property
    def handle_distance(self) -> Any:
        """The distance between the two handles' ends."""
        return self.body_half_size[1] * 2 + self.handle_length * 2

    @property
    def handle0_geoms(self) -> list[str]:
        """The geoms of handle 0 (+y)."""
        return list(self.correct_naming(self._handles[0]))

    @property
    def handle1_geoms(self) -> list[str]:
        """The geoms of handle 1 (-y)."""
        return list(self.correct_naming(self._handles[1]))

    @property
    def handle_geoms(self) -> list[str]:
        """The geoms of both handles."""
        return self.handle0_geoms + self.handle1_geoms

    @property
    def important_sites(self) -> dict[str, Any]:
        """The object's site, and ``handle0``, ``handle1`` and ``center``."""
        return {**super().important_sites, **self._important_sites}

    @property
    def bottom_offset(self) -> Vector:
        """The bottom of the pot."""
        return np.array([0, 0, -1 * self.body_half_size[2]])

    @property
    def top_offset(self) -> Vector:
        """The top of the pot."""
        return np.array([0, 0, self.body_half_size[2]])

    @property
    def horizontal_radius(self) -> Any:
        """``sqrt(2)`` times the largest half-size plus the handle length."""
        return np.sqrt(2) * (max(self.body_half_size) + self.handle_length)
