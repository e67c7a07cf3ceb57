"""``CompositeObject``: robosuite's object made of several primitive geoms in one body.

>>> shelf = CompositeObject(
...     "shelf", total_size=[0.1, 0.1, 0.02], geom_types=["box", "box"],
...     geom_sizes=[[0.1, 0.1, 0.01], [0.1, 0.1, 0.01]],
...     geom_locations=[[0, 0, 0], [0, 0, 0.02]], obj_types="collision")
>>> [g.get("pos") for g in shelf.get_obj().iter("geom")]
['0.0 0.0 -0.01', '0.0 0.0 0.01']
>>> shelf.contact_geoms, float(shelf.horizontal_radius)
(['shelf_g0', 'shelf_g1'], 0.14142135623730953)
"""

from __future__ import annotations

from copy import deepcopy
from numbers import Real
from typing import Any

import numpy as np

from mjcf_model.compat.mjcf_utils.text import array_to_string
from mjcf_model.compat.objects.base import Vector
from mjcf_model.compat.objects.generated import MujocoGeneratedObject, half_extents
from mjcf_model.compat.objects.habits import OBJECT_COLLISION_RGBA_TEXT
from mjcf_model.nodes.base import AnyElement

__all__ = ["CompositeObject"]

#: robosuite's friction for composite geoms without one (a numpy array, so ``"1.0 ..."``).
_DEFAULT_FRICTION = np.array([1.0, 0.005, 0.0001])


def _is_number(value: Any) -> bool:
    if type(value) in (float, int):  # the usual case, before the slower check
        return True
    return isinstance(value, Real) and not isinstance(value, bool)


def _per_geom(value: Any, count: int, single: bool) -> list[Any]:
    return [value] * count if single else list(value)


class CompositeObject(MujocoGeneratedObject):
    """robosuite's ``CompositeObject``: primitive geoms placed in a box of half-size ``total_size``.

    Locations are of lower corners (from the box's), or of centres with
    ``locations_relative_to_center``.

    Raises:
        MjcfValueError: a geom type other than box, ellipsoid, sphere, capsule, cylinder.

    """

    _robosuite_class = ("robosuite.models.objects", "CompositeObject")

    def __init__(
        self,
        name: str,
        total_size: Any,
        geom_types: Any,
        geom_sizes: Any,
        geom_locations: Any,
        geom_quats: Any = None,
        geom_names: Any = None,
        geom_rgbas: Any = None,
        geom_materials: Any = None,
        geom_frictions: Any = None,
        geom_condims: Any = None,
        rgba: Any = None,
        density: Any = 100.0,
        solref: Any = (0.02, 1.0),
        solimp: Any = (0.9, 0.95, 0.001),
        locations_relative_to_center: bool = False,
        joints: Any = "default",
        sites: Any = None,
        obj_types: Any = "all",
        duplicate_collision_geoms: bool = True,
    ) -> None:
        super().__init__(duplicate_collision_geoms=duplicate_collision_geoms)
        self._name = name
        self.joint_specs = self._named_joints(joints, by_position=False)
        self.site_specs = self._named_sites(sites)
        count = len(geom_types)
        self.total_size = np.array(total_size)
        self.geom_types = np.array(geom_types)
        self.geom_sizes = deepcopy(geom_sizes)
        self.geom_locations = np.array(geom_locations)
        self.geom_quats = deepcopy(geom_quats) if geom_quats is not None else [None] * count
        self.geom_names = _per_geom(geom_names, count, geom_names is None)
        self.geom_rgbas = _per_geom(geom_rgbas, count, geom_rgbas is None)
        self.geom_materials = _per_geom(geom_materials, count, geom_materials is None)
        self.geom_frictions = _per_geom(geom_frictions, count, geom_frictions is None)
        self.geom_condims = _per_geom(geom_condims, count, geom_condims is None)
        self.density = _per_geom(density, count, density is None or _is_number(density))
        self.solref = _per_geom(solref, count, solref is None or _is_number(solref[0]))
        self.solimp = _per_geom(solimp, count, solimp is None or _is_number(solimp[0]))
        self.rgba = rgba
        self.locations_relative_to_center = locations_relative_to_center
        single = obj_types is None or isinstance(obj_types, str)
        self.obj_types = _per_geom(obj_types, count, single)
        self.sanity_check()
        self._obj = self._get_object_subtree()
        self._get_object_properties()

    def get_bounding_box_half_size(self) -> Vector:
        """``total_size``."""
        return np.array(self.total_size)

    def in_box(self, position: Any, object_position: Any) -> bool:
        """Whether ``object_position`` is inside this object's box placed at ``position``.

        The box's bottom is lowered by 0.01 (objects settle on the table).
        """
        upper = position + self.total_size
        lower = position - self.total_size
        lower[2] -= 0.01
        return bool(np.all(object_position > lower) and np.all(object_position < upper))

    def _get_object_subtree(self) -> AnyElement:
        geoms: list[AnyElement] = []
        rows = zip(
            self.obj_types,
            self.geom_types,
            self.geom_sizes,
            self.geom_locations,
            self.geom_names,
            self.geom_rgbas,
            self.geom_frictions,
            self.geom_condims,
            self.geom_quats,
            self.geom_materials,
            self.density,
            self.solref,
            self.solimp,
            strict=False,
        )
        for index, row in enumerate(rows):
            geoms.extend(self._geoms(index, *row))
        return self._root_with_specs(geoms)

    def _geoms(
        self,
        index: int,
        obj_type: Any,
        geom_type: Any,
        size: Any,
        location: Any,
        name: Any,
        rgba: Any,
        friction: Any,
        condim: Any,
        quat: Any,
        material: Any,
        density: Any,
        solref: Any,
        solimp: Any,
    ) -> list[AnyElement]:
        half = self._size_to_cartesian_half_lengths(geom_type, size)
        if self.locations_relative_to_center:
            pos = location
        else:
            pos = [(-self.total_size[k] + half[k]) + location[k] for k in range(3)]
        base: dict[str, Any] = {
            "size": size,
            "pos": pos,
            "name": name if name is not None else f"g{index}",
            "type": geom_type,
        }
        if quat is not None:
            base["quat"] = array_to_string(quat)

        def collision() -> dict[str, Any]:
            own = {} if density is None else {"density": str(density)}
            own["friction"] = array_to_string(_DEFAULT_FRICTION if friction is None else friction)
            own["solref"] = array_to_string(solref)
            own["solimp"] = array_to_string(solimp)
            own["rgba"] = OBJECT_COLLISION_RGBA_TEXT
            if condim is not None:
                own["condim"] = str(condim)
            return own

        visual = {} if material is None else {"material": material}
        visual["rgba"] = rgba if rgba is not None else self.rgba
        return self._geom_pair(obj_type, base, collision, visual)

    #: robosuite's name for :func:`~mjcf_model.compat.objects.generated.half_extents`.
    _size_to_cartesian_half_lengths = staticmethod(half_extents)

    bottom_offset = property(lambda self: np.array([0.0, 0.0, -self.total_size[2]]), doc="Below.")
    top_offset = property(lambda self: np.array([0.0, 0.0, self.total_size[2]]), doc="Above.")
    horizontal_radius = property(
        lambda self: np.linalg.norm(self.total_size[:2], 2), doc="Length of total_size's x, y."
    )
