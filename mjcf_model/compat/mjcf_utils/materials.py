"""robosuite's materials and colours: ``CustomMaterial``, ``add_material``, recolouring, alpha.

``CustomMaterial`` is the library's one material class: robosuite's mutable record,
with robosuite's attributes and text. :func:`flat_material` makes one of a colour
without writing a file (robosuite writes a PNG), and :func:`default_material` is
``add_material``'s default.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

import numpy as np

from mjcf_model.compat.geom_roles import with_collision_color, with_visual_material
from mjcf_model.compat.mjcf_utils.builders import new_element
from mjcf_model.compat.mjcf_utils.constants import ALL_TEXTURES, TEXTURES
from mjcf_model.compat.mjcf_utils.naming import already_prefixed
from mjcf_model.compat.mjcf_utils.text import array_to_string, parse_numbers, xml_path_completion
from mjcf_model.errors import MjcfValueError
from mjcf_model.files.png import png_bytes
from mjcf_model.nodes.base import AnyElement, Element, Node, attribute_text
from mjcf_model.serializers.etree import from_etree
from mjcf_model.serializers.etree_view import element_index, write_back
from mjcf_model.tree.paths import edited_at
from mjcf_model.tree.traversal import walk_nodes

__all__ = [
    "CustomMaterial",
    "add_material",
    "recolor_collision_geoms",
    "set_alpha",
]

#: Where robosuite writes the PNG of an RGBA texture (a fixed path in robosuite 1.5.2).
_TEMP_TEXTURES = "/tmp/robosuite_temp_tex"
#: Side of that PNG, in pixels.
_PNG_SIDE = 100


def _pixel(channels: tuple[Any, ...]) -> bytes:
    """The RGBA bytes Pillow's ``Image.new("RGBA", size, channels)`` fills an image with.

    Channels are clipped to 0..255; as in Pillow, green, blue and alpha must fit a C
    ``int`` (else ``OverflowError``; a NaN colour becomes the smallest int64).
    """
    for value in channels[1:]:
        if not -(2**31) <= value < 2**31:
            raise OverflowError(f"signed integer out of range: {value}")
    return bytes(min(max(int(value), 0), 255) for value in channels)


class CustomMaterial:
    """A texture and a material: robosuite's ``CustomMaterial``, with the same attributes and text.

    ``texture`` is a name from ``ALL_TEXTURES``, a path containing ``"/"`` (a relative
    one is joined to robosuite's assets), an RGBA (its 100 x 100 PNG is written to
    ``/tmp/robosuite_temp_tex/<tex_name>.png``, as robosuite does) or ``None``.
    Attribute values become text: iterables with ``array_to_string``, the rest with
    ``str`` (so ``True`` is ``"True"``).

    Raises:
        AssertionError: An unknown texture name, or an RGBA that is not four values.

    Examples:
        >>> wood = CustomMaterial("WoodDark", "wood", "wood_mat", mat_attrib={"specular": 0.4})
        >>> wood.mat_attrib
        {'specular': '0.4', 'name': 'wood_mat', 'texture': 'wood'}

    """

    def __init__(
        self,
        texture: Any,
        tex_name: str,
        mat_name: str,
        tex_attrib: dict[str, Any] | None = None,
        mat_attrib: dict[str, Any] | None = None,
        shared: bool = False,
    ) -> None:
        if type(texture) is str:
            default = False
            if "/" not in texture and texture not in ALL_TEXTURES:
                raise AssertionError(
                    f"Error: Requested invalid texture. Got {texture}. "
                    f"Valid options are:\n{ALL_TEXTURES}"
                )
        else:
            default = True
            if texture is not None and len(texture) != 4:
                raise AssertionError(
                    f"Error: Requested default texture. Got array of length {len(texture)}."
                    "Expected rgba array of length 4."
                )
        self.tex_attrib: dict[str, Any] = {} if tex_attrib is None else tex_attrib.copy()
        self.mat_attrib: dict[str, Any] = {} if mat_attrib is None else mat_attrib.copy()
        self.name = mat_name
        self.shared = shared
        self.tex_attrib["name"] = tex_name
        self.mat_attrib["name"] = mat_name
        self.mat_attrib["texture"] = tex_name
        for attrib in (self.tex_attrib, self.mat_attrib):
            for k, v in attrib.items():
                attrib[k] = material_text(v)
        if not default:
            name = texture if "/" in texture else TEXTURES[texture]
            self.tex_attrib["file"] = xml_path_completion(name)
        elif texture is not None:
            pixel = _pixel(tuple((np.array(texture) * 255).astype("int")))
            Path(_TEMP_TEXTURES).mkdir(parents=True, exist_ok=True)
            path = _TEMP_TEXTURES + f"/{tex_name}.png"
            flat = np.frombuffer(pixel, dtype=np.uint8)
            Path(path).write_bytes(png_bytes(np.tile(flat, (_PNG_SIDE, _PNG_SIDE, 1))))
            self.tex_attrib["file"] = path


def material_text(value: Any) -> str:
    """An attribute value as ``CustomMaterial`` writes it.

    Text stays; an iterable becomes ``array_to_string``; anything else ``str`` (so
    ``True`` is ``"True"``).

    Examples:
        >>> material_text("1 1"), material_text([3, 3]), material_text(0.4)
        ('1 1', '3 3', '0.4')
        >>> material_text(True)
        'True'

    """
    if type(value) is str:
        return value
    return array_to_string(value) if isinstance(value, Iterable) else str(value)


def default_material() -> CustomMaterial:
    """Robosuite's material when ``add_material`` is given none: a white flat cube texture.

    A new one on each call: ``add_material`` changes the material it is given.

    Examples:
        >>> default_material().tex_attrib["rgb1"], default_material().name
        ('1.0 1.0 1.0', 'default_mat')

    """
    white = np.ones(3)
    flat = {"type": "cube", "builtin": "flat", "width": 100, "height": 100}
    return CustomMaterial(
        texture=None,
        tex_name="default_tex",
        mat_name="default_mat",
        tex_attrib={**flat, "rgb1": white, "rgb2": white},
    )


def flat_material(rgba: Any, tex_name: str, mat_name: str) -> CustomMaterial:
    """A material of one colour, as MuJoCo's built-in ``flat`` texture: no file is written.

    robosuite's ``CustomMaterial(texture=rgba, ...)`` writes a 100 x 100 PNG of the colour
    to a shared temporary folder (one file per texture name, which objects of different
    colours overwrite); this texture has the same pixels. A flat texture has no alpha: an
    alpha below 1 sets the material's ``rgba`` to ``(1, 1, 1, alpha)``.

    Examples:
        >>> glass = flat_material([0.5, 0.5, 1, 0.25], "t", "m")
        >>> glass.tex_attrib["builtin"], glass.tex_attrib["rgb1"], glass.mat_attrib["rgba"]
        ('flat', '0.5 0.5 1', '1 1 1 0.25')

    """
    color = list(rgba)
    if len(color) != 4:
        raise MjcfValueError(f"expected an RGBA of 4 numbers, found {len(color)} in {rgba!r}")
    flat = {"builtin": "flat", "rgb1": color[:3], "rgb2": color[:3], "width": 100, "height": 100}
    tint = {"rgba": [1, 1, 1, color[3]]} if color[3] < 1 else {}
    return CustomMaterial(None, tex_name, mat_name, tex_attrib=flat, mat_attrib=tint)


def add_material(
    root: ET.Element, naming_prefix: str = "", custom_material: CustomMaterial | None = None
) -> tuple[ET.Element, ET.Element, CustomMaterial, bool]:
    """Give each visual geom (group ``"1"``) without a material the material, in place.

    robosuite's rules, kept: ``root`` itself counts; unless the material is
    ``shared`` or its name already starts with ``naming_prefix``, the material
    object itself gets the prefix (name, texture name, texture reference).
    ``custom_material`` defaults to robosuite's white ``default_mat``.

    Returns:
        ``(texture element, material element, the material, whether a geom took it)``.

    Examples:
        >>> body = ET.fromstring('<body><geom group="1"/><geom group="0"/></body>')
        >>> tex, mat, material, used = add_material(body, "p_")
        >>> body[0].get("material"), ET.tostring(mat, encoding="unicode"), used
        ('p_default_mat', '<material texture="p_default_tex" name="p_default_mat" />', True)

    """
    if custom_material is None:
        custom_material = default_material()
    if not already_prefixed(custom_material.name, naming_prefix) and not custom_material.shared:
        custom_material.name = naming_prefix + custom_material.name
        custom_material.tex_attrib["name"] = naming_prefix + custom_material.tex_attrib["name"]
        custom_material.mat_attrib["name"] = naming_prefix + custom_material.mat_attrib["name"]
        custom_material.mat_attrib["texture"] = (
            naming_prefix + custom_material.mat_attrib["texture"]
        )
    used = False
    node = from_etree(root, typed=False)
    if isinstance(node, Element):
        tree, used = with_visual_material(node, custom_material.name)
        write_back(root, node, tree)
    tex_element = new_element(tag="texture", **custom_material.tex_attrib)
    mat_element = new_element(tag="material", **custom_material.mat_attrib)
    return tex_element, mat_element, custom_material, used


def recolored(node: Node, rgba: Any, exclude: Callable[[AnyElement], Any] | None = None) -> Node:
    """``node`` with each collision geom not excluded painted ``array_to_string(rgba)``.

    robosuite formats the colour only when a geom takes it (and fails only then).
    """
    if not isinstance(node, Element):
        return node
    return with_collision_color(node, lambda: array_to_string(rgba), exclude)


def recolor_collision_geoms(
    root: ET.Element, rgba: Any, exclude: Callable[[ET.Element], Any] | None = None
) -> None:
    """Paint every collision geom of ``root`` (itself included) ``rgba`` and drop its material.

    Unlike robosuite, ``exclude`` sees the geoms as they were before the call.

    Examples:
        >>> tree = ET.fromstring('<body><geom name="floor"/><geom name="g" group="0"/></body>')
        >>> floor = lambda geom: geom.get("name") == "floor"
        >>> recolor_collision_geoms(tree, np.array([0.5, 0, 0, 1]), floor)
        >>> [g.get("rgba") for g in tree]
        [None, '0.5 0.0 0.0 1.0']

    """
    node = from_etree(root, typed=False)
    node_exclude: Callable[[AnyElement], Any] | None = None
    if exclude is not None:
        live = element_index(root, node)
        callback = exclude

        def node_exclude(geom: AnyElement) -> Any:
            return callback(live[id(geom)])

    write_back(root, node, recolored(node, rgba, node_exclude))


def with_alpha(node: Node, alpha: Any) -> Node:
    """``node`` with the alpha of every descendant's ``rgba`` (not ``node``'s) set to ``alpha``."""
    edits: dict[tuple[int, ...], dict[str, str | None]] = {}
    for parent, current, path in walk_nodes(node):
        rgba = attribute_text(current, "rgba")
        if parent is not None and rgba is not None:
            edits[path] = {"rgba": array_to_string([*parse_numbers(rgba)[0:3], alpha])}
    return edited_at(node, edits)


def set_alpha(node: ET.Element, alpha: Any = 0.1) -> None:
    """Set the alpha of every ``rgba`` below ``node`` (not its own) to ``alpha``, in place.

    Colours are rewritten as numpy floats, as robosuite does. Unlike robosuite, any
    white space separates numbers, and an unreadable colour leaves the tree unchanged.

    Examples:
        >>> tree = ET.fromstring('<body><geom rgba="1 0 0 1"/></body>')
        >>> set_alpha(tree, 0.3)
        >>> tree[0].get("rgba")
        '1.0 0.0 0.0 0.3'

    """
    old = from_etree(node, typed=False)
    write_back(node, old, with_alpha(old, alpha))
