"""robosuite's materials on nodes: :func:`with_material` and :func:`recolored_collision_geoms`.

The material is robosuite's :class:`CustomMaterial` (the library's one material class,
from :mod:`mjcf_model.compat.mjcf_utils.materials`). :func:`with_material` gives visual
geoms a material (robosuite's ``add_material``) and :func:`recolored_collision_geoms`
paints collision geoms (robosuite's ``recolor_collision_geoms``); both return a new tree
that shares every unchanged subtree with the input, and neither changes the material.

>>> from mjcf_model import Body, Geom
>>> body = Body(children=[Geom(name="vis", group=1), Geom(name="col")])
>>> result = with_material(body, naming_prefix="p_")
>>> result.tree.geoms[0].material, result.material.attributes["texture"], result.used
('p_default_mat', 'p_default_tex', True)
>>> recolored_collision_geoms(body, (0.5, 0, 0, 1)).geoms[1].rgba
(0.5, 0.0, 0.0, 1.0)
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Generic, NamedTuple, TypeVar

from mjcf_model.compat.geom_roles import with_collision_color, with_visual_material
from mjcf_model.compat.mjcf_utils.materials import CustomMaterial, default_material, material_text
from mjcf_model.nodes.base import AnyElement, Element, GenericElement
from mjcf_model.nodes.tendon import TendonGeom
from mjcf_model.values import Value, to_vec4

__all__ = [
    "CustomMaterial",
    "MaterialResult",
    "material_nodes",
    "recolored_collision_geoms",
    "with_material",
]

_E = TypeVar("_E", bound=Element)


def material_nodes(
    material: Any, prefix: str = "", text: Callable[[Any], str] = material_text
) -> tuple[GenericElement, GenericElement]:
    """The ``<texture>`` and ``<material>`` of a ``CustomMaterial`` (ours or robosuite's).

    Their attributes are the material's, made text by ``text`` (as ``CustomMaterial``
    writes them, by default), in its order; unless the material is ``shared``, the
    texture's and material's names get ``prefix``.

    Examples:
        >>> wood = CustomMaterial(None, "wood", "wood_mat", tex_attrib={"builtin": "flat"})
        >>> texture, material = material_nodes(wood, "p_")
        >>> dict(texture.attributes), dict(material.attributes)
        ({'builtin': 'flat', 'name': 'p_wood'}, {'name': 'p_wood_mat', 'texture': 'p_wood'})

    """
    add = "" if material.shared else prefix
    texture = {k: text(v) for k, v in material.tex_attrib.items()}
    own = {k: text(v) for k, v in material.mat_attrib.items()}
    texture["name"] = add + texture["name"]
    own["name"] = add + own["name"]
    if "texture" in own:
        own["texture"] = add + own["texture"]
    return (
        GenericElement(tag="texture", attributes=texture),
        GenericElement(tag="material", attributes=own),
    )


class MaterialResult(NamedTuple, Generic[_E]):
    """What :func:`with_material` returns.

    Examples:
        >>> from mjcf_model import Geom
        >>> tree, texture, material, used = with_material(Geom(group=1))
        >>> tree.material, texture.attributes["name"], material.attributes["name"], used
        ('default_mat', 'default_tex', 'default_mat', True)

    """

    #: The new tree (the input itself when no geom took the material).
    tree: _E
    #: The ``<texture>`` asset the material uses.
    texture: GenericElement
    #: The ``<material>`` asset.
    material: GenericElement
    #: Whether any geom took the material.
    used: bool


def with_material(node: _E, material: Any = None, naming_prefix: str = "") -> MaterialResult[_E]:
    """Give every visual geom without a material this one: robosuite's ``add_material``.

    Every ``geom`` element (``node`` included) whose group is 1 and that has no
    ``material`` gets ``material=<material name>``. Unless the material is
    ``shared``, its texture and material names get ``naming_prefix`` first,
    always (robosuite skips the prefix when the material name already starts
    with it). The input is not changed, and neither is ``material``.

    Args:
        node: The tree.
        material: A ``CustomMaterial`` (ours or robosuite's); ``None`` is robosuite's
            default (:func:`~mjcf_model.compat.mjcf_utils.materials.default_material`).
        naming_prefix: Prefix of the texture and material names.

    Returns:
        The new tree, the texture and material nodes, and whether any geom took
        the material.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="v", group=1), Geom(name="m", group=1, material="x")])
        >>> result = with_material(body, CustomMaterial(None, "t", "m"))
        >>> [g.material for g in result.tree.geoms], result.tree.geoms[1] is body.geoms[1]
        (['m', 'x'], True)

    """
    chosen = default_material() if material is None else material
    texture, own = material_nodes(chosen, naming_prefix)
    tree, used = with_visual_material(node, own.attributes["name"])
    return MaterialResult(tree, texture, own, used)


def recolored_collision_geoms(
    node: _E, rgba: object, exclude: Callable[[AnyElement], bool] | None = None
) -> _E:
    """Paint every collision geom ``rgba``: robosuite's ``recolor_collision_geoms``.

    Every geom (``node`` included) whose group is not written or is 0, and for
    which ``exclude(geom)`` is not true, gets ``rgba`` and loses its ``material``.
    A spatial tendon's ``<geom geom="..."/>`` (a wrapping reference, which MuJoCo
    gives no colour) is left alone, unlike robosuite's function, which paints it
    and makes a model MuJoCo rejects (``mjcf_utils.recolor_collision_geoms`` keeps
    robosuite's behaviour). As robosuite's, it goes by the group written on each
    ``geom`` element, in ``<default>`` too: a default class's geom without a group
    is painted, and so is every geom that takes its colour from that class.
    Unchanged subtrees are the input's own.

    Raises:
        MjcfValueError: ``rgba`` is not four numbers.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="floor"), Geom(name="box", material="wood")])
        >>> new = recolored_collision_geoms(body, [0, 0.5, 0, 1], lambda g: g.name == "floor")
        >>> new.geoms[1].rgba, new.geoms[1].material, new.geoms[0] is body.geoms[0]
        ((0.0, 0.5, 0.0, 1.0), None, True)

    """
    color: Value | None = to_vec4(rgba)
    assert color is not None, "to_vec4 refuses None: rgba is required"

    def left_alone(element: AnyElement) -> bool:
        return isinstance(element, TendonGeom) or (exclude is not None and exclude(element))

    return with_collision_color(node, lambda: color, left_alone)
