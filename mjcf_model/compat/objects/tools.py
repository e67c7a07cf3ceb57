"""robosuite's tools and frames: ``HammerObject``, ``HookFrame`` and ``RatchetingWrenchObject``.

>>> hammer = HammerObject("hammer", rng=np.random.default_rng(0))
>>> hammer.all_geoms
['hammer_handle', 'hammer_head', 'hammer_neck', 'hammer_face', 'hammer_claw']
>>> round(hammer.handle_length, 4), round(hammer.horizontal_radius, 4)
(0.1405, 0.0914)
>>> frame = HookFrame("frame", hook_height=0.03, tip_size=(0.01, 0.001, 0.005, 0.05))
>>> len(frame.contact_geoms), frame.init_quat.tolist()
(55, [-0.5, -0.5, 0.5, 0.5])
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from mjcf_model.compat.mjcf_utils.constants import BLUE, CYAN, GREEN, RED
from mjcf_model.compat.objects.base import MujocoObject, Vector
from mjcf_model.compat.objects.composite import CompositeObject
from mjcf_model.compat.objects.composite_body import CompositeBodyObject
from mjcf_model.compat.objects.generated import BoxObject
from mjcf_model.compat.objects.recipes import (
    UPRIGHT,
    add_geom,
    centred,
    looks,
    marker_site,
    textured,
)
from mjcf_model.compat.objects.shells import HollowCylinderObject, cone_layers
from mjcf_model.errors import MjcfValueError

__all__ = ["HammerObject", "HookFrame", "RatchetingWrenchObject"]


def _range(value: Any) -> Any:
    """A ``(low, high)`` range: ``value`` if it is one, else ``[value, value]``."""
    return value if isinstance(value, Iterable) else [value] * 2


class HammerObject(CompositeObject):
    """robosuite's ``HammerObject``: a handle, a head, a face on a neck, and a claw.

    The handle's radius, length, density and friction are drawn from their ranges
    (a number is a range of one value), then the head's half-size from
    ``[radius, 1.2 * radius]``: five draws from ``rng``, in robosuite's order, so a
    seeded generator gives robosuite's hammer and leaves it in the same state.

    Args:
        name: Name of the object.
        handle_shape: ``"box"`` or ``"cylinder"``.
        handle_radius: Range of the handle's radius.
        handle_length: Range of the handle's length.
        handle_density: Range of the handle's density.
        handle_friction: Range of the handle's sliding friction.
        head_density_ratio: The head's density over the handle's.
        use_texture: Wood and metal; otherwise the colours below.
        rgba_handle: Colour of the handle (default red).
        rgba_head: Colour of the head (default cyan).
        rgba_face: Colour of the neck and face (default blue).
        rgba_claw: Colour of the claw (default green).
        rng: The generator drawn from (``None``: a new, unseeded one, as robosuite).

    Raises:
        MjcfValueError: a handle shape other than box or cylinder (after the draws).

    """

    _robosuite_class = ("robosuite.models.objects", "HammerObject")

    def __init__(
        self,
        name: str,
        handle_shape: str = "box",
        handle_radius: Any = (0.015, 0.02),
        handle_length: Any = (0.1, 0.25),
        handle_density: Any = (100, 250),
        handle_friction: Any = (3.0, 5.0),
        head_density_ratio: float = 2.0,
        use_texture: bool = True,
        rgba_handle: Any = None,
        rgba_head: Any = None,
        rgba_face: Any = None,
        rgba_claw: Any = None,
        rng: np.random.Generator | None = None,
    ) -> None:
        self.rng = np.random.default_rng() if rng is None else rng
        self._name = name
        self.handle_shape = handle_shape
        self.head_density_ratio = head_density_ratio
        self.handle_radius_range = _range(handle_radius)
        self.handle_length_range = _range(handle_length)
        self.handle_density_range = _range(handle_density)
        self.handle_friction_range = _range(handle_friction)
        draw = self.rng.uniform
        self.handle_radius = draw(self.handle_radius_range[0], self.handle_radius_range[1])
        self.handle_length = draw(self.handle_length_range[0], self.handle_length_range[1])
        self.handle_density = draw(self.handle_density_range[0], self.handle_density_range[1])
        self.handle_friction = draw(self.handle_friction_range[0], self.handle_friction_range[1])
        self.head_halfsize = draw(self.handle_radius, self.handle_radius * 1.2)
        self.use_texture = use_texture
        self.rgba_handle = RED if rgba_handle is None else rgba_handle
        self.rgba_head = CYAN if rgba_head is None else rgba_head
        self.rgba_face = BLUE if rgba_face is None else rgba_face
        self.rgba_claw = GREEN if rgba_claw is None else rgba_claw
        super().__init__(**self._get_geom_attrs())
        self.append_material(textured("SteelScratched", "metal", "metal_mat"))
        self.append_material(textured("WoodLight", "wood", "wood_mat"))

    def _get_geom_attrs(self) -> dict[str, Any]:
        """The arguments of ``CompositeObject`` (robosuite's method of the same name)."""
        if self.handle_shape not in {"cylinder", "box"}:
            raise MjcfValueError(
                f"a hammer's handle_shape is 'box' or 'cylinder', got {self.handle_shape!r}"
            )
        half, radius, length = self.head_halfsize, self.handle_radius, self.handle_length
        full = np.array((3.2 * half, half, length + 2 * half))
        top = length / 2.0 + half
        sideways, face = (0.707106, 0, 0.707106, 0), self.rgba_face
        metal = {"geom_frictions": None, "density": self.handle_density * self.head_density_ratio}
        arguments: dict[str, Any] = {}
        handle = (
            [radius, length / 2.0]
            if self.handle_shape == "cylinder"
            else [radius] * 2 + [length / 2.0]
        )
        add_geom(
            arguments, "handle", self.handle_shape, (0, 0, 0), np.array(handle),
            **looks(self.use_texture, "wood_mat", self.rgba_handle),
            geom_frictions=(self.handle_friction, 0.005, 0.0001), density=self.handle_density,
        )  # fmt: skip
        for geom_name, geom_type, location, quat, size, rgba in (
            ("head", "box", (0, 0, top), UPRIGHT, [half * 2, half, half], self.rgba_head),
            ("neck", "cylinder", (half * 2.2, 0, top), sideways, [half * 0.8, half * 0.2], face),
            ("face", "cylinder", (half * 2.8, 0, top), sideways, [half, half * 0.4], face),
            (
                "claw", "box", (-half * 2, 0, top), (0.9238795, 0, 0.3826834, 0),
                [half * 0.7072, half * 0.95, half * 0.7072], self.rgba_claw,
            ),
        ):  # fmt: skip
            metal_looks = looks(self.use_texture, "metal_mat", rgba)
            add_geom(
                arguments,
                geom_name,
                geom_type,
                location,
                np.array(size),
                quat,
                **metal_looks,
                **metal,
            )
        return {**arguments, **centred(self.name, full / 2.0)}

    @property
    def init_quat(self) -> Vector:
        """Lying on one side or the other (``x y z w``): a new draw from ``rng`` at each read."""
        if self.rng.random() >= 0.5:
            return np.array([0.5, -0.5, 0.5, -0.5])
        return np.array([-0.5, -0.5, -0.5, -0.5])

    handle_geoms = property(lambda self: self.correct_naming(["handle"]), doc="The handle.")
    head_geoms = property(lambda self: self.correct_naming(["head"]), doc="The head.")
    face_geoms = property(lambda self: self.correct_naming(["neck", "face"]), doc="Neck, face.")
    claw_geoms = property(lambda self: self.correct_naming(["claw"]), doc="The claw.")

    @property
    def all_geoms(self) -> list[str]:
        """Handle, head, neck, face and claw."""
        return self.handle_geoms + self.head_geoms + self.face_geoms + self.claw_geoms  # type: ignore[no-any-return]

    @property
    def bottom_offset(self) -> Vector:
        """The handle's radius below."""
        return np.array([0, 0, -self.handle_radius])

    @property
    def top_offset(self) -> Vector:
        """The handle's radius above."""
        return np.array([0, 0, self.handle_radius])

    @property
    def horizontal_radius(self) -> Any:
        """The head's half-size plus half the handle."""
        return self.head_halfsize + 0.5 * self.handle_length


class HookFrame(CompositeObject):
    """robosuite's ``HookFrame``: an upside-down L of brass, with an optional hook, grip and tip.

    Args:
        name: Name of the object.
        frame_length: Length of the horizontal bar.
        frame_height: Height of the vertical bar.
        frame_thickness: Thickness of the bars.
        hook_height: Height of a hook rising at the far end (``None``: no hook).
        grip_location: Height of a grip on the vertical bar (with ``grip_size``).
        grip_size: Half-width and half-height of the grip.
        tip_size: A steel tip below the vertical bar: cylinder half-height, cone
            inner and outer radius, cone height (``None``: no tip).
        friction: Friction of the geoms but the grip (``None``: robosuite's default).
        density: Density of every geom.
        solref: Contact ``solref`` of every geom.
        solimp: Contact ``solimp`` of every geom.
        use_texture: Brass, ceramic and steel; otherwise ``rgba``.
        rgba: Colour without texture (the grip stays dark grey).

    """

    _robosuite_class = ("robosuite.models.objects", "HookFrame")

    def __init__(
        self,
        name: str,
        frame_length: float = 0.3,
        frame_height: float = 0.2,
        frame_thickness: float = 0.025,
        hook_height: float | None = None,
        grip_location: float | None = None,
        grip_size: Any = None,
        tip_size: Any = None,
        friction: Any = None,
        density: Any = 1000.0,
        solref: Any = (0.02, 1.0),
        solimp: Any = (0.9, 0.95, 0.001),
        use_texture: bool = True,
        rgba: Any = (0.2, 0.1, 0.0, 1.0),
    ) -> None:
        self._name = name
        self.size: Any = None
        self.frame_length = frame_length
        self.frame_height = frame_height
        self.frame_thickness = frame_thickness
        self.hook_height = hook_height
        self.grip_location = grip_location
        self.grip_size = None if grip_size is None else tuple(grip_size)
        self.tip_size = None if tip_size is None else tuple(tip_size)
        self.friction = friction if friction is None else np.array(friction)
        self.solref = solref
        self.solimp = solimp
        self.density = density
        self.use_texture = use_texture
        self.rgba = rgba
        self.mat_name = "brass_mat"
        self.grip_mat_name = "ceramic_mat"
        self.tip_mat_name = "steel_mat"
        super().__init__(**self._get_geom_attrs())
        self.append_material(textured("Brass", "brass", self.mat_name))
        if self._has_grip:
            self.append_material(textured("Ceramic", "ceramic", self.grip_mat_name))
        if self.tip_size is not None:
            self.append_material(textured("SteelScratched", "steel", self.tip_mat_name))

    @property
    def _has_grip(self) -> bool:
        return self.grip_location is not None and self.grip_size is not None

    def _get_geom_attrs(self) -> dict[str, Any]:
        """The arguments of ``CompositeObject`` (robosuite's method of the same name)."""
        length, height, thick = self.frame_length, self.frame_height, self.frame_thickness
        tip = self.tip_size
        self.size = np.array((length, thick, height))
        if tip is not None:
            self.size[2] += 2.0 * (tip[0] + 2.0 * tip[3])
        post = (length - thick) / 2  # the x of the vertical bar
        brass = {
            **looks(self.use_texture, self.mat_name, self.rgba),
            "geom_frictions": self.friction,
        }
        bars = [
            ("vertical_frame", (post, 0, -thick / 2), (thick, thick, height - thick)),
            ("horizontal_frame", (0, 0, (height - thick) / 2), (length, thick, thick)),
        ]
        if self.hook_height is not None:
            hook = ((-length + thick) / 2, 0, (height + self.hook_height) / 2)
            bars.append(("hook_frame", hook, (thick, thick, self.hook_height)))
        arguments: dict[str, Any] = {}
        for bar_name, location, full in bars:
            add_geom(arguments, bar_name, "box", location, np.array(full) / 2, **brass)
        if self.grip_location is not None and self.grip_size is not None:
            grip, where = self.grip_size, (post, 0, -thick / 2 + self.grip_location)
            add_geom(
                arguments, "grip_frame", "box", where, (grip[0], grip[0], grip[1]),
                geom_rgbas=(0.13, 0.13, 0.13, 1.0),
                geom_materials=self.grip_mat_name if self.use_texture else None,
                geom_frictions=(1.0, 0.005, 0.0001),
            )  # fmt: skip
        if tip is not None:
            self._add_tip(arguments, tip, (post, 0, -height / 2 - tip[0]))
        sites = [
            marker_site("hang_site", (-length / 2, 0, (height - thick) / 2)),
            marker_site("mount_site", (post, 0, -height / 2), GREEN),
            marker_site("intersection_site", (post, 0, (height - thick) / 2), BLUE),
        ]
        if tip is not None:
            sites.append(marker_site("tip_site", (post, 0, -height / 2 - 2.0 * tip[0] - tip[3])))
        arguments["sites"] = sites
        more = {"density": self.density, "solref": self.solref, "solimp": self.solimp}
        return {**arguments, **centred(self.name, self.size / 2, **more)}

    def _add_tip(self, arguments: dict[str, Any], tip: Any, cylinder: Any) -> None:
        """The tip: a steel cylinder, then a cone of 51 boxes, narrowest first."""
        steel = {
            **looks(self.use_texture, self.tip_mat_name, self.rgba),
            "geom_frictions": self.friction,
        }
        add_geom(arguments, "tip_cylinder", "cylinder", cylinder, (tip[2], tip[0]), **steel)
        count = 51  # robosuite's cone of 50 geoms, made odd
        layers = cone_layers(
            tip[1], (tip[2] - tip[1]) / (count - 1), tip[3] / count / 2.0, count, True
        )
        offset = (cylinder[0], cylinder[1], cylinder[2] - tip[0] - tip[3] / 2.0)
        sizes = [size for _, size in layers][::-1]
        for i, ((x, y, z), size) in enumerate(
            zip((place for place, _ in layers), sizes, strict=True)
        ):
            where = (x + offset[0], y + offset[1], z + offset[2])
            add_geom(arguments, f"tip_cone_{i}", "box", where, size, **steel)

    @property
    def init_quat(self) -> Vector:
        """The frame turned to hang (``x y z w``, float32 as robosuite's product gives it)."""
        return np.array([-0.5, -0.5, 0.5, 0.5], dtype=np.float32)


class RatchetingWrenchObject(CompositeBodyObject):
    """robosuite's ``RatchetingWrenchObject``: a box handle between two rings, all of steel.

    Args:
        name: Name of the object.
        handle_size: Half-size of the handle box.
        outer_radius_1: Outer radius of the first ring (``hole1``, on -x).
        inner_radius_1: Inner radius of the first ring.
        height_1: Half-height of the first ring.
        outer_radius_2: Outer radius of the second ring (``hole2``, on +x).
        inner_radius_2: Inner radius of the second ring.
        height_2: Half-height of the second ring.
        ngeoms: Boxes per ring.
        grip_size: Half-width and half-length of a dark grip along the handle (``None``: none).
        density: Density of every geom.
        solref: Contact ``solref`` of every geom.
        solimp: Contact ``solimp`` of every geom.
        friction: Friction of the rings and the handle (``None``: robosuite's default).

    """

    _robosuite_class = ("robosuite.models.objects", "RatchetingWrenchObject")

    def __init__(
        self,
        name: str,
        handle_size: Any = (0.08, 0.01, 0.005),
        outer_radius_1: float = 0.0425,
        inner_radius_1: float = 0.03,
        height_1: float = 0.05,
        outer_radius_2: float = 0.0425,
        inner_radius_2: float = 0.03,
        height_2: float = 0.05,
        ngeoms: int = 8,
        grip_size: Any = None,
        density: Any = 1000.0,
        solref: Any = (0.02, 1.0),
        solimp: Any = (0.9, 0.95, 0.001),
        friction: Any = None,
    ) -> None:
        self.handle_size = tuple(handle_size)
        self.outer_radii = (outer_radius_1, outer_radius_2)
        self.inner_radii = (inner_radius_1, inner_radius_2)
        self.heights = (height_1, height_2)
        self.ngeoms = ngeoms
        self.grip_size = None if grip_size is None else tuple(grip_size)
        steel = textured("SteelScratched", "steel", "steel_mat")
        contact = {"density": density, "solref": solref, "solimp": solimp}
        rings = [
            HollowCylinderObject(
                name=f"hole{i + 1}", outer_radius=self.outer_radii[i],
                inner_radius=self.inner_radii[i], height=self.heights[i], ngeoms=ngeoms,
                material=steel, friction=friction, **contact,
            )
            for i in range(2)
        ]  # fmt: skip
        handle = BoxObject("handle", size=handle_size, material=steel, friction=friction, **contact)
        objects: list[MujocoObject] = [*rings, handle]
        # Each ring overlaps the handle by one box's depth.
        positions = [
            np.array(
                [-handle_size[0] - self.outer_radii[0] + 2.0 * rings[0].unit_box_height, 0, 0]
            ),
            np.array([handle_size[0] + self.outer_radii[1] - 2.0 * rings[1].unit_box_height, 0, 0]),
            np.zeros(3),
        ]
        quats: list[Any] = [None, None, None]
        if self.grip_size is not None:
            grip = self.grip_size
            objects.append(
                BoxObject(
                    name="grip", size=[grip[0], grip[0], grip[1]], rgba=(0.13, 0.13, 0.13, 1.0),
                    friction=(1.0, 0.005, 0.0001), **contact,
                )
            )  # fmt: skip
            positions.append(np.zeros(3))
            quats.append((np.sqrt(2) / 2.0, 0.0, np.sqrt(2) / 2.0, 0.0))
        super().__init__(
            name=name,
            objects=objects,
            object_locations=positions,
            object_quats=quats,
            object_parents=[None] * len(objects),
            joints=[{"type": "free", "damping": "0.0005"}],
        )
