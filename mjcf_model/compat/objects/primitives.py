"""``BoxObject``, ``BallObject``, ``CylinderObject`` and ``CapsuleObject``, as robosuite makes them.

Drawn sizes use the compatible ``get_size``, so a seeded generator gives robosuite's sizes.

>>> box = BoxObject("cube", size_min=[0.02] * 3, size_max=[0.022] * 3, rng=np.random.default_rng(0))
>>> box.get_obj()[0].get("size")
'0.021273923374642907 0.02053957342752774 0.02008194704787239'
>>> float(box.horizontal_radius), box.bottom_offset.tolist()
(0.029571166570410805, [0.0, 0.0, -0.02008194704787239])
"""

from __future__ import annotations

from typing import Any, ClassVar

import numpy as np

from mjcf_model.compat.mjcf_utils.text import get_size
from mjcf_model.compat.objects.base import Vector
from mjcf_model.compat.objects.generated import MujocoGeneratedObject, PrimitiveObject
from mjcf_model.errors import MjcfValueError

__all__ = ["BallObject", "BoxObject", "CapsuleObject", "CylinderObject"]


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


class BoxObject(_SizedPrimitive):
    """A box; ``size`` is three half-lengths (drawn from 0.03 to 0.07 by default)."""

    _robosuite_class = ("robosuite.models.objects", "BoxObject")
    geom_type = "box"

    @property
    def bottom_offset(self) -> Vector:
        """``[0, 0, -z]``."""
        return np.array([0, 0, -1 * self.size[2]])

    @property
    def top_offset(self) -> Vector:
        """``[0, 0, z]``."""
        return np.array([0, 0, self.size[2]])

    @property
    def horizontal_radius(self) -> Any:
        """The length of the x, y half-lengths."""
        return np.linalg.norm(self.size[0:2], 2)

    def get_bounding_box_half_size(self) -> Vector:
        """The three half-lengths."""
        return np.array([self.size[0], self.size[1], self.size[2]])


class BallObject(_SizedPrimitive):
    """A sphere; ``size`` is its radius.

    Unlike robosuite's, it takes ``rng`` (robosuite's draws unseeded).
    """

    _robosuite_class = ("robosuite.models.objects", "BallObject")
    geom_type = "sphere"
    _size_max = (0.07,)
    _size_min = (0.03,)
    _shape = "ball"

    bottom_offset = property(lambda self: np.array([0, 0, -1 * self.size[0]]), doc="Below.")
    top_offset = property(lambda self: np.array([0, 0, self.size[0]]), doc="Above.")
    horizontal_radius = property(lambda self: self.size[0], doc="The radius.")

    def get_bounding_box_half_size(self) -> Vector:
        """The radius, three times."""
        return np.array([self.size[0], self.size[0], self.size[0]])


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
        template = MujocoGeneratedObject.get_collision_attrib_template()
        template["margin"] = "0.001"
        return template

    bottom_offset = property(lambda self: np.array([0, 0, -1 * self.size[1]]), doc="Below.")
    top_offset = property(lambda self: np.array([0, 0, self.size[1]]), doc="Above.")
    horizontal_radius = property(lambda self: self.size[0], doc="The radius.")

    def get_bounding_box_half_size(self) -> Vector:
        """Radius, radius, half-length."""
        return np.array([self.size[0], self.size[0], self.size[1]])


class CapsuleObject(_SizedPrimitive):
    """A capsule; ``size`` is radius and half-length of the cylinder part.

    Unlike robosuite's, it takes ``rng`` (robosuite's draws unseeded).
    """

    _robosuite_class = ("robosuite.models.objects", "CapsuleObject")
    geom_type = "capsule"
    _size_max = (0.07, 0.07)
    _size_min = (0.03, 0.03)
    _shape = "capsule"

    bottom_offset = property(
        lambda self: np.array([0, 0, -1 * (self.size[0] + self.size[1])]), doc="Below."
    )
    top_offset = property(lambda self: np.array([0, 0, self.size[0] + self.size[1]]), doc="Above.")
    horizontal_radius = property(lambda self: self.size[0], doc="The radius.")

    def get_bounding_box_half_size(self) -> Vector:
        """Radius, radius, radius plus half-length."""
        return np.array([self.size[0], self.size[0], self.size[0] + self.size[1]])
