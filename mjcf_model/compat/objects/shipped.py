"""The XML objects robosuite ships (can, milk, nuts, door...), read from robosuite's own files.

robosuite must be installed (it is found, not imported); otherwise they raise ``MjcfLookupError``.

>>> can = CanObject("can")
>>> can.joints, can.contact_geoms, float(can.horizontal_radius)
(['can_joint0'], ['can_g0'], 0.025)
"""

from __future__ import annotations

import os
from typing import Any

import numpy as np

from mjcf_model.compat.assets import assets_root
from mjcf_model.compat.mjcf_utils.text import array_to_string
from mjcf_model.compat.objects.document import find_path
from mjcf_model.compat.objects.xml import MujocoXMLObject
from mjcf_model.errors import MjcfLookupError
from mjcf_model.nodes.base import with_attributes
from mjcf_model.tree.paths import replaced_at, subtree_at

__all__ = [
    "BottleObject",
    "BreadObject",
    "BreadVisualObject",
    "CanObject",
    "CanVisualObject",
    "CerealObject",
    "CerealVisualObject",
    "DoorObject",
    "LemonObject",
    "MilkObject",
    "MilkVisualObject",
    "PlateWithHoleObject",
    "RoundNutObject",
    "SquareNutObject",
]

_DAMPED_FREE_JOINT = {"type": "free", "damping": "0.0005"}


def robosuite_asset(relative: str) -> str:
    """The absolute path of a file in robosuite's ``models/assets`` (raises without robosuite)."""
    missing = (
        f"robosuite's object {relative!r} is a file shipped with robosuite, which is not "
        "installed; install robosuite or load your own file with MujocoXMLObject"
    )
    return os.path.join(assets_root(missing), relative)


class _Shipped(MujocoXMLObject):
    """An object of robosuite's assets; subclasses pass ``file=``, their twin has their name."""

    _file = ""
    #: ``"damped"`` (a damped free joint), ``"default"`` or ``None``, as robosuite's class.
    _joint_choice: Any = "damped"
    _obj_type = "all"

    def __init_subclass__(cls, file: str | None = None, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        if file is not None:
            cls._file = file
            cls._robosuite_class = ("robosuite.models.objects", cls.__name__)

    def __init__(self, name: str) -> None:
        joints = self._joint_choice
        super().__init__(
            robosuite_asset(self._file),
            name=name,
            joints=[dict(_DAMPED_FREE_JOINT)] if joints == "damped" else joints,
            obj_type=self._obj_type,
            duplicate_collision_geoms=True,
        )


class _WithHandle(_Shipped):
    """A nut: its handle site is important too."""

    @property
    def important_sites(self) -> dict[str, Any]:
        """``obj`` and ``handle`` (the ``handle_site``)."""
        sites = super().important_sites
        sites["handle"] = self.naming_prefix + "handle_site"
        return sites


class _Visual(_Shipped):
    """A visual fiducial: visual geoms only, no joints."""

    _joint_choice = None
    _obj_type = "visual"


class BottleObject(_Shipped, file="objects/bottle.xml"):
    """robosuite's bottle (``objects/bottle.xml``)."""


class CanObject(_Shipped, file="objects/can.xml"):
    """robosuite's coke can (``objects/can.xml``), used in PickPlace."""


class LemonObject(_Shipped, file="objects/lemon.xml"):
    """robosuite's lemon (``objects/lemon.xml``), with an undamped free joint."""

    _joint_choice = "default"


class MilkObject(_Shipped, file="objects/milk.xml"):
    """robosuite's milk carton (``objects/milk.xml``)."""


class BreadObject(_Shipped, file="objects/bread.xml"):
    """robosuite's bread loaf (``objects/bread.xml``)."""


class CerealObject(_Shipped, file="objects/cereal.xml"):
    """robosuite's cereal box (``objects/cereal.xml``)."""


class SquareNutObject(_WithHandle, file="objects/square-nut.xml"):
    """robosuite's square nut (``objects/square-nut.xml``), used in NutAssembly."""


class RoundNutObject(_WithHandle, file="objects/round-nut.xml"):
    """robosuite's round nut (``objects/round-nut.xml``), used in NutAssembly."""


class MilkVisualObject(_Visual, file="objects/milk-visual.xml"):
    """Visual fiducial of the milk carton (``objects/milk-visual.xml``)."""


class BreadVisualObject(_Visual, file="objects/bread-visual.xml"):
    """Visual fiducial of the bread loaf (``objects/bread-visual.xml``)."""


class CerealVisualObject(_Visual, file="objects/cereal-visual.xml"):
    """Visual fiducial of the cereal box (``objects/cereal-visual.xml``)."""


class CanVisualObject(_Visual, file="objects/can-visual.xml"):
    """Visual fiducial of the coke can (``objects/can-visual.xml``)."""


class PlateWithHoleObject(_Shipped, file="objects/plate-with-hole.xml"):
    """Square plate with a hole (``objects/plate-with-hole.xml``), used in PegInHole."""

    _joint_choice = None


class DoorObject(_Shipped, file="objects/door.xml"):
    """robosuite's door with a handle (``objects/door.xml``, ``door_lock.xml`` with ``lock``).

    Args:
        name: Name of the object.
        friction: Replaces the hinge's ``frictionloss``.
        damping: Replaces the hinge's ``damping``.
        lock: Use the door with a latch lock.

    """

    _joint_choice = None

    def __init__(
        self, name: str, friction: Any = None, damping: Any = None, lock: bool = False
    ) -> None:
        if lock:
            self._file = "objects/door_lock.xml"
        super().__init__(name)
        self.door_body = self.naming_prefix + "door"
        self.frame_body = self.naming_prefix + "frame"
        self.latch_body = self.naming_prefix + "latch"
        self.hinge_joint = self.naming_prefix + "hinge"
        self.lock = lock
        self.friction = friction
        self.damping = damping
        if friction is not None:
            self._set_hinge("frictionloss", friction)
        if damping is not None:
            self._set_hinge("damping", damping)

    def _set_hinge(self, attribute_name: str, value: Any) -> None:
        """Write ``value`` (as robosuite writes ``np.array([value])``) on the hinge joint."""
        world = self._node("worldbody")
        path = find_path(world, "joint", name=self.hinge_joint)
        if path is None:
            raise MjcfLookupError(f"no joint {self.hinge_joint!r} in {self.file}")
        text = array_to_string(np.array([value]))
        hinge = with_attributes(subtree_at(world, path), {attribute_name: text})
        self._replace("worldbody", replaced_at(world, path, [hinge]))

    @property
    def important_sites(self) -> dict[str, Any]:
        """``obj`` and ``handle`` (the door handle site)."""
        sites = super().important_sites
        sites["handle"] = self.naming_prefix + "handle"
        return sites
