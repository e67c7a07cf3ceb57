"""robosuite's textures and materials as frozen values, without mutation or files written.

:class:`CustomMaterial` is the frozen equivalent of robosuite's class of the
same name: it describes a texture and a material and makes their nodes.
:func:`with_material` gives visual geoms a material (robosuite's
``add_material``) and :func:`recolored_collision_geoms` paints collision geoms
(robosuite's ``recolor_collision_geoms``); both return a new tree that shares
every unchanged subtree with the input.

>>> from mjcf_model import Body, Geom
>>> body = Body(children=[Geom(name="vis", group=1), Geom(name="col")])
>>> result = with_material(body, naming_prefix="p_")
>>> result.tree.geoms[0].material, result.material.texture, result.used
('p_default_mat', 'p_default_tex', True)
>>> recolored_collision_geoms(body, (0.5, 0, 0, 1)).geoms[1].rgba
(0.5, 0.0, 0.0, 1.0)
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import Any, Generic, NamedTuple, TypeVar, cast

import attrs

from mjcf_model.compat.assets import assets_root
from mjcf_model.compat.geom_roles import geom_role, with_collision_color
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.asset import Material, Texture
from mjcf_model.nodes.base import (
    AnyElement,
    AttributeMap,
    Element,
    Node,
    get_attribute,
    ordered_node,
    with_attributes,
)
from mjcf_model.nodes.tendon import TendonGeom
from mjcf_model.tree.traversal import map_tree
from mjcf_model.values import Floats, Value, format_value, plain_value, to_floats, to_vec4

__all__ = [
    "DEFAULT_MATERIAL",
    "TEXTURE_FILES",
    "CustomMaterial",
    "MaterialResult",
    "recolored_collision_geoms",
    "with_material",
]

#: robosuite's named textures and their image files (``TEXTURE_FILES`` in ``mjcf_utils``).
TEXTURE_FILES: Mapping[str, str] = MappingProxyType(
    {
        "WoodRed": "red-wood.png",
        "WoodGreen": "green-wood.png",
        "WoodBlue": "blue-wood.png",
        "WoodLight": "light-wood.png",
        "WoodDark": "dark-wood.png",
        "WoodTiles": "wood-tiles.png",
        "WoodPanels": "wood-varnished-panels.png",
        "WoodgrainGray": "gray-woodgrain.png",
        "PlasterCream": "cream-plaster.png",
        "PlasterPink": "pink-plaster.png",
        "PlasterYellow": "yellow-plaster.png",
        "PlasterGray": "gray-plaster.png",
        "PlasterWhite": "white-plaster.png",
        "BricksWhite": "white-bricks.png",
        "Metal": "metal.png",
        "SteelBrushed": "steel-brushed.png",
        "SteelScratched": "steel-scratched.png",
        "Brass": "brass-ambra.png",
        "Bread": "bread.png",
        "Can": "can.png",
        "Ceramic": "ceramic.png",
        "Cereal": "cereal.png",
        "Clay": "clay.png",
        "Dirt": "dirt.png",
        "Glass": "glass.png",
        "FeltGray": "gray-felt.png",
        "Lemon": "lemon.png",
    }
)

#: Side of the flat texture made for an RGBA colour, in pixels (robosuite's PNG is 100 x 100).
_FLAT_SIZE = 100

_E = TypeVar("_E", bound=Element)


def _to_texture(value: object) -> str | Floats | None:
    """Converter: a name or path stays text; anything else is read as numbers (an RGBA)."""
    if value is None or isinstance(value, str):
        return value
    return to_floats(value)


def _check_texture(_instance: Any, _attribute: Any, value: str | Floats | None) -> None:
    if isinstance(value, str):
        if "/" not in value and value not in TEXTURE_FILES:
            raise MjcfValueError(
                f"unknown texture {value!r}: expected a path containing '/', an RGBA, or one of "
                + ", ".join(TEXTURE_FILES)
            )
    elif value is not None and len(value) != 4:
        raise MjcfValueError(f"expected an RGBA of 4 numbers, found {len(value)} in {value!r}")


def _to_texts(value: Mapping[str, object] | None) -> AttributeMap:
    """Converter: attribute values become MJCF text; ``None`` values are dropped."""
    if isinstance(value, AttributeMap):
        return value
    if not value:
        return AttributeMap()
    texts: dict[str, str] = {}
    for key, item in value.items():
        if item is not None:
            plain = plain_value(item)
            texts[key] = plain if isinstance(plain, str) else format_value(plain)
    return AttributeMap(texts)


_NO_TEXTURES = (
    "named textures are image files shipped with robosuite, which is not installed; "
    "install robosuite, or give a file path or an RGBA instead"
)


@attrs.frozen(kw_only=True)
class CustomMaterial:
    """A texture and a material that uses it: robosuite's ``CustomMaterial``, frozen.

    ``texture`` says where the image comes from:

    * a name from :data:`TEXTURE_FILES`: the image file shipped with robosuite;
    * text containing ``"/"``: that file path, kept as given (robosuite joins a
      relative path to its own assets directory);
    * four numbers: an RGBA colour. robosuite writes a 100 x 100 PNG of that
      colour to a temporary directory; here the texture is MuJoCo's built-in
      ``flat`` texture of that colour, so nothing is written;
    * ``None``: no file; ``tex_attrib`` must then say how to make the texture
      (``builtin=...``), as robosuite's default material does.

    Attribute values are kept as MJCF text in the shortest form (``True`` is
    ``"true"``, where robosuite writes ``"True"``; ``None`` values are dropped).

    Raises:
        MjcfValueError: ``texture`` is an unknown name or not four numbers.

    Examples:
        >>> wood = CustomMaterial(
        ...     texture="WoodDark",
        ...     tex_name="dark_wood",
        ...     mat_name="dark_wood_mat",
        ...     tex_attrib={"type": "cube"},
        ...     mat_attrib={"texrepeat": [3, 3], "specular": 0.4},
        ... )
        >>> wood.name, wood.material_node.texrepeat
        ('dark_wood_mat', (3.0, 3.0))
        >>> wood.texture_node.file.endswith("/models/assets/textures/dark-wood.png")
        True
        >>> CustomMaterial(texture="Oak", tex_name="t", mat_name="m")
        Traceback (most recent call last):
            ...
        mjcf_model.errors.MjcfValueError: unknown texture 'Oak': expected a path containing '/', ...

    """

    #: A name from :data:`TEXTURE_FILES`, a file path containing ``"/"``, an RGBA, or ``None``.
    texture: str | Floats | None = attrs.field(converter=_to_texture, validator=_check_texture)
    #: Name of the texture asset.
    tex_name: str = attrs.field(validator=attrs.validators.instance_of(str))
    #: Name of the material asset.
    mat_name: str = attrs.field(validator=attrs.validators.instance_of(str))
    #: Further texture attributes (MJCF name to value; kept as text).
    tex_attrib: AttributeMap = attrs.field(factory=AttributeMap, converter=_to_texts)
    #: Further material attributes (MJCF name to value; kept as text).
    mat_attrib: AttributeMap = attrs.field(factory=AttributeMap, converter=_to_texts)
    #: Whether the names are shared between models and never get a prefix.
    shared: bool = attrs.field(default=False, validator=attrs.validators.instance_of(bool))

    @property
    def name(self) -> str:
        """The material name (robosuite's ``CustomMaterial.name``).

        Examples:
            >>> CustomMaterial(texture=None, tex_name="t", mat_name="m").name
            'm'

        """
        return self.mat_name

    @property
    def texture_node(self) -> Texture:
        """The ``<texture>`` asset: ``tex_attrib``, then ``name``, then the image source.

        Raises:
            MjcfLookupError: The texture is a name and robosuite is not installed.

        Examples:
            >>> flat = CustomMaterial(texture=(0.2, 0.4, 0.6, 1), tex_name="t", mat_name="m")
            >>> node = flat.texture_node
            >>> node.name, node.builtin, node.rgb1, node.width, node.height
            ('t', 'flat', (0.2, 0.4, 0.6), 100, 100)

        """
        values: dict[str, Value] = dict(self.tex_attrib)
        values["name"] = self.tex_name
        texture = self.texture
        if isinstance(texture, str):
            if "/" in texture:
                values["file"] = texture
            else:
                values["file"] = os.path.join(
                    assets_root(_NO_TEXTURES), "textures", TEXTURE_FILES[texture]
                )
        elif texture is not None:
            rgb = texture[:3]
            values["builtin"] = "flat"
            values["rgb1"] = rgb
            values["rgb2"] = rgb  # the bottom face of a cube texture
            values.setdefault("width", _FLAT_SIZE)
            values.setdefault("height", _FLAT_SIZE)
        return ordered_node(Texture, values.items())

    @property
    def material_node(self) -> Material:
        """The ``<material>`` asset: ``mat_attrib``, then ``name`` and ``texture``.

        An RGBA texture with alpha below 1 also sets the material's ``rgba`` to
        ``(1, 1, 1, alpha)`` (unless ``mat_attrib`` sets ``rgba``): a flat
        texture has no alpha channel.

        Examples:
            >>> glass = CustomMaterial(texture=[0.5, 0.5, 1, 0.25], tex_name="t", mat_name="m")
            >>> glass.material_node.texture, glass.material_node.rgba
            ('t', (1.0, 1.0, 1.0, 0.25))

        """
        values: dict[str, Value] = dict(self.mat_attrib)
        values["name"] = self.mat_name
        values["texture"] = self.tex_name
        texture = self.texture
        if texture is not None and not isinstance(texture, str) and texture[3] < 1:
            values.setdefault("rgba", (1.0, 1.0, 1.0, texture[3]))
        return ordered_node(Material, values.items())

    def prefixed(self, prefix: str) -> CustomMaterial:
        """A copy whose texture and material names start with ``prefix`` (unless ``shared``).

        The prefix is always added, even to a name that already starts with it.

        Examples:
            >>> plain = CustomMaterial(texture=None, tex_name="t", mat_name="m")
            >>> plain.prefixed("p_").tex_name, plain.prefixed("p_").prefixed("p_").name
            ('p_t', 'p_p_m')
            >>> attrs.evolve(plain, shared=True).prefixed("p_").name
            'm'

        """
        if self.shared or not prefix:
            return self
        return attrs.evolve(self, tex_name=prefix + self.tex_name, mat_name=prefix + self.mat_name)


#: robosuite's material when ``add_material`` is given none: a white flat cube texture.
DEFAULT_MATERIAL = CustomMaterial(
    texture=None,
    tex_name="default_tex",
    mat_name="default_mat",
    tex_attrib={
        "type": "cube",
        "builtin": "flat",
        "width": 100,
        "height": 100,
        "rgb1": (1, 1, 1),
        "rgb2": (1, 1, 1),
    },
)


class MaterialResult(NamedTuple, Generic[_E]):
    """What :func:`with_material` returns.

    Examples:
        >>> from mjcf_model import Geom
        >>> tree, texture, material, used = with_material(Geom(group=1))
        >>> tree.material, texture.name, material.name, used
        ('default_mat', 'default_tex', 'default_mat', True)

    """

    #: The new tree (the input itself when no geom took the material).
    tree: _E
    #: The ``<texture>`` asset the material uses.
    texture: Texture
    #: The ``<material>`` asset.
    material: Material
    #: Whether any geom took the material.
    used: bool


def with_material(
    node: _E, material: CustomMaterial | None = None, naming_prefix: str = ""
) -> MaterialResult[_E]:
    """Give every visual geom without a material this one: robosuite's ``add_material``.

    Every ``geom`` element (``node`` included) whose group is 1 and that has no
    ``material`` gets ``material=<material name>``. Unless the material is
    ``shared``, its texture and material names get ``naming_prefix`` first,
    always (robosuite skips the prefix when the material name already starts
    with it). The input is not changed, and neither is ``material``.

    Args:
        node: The tree.
        material: The material; ``None`` is robosuite's default,
            :data:`DEFAULT_MATERIAL`.
        naming_prefix: Prefix of the texture and material names.

    Returns:
        The new tree, the texture and material nodes, and whether any geom took
        the material.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="v", group=1), Geom(name="m", group=1, material="x")])
        >>> result = with_material(body, CustomMaterial(texture=None, tex_name="t", mat_name="m"))
        >>> [g.material for g in result.tree.geoms], result.tree.geoms[1] is body.geoms[1]
        (['m', 'x'], True)

    """
    chosen = (DEFAULT_MATERIAL if material is None else material).prefixed(naming_prefix)
    used = False

    def visit(current: Node) -> Node:
        nonlocal used
        if (
            isinstance(current, Element)
            and geom_role(current) == "visual"
            and get_attribute(current, "material") is None
        ):
            used = True
            return with_attributes(current, {"material": chosen.name})
        return current

    tree = cast(_E, map_tree(visit, node))
    return MaterialResult(tree, chosen.texture_node, chosen.material_node, used)


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
