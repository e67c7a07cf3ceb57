"""robosuite's round objects made of many small geoms: ``ConeObject``, ``HollowCylinderObject``.

>>> cone = ConeObject("cone")
>>> cone.n, len(cone.contact_geoms), cone.get_obj().find("geom").get("size")
(9, 9, '0.0425 0.002777777777777778')
>>> ring = HollowCylinderObject("ring", ngeoms=6, make_half=True)
>>> ring.contact_geoms
['ring_hc_0', 'ring_hc_1', 'ring_hc_2', 'ring_hc_3']
"""

from __future__ import annotations

from typing import Any

import numpy as np

from mjcf_model.compat.mjcf_utils.materials import CustomMaterial
from mjcf_model.compat.objects.composite import CompositeObject
from mjcf_model.compat.objects.generated import material_name
from mjcf_model.compat.objects.recipes import add_geom, centred, marker_site
from mjcf_model.errors import MjcfValueError

__all__ = ["ConeObject", "HollowCylinderObject"]


class _Shell(CompositeObject):
    """What the cone and the hollow cylinder share: their arguments, centre site and material."""

    def __init__(
        self,
        name: str,
        outer_radius: float,
        inner_radius: float,
        height: float,
        rgba: Any,
        material: Any,
        density: Any,
        solref: Any,
        solimp: Any,
        friction: Any,
    ) -> None:
        self._name = name
        self.rgba = rgba
        self.density = density
        self.friction = friction if friction is None else np.array(friction)
        self.solref = solref
        self.solimp = solimp
        self.has_material = material is not None
        if self.has_material:
            if not isinstance(material, CustomMaterial) and not hasattr(material, "mat_attrib"):
                raise MjcfValueError(f"material must be a CustomMaterial, got {material!r}")
            self.material = material
        self.r1 = inner_radius
        self.r2 = outer_radius
        self.height = height

    def _geom_arguments(self) -> dict[str, Any]:
        """The geoms and their arguments, by ``CompositeObject`` parameter (no sites)."""
        raise NotImplementedError

    def _build(self) -> None:
        super().__init__(**self._get_geom_attrs())
        if self.has_material:
            self.append_material(self.material)

    def _get_geom_attrs(self) -> dict[str, Any]:
        arguments = self._geom_arguments()
        arguments["sites"] = [marker_site("center", (0, 0, 0))]
        return arguments

    def _add(self, arguments: dict[str, Any], *geom: Any) -> None:
        """Add a geom (name, type, location, size, quat) with the shell's looks, condim 4."""
        material = material_name(self.material) if self.has_material else None
        looking = {"geom_rgbas": self.rgba, "geom_materials": material}
        add_geom(arguments, *geom, **looking, geom_frictions=self.friction, geom_condims=4)

    def _base(self, total_size: Any) -> dict[str, Any]:
        more = {"density": self.density, "solref": self.solref, "solimp": self.solimp}
        return centred(self.name, total_size, **more)


class ConeObject(_Shell):
    """robosuite's ``ConeObject``: ``ngeoms`` stacked discs (or boxes) narrowing upwards.

    Args:
        name: Name of the object.
        outer_radius: Radius of the bottom disc.
        inner_radius: Radius of the top disc.
        height: Height of the stack.
        ngeoms: How many discs; an even number is made odd (one more).
        use_box: Square boxes instead of discs.
        rgba: Colour of the visual geoms.
        material: A ``CustomMaterial`` (this library's or robosuite's) for every geom.
        density: Density of every geom.
        solref: Contact ``solref`` of every geom.
        solimp: Contact ``solimp`` of every geom.
        friction: Friction of every geom (``None``: robosuite's default).

    """

    _robosuite_class = ("robosuite.models.objects", "ConeObject")

    def __init__(
        self,
        name: str,
        outer_radius: float = 0.0425,
        inner_radius: float = 0.03,
        height: float = 0.05,
        ngeoms: int = 8,
        use_box: bool = False,
        rgba: Any = None,
        material: Any = None,
        density: Any = 1000.0,
        solref: Any = (0.02, 1.0),
        solimp: Any = (0.9, 0.95, 0.001),
        friction: Any = None,
    ) -> None:
        super().__init__(
            name, outer_radius, inner_radius, height, rgba, material, density, solref, solimp,
            friction,
        )  # fmt: skip
        self.n = ngeoms + 1 if ngeoms % 2 == 0 else ngeoms
        self.unit_height = height / self.n / 2.0
        self.unit_r = (self.r2 - self.r1) / (self.n - 1)
        self.use_box = use_box
        self._build()

    def _geom_arguments(self) -> dict[str, Any]:
        arguments: dict[str, Any] = {}
        layers = cone_layers(self.r1, self.unit_r, self.unit_height, self.n, self.use_box)
        kind = "box" if self.use_box else "cylinder"
        for i, (location, size) in enumerate(layers):
            self._add(arguments, f"c_{i}", kind, location, size, None)
        return {**arguments, **self._base([self.r2, self.r2, self.height / 2.0])}


def cone_layers(
    inner_radius: float, step: float, half_height: float, count: int, use_box: bool
) -> list[tuple[tuple[float, float, float], tuple[float, ...]]]:
    """The centres and sizes of a cone's ``count`` layers (odd), bottom (widest) first.

    Each layer is ``step`` wider than the one above and ``2 * half_height`` high,
    the middle one at 0: robosuite's ``ConeObject`` geometry, also the tip of its
    ``HookFrame``.

    Examples:
        >>> [size for _, size in cone_layers(0.01, 0.01, 0.005, 3, use_box=False)]
        [(0.03, 0.005), (0.02, 0.005), (0.01, 0.005)]

    """
    side = (count - 1) // 2
    radii = [inner_radius + i * step for i in range(count)][::-1]
    return [
        (
            (0.0, 0.0, level * half_height * 2.0),
            (radius, radius, half_height) if use_box else (radius, half_height),
        )
        for level, radius in zip(range(-side, side + 1), radii, strict=True)
    ]


class HollowCylinderObject(_Shell):
    """robosuite's ``HollowCylinderObject``: a ring of ``ngeoms`` boxes (``height`` is half).

    Args:
        name: Name of the object.
        outer_radius: Outer radius of the ring.
        inner_radius: Inner radius of the ring.
        height: Half-height of the boxes.
        ngeoms: How many boxes make the whole ring.
        rgba: Colour of the visual geoms.
        material: A ``CustomMaterial`` (this library's or robosuite's) for every geom.
        density: Density of every geom.
        solref: Contact ``solref`` of every geom.
        solimp: Contact ``solimp`` of every geom.
        friction: Friction of every geom (``None``: robosuite's default).
        make_half: Only the boxes of one half (``ngeoms // 2 + 1``).

    """

    _robosuite_class = ("robosuite.models.objects", "HollowCylinderObject")

    def __init__(
        self,
        name: str,
        outer_radius: float = 0.0425,
        inner_radius: float = 0.03,
        height: float = 0.05,
        ngeoms: int = 8,
        rgba: Any = None,
        material: Any = None,
        density: Any = 1000.0,
        solref: Any = (0.02, 1.0),
        solimp: Any = (0.9, 0.95, 0.001),
        friction: Any = None,
        make_half: bool = False,
    ) -> None:
        super().__init__(
            name, outer_radius, inner_radius, height, rgba, material, density, solref, solimp,
            friction,
        )  # fmt: skip
        self.make_half = make_half
        self.n = ngeoms
        self.unit_box_width = self.r2 * np.sin(np.pi / self.n)
        self.unit_box_height = (self.r2 - self.r1) * np.cos(np.pi / self.n) / 2.0
        self.unit_box_depth = self.height
        self.int_r = self.r1 * np.cos(np.pi / self.n) + self.unit_box_height
        self._build()

    def _geom_arguments(self) -> dict[str, Any]:
        arguments: dict[str, Any] = {}
        step = 2.0 * np.pi / self.n
        size = (self.unit_box_height, self.unit_box_width, self.unit_box_depth)
        for i in range(self.n // 2 + 1 if self.make_half else self.n):
            angle = np.pi - i * step
            centre = np.array([self.int_r * np.cos(angle), self.int_r * np.sin(angle), 0.0])
            quat = tuple(np.array([np.cos(angle / 2.0), 0.0, 0.0, np.sin(angle / 2.0)]))
            self._add(arguments, f"hc_{i}", "box", tuple(centre), tuple(np.array(size)), quat)
        return {**arguments, **self._base([self.r2, self.r2, self.height])}
