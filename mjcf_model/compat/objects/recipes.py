"""What robosuite's composite objects build from: walls around a box, turns, wood and metal.

robosuite's recipes (``Bin``, ``PotWithHandlesObject``, ``HookFrame``...) pass lists of
geom arguments to ``CompositeObject``; these helpers make the pieces several of them
share, with robosuite's arithmetic, so the numbers written are robosuite's to the bit.

>>> [quat.tolist() for quat in WALL_TURNS][:2]
[[0.7071067811865476, 0.0, 0.0, 0.7071067811865475], [1.0, 0.0, 0.0, 0.0]]
>>> looks(True, "wood_mat", (1, 0, 0, 1))
{'geom_rgbas': None, 'geom_materials': 'wood_mat'}
>>> looks(False, "wood_mat", (1, 0, 0, 1))
{'geom_rgbas': (1, 0, 0, 1), 'geom_materials': None}
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from mjcf_model.compat.mjcf_utils.constants import RED
from mjcf_model.compat.mjcf_utils.materials import CustomMaterial
from mjcf_model.compat.mjcf_utils.text import add_to_dict
from mjcf_model.compat.objects.base import Vector

__all__ = [
    "UPRIGHT",
    "WALL_TURNS",
    "add_geom",
    "centred",
    "looks",
    "marker_site",
    "textured",
    "wall_offsets",
    "z_turn",
]


#: The identity quaternion as robosuite's recipes write it (integers: ``"1 0 0 0"``).
UPRIGHT = (1, 0, 0, 0)


def add_geom(
    arguments: dict[str, Any], name: str, kind: str, location: Any, size: Any,
    quat: Any = UPRIGHT, **more: Any,
) -> None:  # fmt: skip
    """Append a geom to ``CompositeObject`` arguments, one value per parameter list.

    ``more`` gives the other per-geom values (``geom_rgbas``, ``density``...); a
    recipe gives every geom the same keys, as robosuite's ``add_to_dict`` expects.

    Examples:
        >>> arguments = {}
        >>> add_geom(arguments, "base", "box", (0, 0, 0), (0.1, 0.1, 0.01), density=10)
        >>> arguments["geom_names"], arguments["geom_quats"], arguments["density"]
        (['base'], [(1, 0, 0, 0)], [10])

    """
    add_to_dict(
        dic=arguments, geom_types=kind, geom_locations=location, geom_quats=quat,
        geom_sizes=size, geom_names=name, **more,
    )  # fmt: skip


def centred(name: str, total_size: Any, **more: Any) -> dict[str, Any]:
    """A recipe's ``CompositeObject`` arguments besides its geoms: centred, each geom twice."""
    return {
        "total_size": total_size, "name": name, "locations_relative_to_center": True,
        "obj_types": "all", **more,
    }  # fmt: skip


def z_turn(angle: float) -> Vector:
    """The ``w x y z`` quaternion of a turn by ``angle`` about z, as robosuite computes it.

    robosuite writes ``convert_quat(axisangle2quat([0, 0, angle]), "wxyz")``: the
    same operations here give the same bits (``cos(pi / 2)`` is ``6.1e-17``, not 0).

    Examples:
        >>> z_turn(np.pi).tolist(), z_turn(0.0).tolist()
        ([6.123233995736766e-17, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0, 0.0])

    """
    rotation = np.array([0, 0, angle])
    size = np.linalg.norm(rotation)
    if math.isclose(size, 0.0):
        return np.array([1.0, 0.0, 0.0, 0.0])
    quat = np.zeros(4)
    quat[0] = np.cos(size / 2.0)
    quat[1:] = rotation / size * np.sin(size / 2.0)
    return quat


#: The turns of the four walls of robosuite's boxes (bins, stands, pots): y-, x-, y+, x+.
WALL_TURNS = tuple(z_turn(angle) for angle in np.array([np.pi / 2, 0, -np.pi / 2, np.pi]))


def wall_offsets(x: Any, y: Any) -> tuple[Vector, Vector]:
    """The centres of four walls ``x`` and ``y`` from the middle, in :data:`WALL_TURNS` order.

    Examples:
        >>> [values.tolist() for values in wall_offsets(0.1, 0.2)]
        [[0.0, -0.1, 0.0, 0.1], [-0.2, 0.0, 0.2, 0.0]]

    """
    return np.array([0, -x, 0, x]), np.array([-y, 0, y, 0])


def textured(texture: str, tex_name: str, mat_name: str, texrepeat: str = "3 3") -> CustomMaterial:
    """The cube-mapped material of robosuite's recipes (``specular`` 0.4, ``shininess`` 0.1).

    Examples:
        >>> textured("WoodDark", "dark_wood", "dark_wood_mat").mat_attrib["texrepeat"]
        '3 3'

    """
    return CustomMaterial(
        texture=texture,
        tex_name=tex_name,
        mat_name=mat_name,
        tex_attrib={"type": "cube"},
        mat_attrib={"texrepeat": texrepeat, "specular": "0.4", "shininess": "0.1"},
    )


def looks(use_texture: bool, material: str, rgba: Any) -> dict[str, Any]:
    """A geom's ``geom_rgbas``/``geom_materials`` arguments: the material, or else the colour."""
    if use_texture:
        return {"geom_rgbas": None, "geom_materials": material}
    return {"geom_rgbas": rgba, "geom_materials": None}


def marker_site(name: str, pos: Any, rgba: Any = RED) -> dict[str, Any]:
    """The small sphere site robosuite's recipes mark points with (``pos`` kept as given)."""
    return {"name": name, "pos": pos, "size": "0.002", "rgba": rgba, "type": "sphere"}
