"""Materials: CustomMaterial, with_material and recolored_collision_geoms against robosuite."""

from __future__ import annotations

import importlib.util
import os
import uuid
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import attrs
import mujoco
import numpy as np
import pytest
from hypothesis import given, settings
from PIL import Image
from robosuite.utils import mjcf_utils

from mjcf_model import (
    Asset,
    Body,
    Geom,
    Material,
    MjcfLookupError,
    MjcfValueError,
    Mujoco,
    Node,
    Texture,
    Worldbody,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.compat.materials import (
    DEFAULT_MATERIAL,
    TEXTURE_FILES,
    CustomMaterial,
    MaterialResult,
    recolored_collision_geoms,
    with_material,
)
from mjcf_model.nodes.base import AnyElement, Element, get_attribute
from mjcf_model.strategies import models
from serializers import dumps, load, loads, to_etree
from tests.conftest import corpus_id, loading_corpus

CORPUS = loading_corpus()
ROBOSUITE_CORPUS = [p for p in CORPUS if "robosuite" in p.parts]

TREE = loads(
    """
    <mujoco>
      <worldbody>
        <geom name="floor" type="plane" size="1 1 0.1" material="floor_mat"/>
        <body name="obj">
          <geom name="col" size="0.1" group="0" material="wood"/>
          <geom name="vis" size="0.1" group="1"/>
          <geom name="vis_mat" size="0.1" group="1" material="metal"/>
          <geom name="other" size="0.1" group="2"/>
          <body name="inner"><geom name="nogroup" size="0.05"/><site name="s"/></body>
        </body>
        <body name="untouched"><site name="t"/></body>
      </worldbody>
    </mujoco>
    """
)


def _numbers(text: str | None) -> list[float] | None:
    if text is None:
        return None
    try:
        return [float(token) for token in text.split()]
    except ValueError:
        return None


def _same_values(ours: dict[str, str], theirs: dict[str, str]) -> None:
    """Same keys in the same order; numbers compared numerically, text exactly."""
    assert list(ours) == list(theirs)
    for key, text in theirs.items():
        expected = _numbers(text)
        if expected is None:
            assert ours[key] == text, key
        else:
            assert _numbers(ours[key]) == expected, key


def _attributes(element: AnyElement) -> dict[str, str]:
    return dict(to_etree(element).attrib)


def _geom_states(root: ET.Element) -> list[tuple[str | None, str | None, list[float] | None]]:
    return [(g.get("name"), g.get("material"), _numbers(g.get("rgba"))) for g in root.iter("geom")]


def _assert_shared(old: Node, new: Node) -> None:
    """Every subtree equal to the input's is the input's own object."""
    if old == new:
        assert new is old
        return
    assert isinstance(old, Element) and isinstance(new, Element)
    assert len(old.children) == len(new.children)
    for before, after in zip(old.children, new.children, strict=True):
        _assert_shared(before, after)


def _robosuite_material(**kwargs: Any) -> mjcf_utils.CustomMaterial:
    return mjcf_utils.CustomMaterial(**kwargs)


WOOD = {
    "texture": "WoodDark",
    "tex_name": "dark_wood",
    "mat_name": "dark_wood_mat",
    "tex_attrib": {"type": "cube"},
    "mat_attrib": {"texrepeat": "3 3", "specular": "0.4", "shininess": "0.1"},
}


def test_texture_files_are_robosuites_and_read_only() -> None:
    """The 27 names map to robosuite's files, in robosuite's order; the mapping is read-only."""
    assert list(TEXTURE_FILES.items()) == list(mjcf_utils.TEXTURE_FILES.items())
    assert len(TEXTURE_FILES) == 27
    with pytest.raises(TypeError):
        TEXTURE_FILES["Oak"] = "oak.png"  # type: ignore[index]


@pytest.mark.parametrize("name", list(TEXTURE_FILES))
def test_named_texture_file_is_robosuites_file(name: str) -> None:
    """A named texture's file is the path robosuite writes, and the file exists."""
    ours = CustomMaterial(texture=name, tex_name="t", mat_name="m")
    theirs = _robosuite_material(texture=name, tex_name="t", mat_name="m")
    file = ours.texture_node.file
    assert file == theirs.tex_attrib["file"]
    assert file is not None and os.path.isfile(file)


def test_named_texture_nodes_equal_robosuites_dicts() -> None:
    """``texture_node``/``material_node`` have robosuite's tex_attrib/mat_attrib keys and values."""
    ours = CustomMaterial(**WOOD)
    theirs = _robosuite_material(**WOOD)
    _same_values(_attributes(ours.texture_node), theirs.tex_attrib)
    _same_values(_attributes(ours.material_node), theirs.mat_attrib)
    assert ours.name == theirs.name == "dark_wood_mat"
    assert isinstance(ours.texture_node, Texture) and isinstance(ours.material_node, Material)


def test_numeric_attribute_values_equal_robosuites() -> None:
    """Lists, arrays and numpy scalars in the attribute dicts give robosuite's numbers."""
    kwargs: dict[str, Any] = {
        "texture": "WoodRed",
        "tex_name": "redwood",
        "mat_name": "redwood_mat",
        "tex_attrib": {"type": "cube", "width": 64},
        "mat_attrib": {"texrepeat": [1, 1], "specular": 0.4, "shininess": np.float64(0.1)},
    }
    ours = CustomMaterial(**kwargs)
    theirs = _robosuite_material(**kwargs)
    _same_values(_attributes(ours.texture_node), theirs.tex_attrib)
    _same_values(_attributes(ours.material_node), theirs.mat_attrib)


def test_path_texture_is_kept_as_given() -> None:
    """An absolute path is robosuite's too; a relative one is kept (robosuite adds its assets)."""
    absolute = {"texture": "/data/textures/marble.png", "tex_name": "t", "mat_name": "m"}
    ours = CustomMaterial(**absolute)
    _same_values(_attributes(ours.texture_node), _robosuite_material(**absolute).tex_attrib)
    relative = CustomMaterial(texture="textures/marble.png", tex_name="t", mat_name="m")
    assert relative.texture_node.file == "textures/marble.png"
    theirs = _robosuite_material(texture="textures/marble.png", tex_name="t", mat_name="m")
    assert theirs.tex_attrib["file"].endswith(os.path.join("assets", "textures", "marble.png"))


def test_none_texture_equals_robosuites_default_material() -> None:
    """The default material's texture and material equal robosuite's (no file)."""
    theirs = _robosuite_material(
        texture=None,
        tex_name="default_tex",
        mat_name="default_mat",
        tex_attrib={
            "type": "cube",
            "builtin": "flat",
            "width": 100,
            "height": 100,
            "rgb1": np.ones(3),
            "rgb2": np.ones(3),
        },
    )
    _same_values(_attributes(DEFAULT_MATERIAL.texture_node), theirs.tex_attrib)
    _same_values(_attributes(DEFAULT_MATERIAL.material_node), theirs.mat_attrib)
    assert DEFAULT_MATERIAL.texture_node.file is None


def test_rgba_texture_compiles_to_robosuites_pixels() -> None:
    """MuJoCo's flat texture has the colour of the PNG robosuite writes; alpha goes to rgba."""
    rgba = [0.2, 0.4, 0.6, 0.5]
    tex_name = f"mjcf_model_test_{uuid.uuid4().hex}"
    theirs = _robosuite_material(texture=rgba, tex_name=tex_name, mat_name="m")
    png = Path(theirs.tex_attrib["file"])
    with Image.open(png) as image:
        pixels = {tuple(int(v) for v in p) for p in np.asarray(image).reshape(-1, 4)}
        size = image.size
    png.unlink()
    assert len(pixels) == 1
    (pixel,) = pixels
    ours = CustomMaterial(texture=rgba, tex_name=tex_name, mat_name="m")
    assert ours.texture == (0.2, 0.4, 0.6, 0.5)
    model = Mujoco(
        children=[
            Asset(children=[ours.texture_node, ours.material_node]),
            Worldbody(children=[Geom(size=[0.1], material="m")]),
        ]
    )
    compiled = mujoco.MjModel.from_xml_string(dumps(model))
    texels = compiled.tex_data.reshape(-1, compiled.tex_nchannel[0])
    assert {tuple(int(v) for v in texel) for texel in texels} == {pixel[:3]}
    assert compiled.tex_width[0] == size[0]
    assert list(compiled.mat_rgba[0]) == pytest.approx([1, 1, 1, pixel[3] / 255], abs=1 / 255)
    assert ours.material_node.rgba == (1.0, 1.0, 1.0, 0.5)


def test_opaque_rgba_leaves_material_rgba_unset() -> None:
    """With alpha 1 the material sets no rgba; mat_attrib's own rgba wins otherwise."""
    opaque = CustomMaterial(texture=(1, 0, 0, 1), tex_name="t", mat_name="m")
    assert opaque.material_node.rgba is None
    tinted = CustomMaterial(
        texture=(1, 0, 0, 0.5), tex_name="t", mat_name="m", mat_attrib={"rgba": "1 0 0 0.2"}
    )
    assert tinted.material_node.rgba == (1.0, 0.0, 0.0, 0.2)


def test_named_texture_compiles_with_the_image_size() -> None:
    """MuJoCo loads the named texture's image: the texture has the PNG's size."""
    wood = CustomMaterial(**WOOD)
    model = Mujoco(
        children=[
            Asset(children=[wood.texture_node, wood.material_node]),
            Worldbody(children=[Geom(size=[0.1], material="dark_wood_mat")]),
        ]
    )
    compiled = mujoco.MjModel.from_xml_string(dumps(model))
    file = wood.texture_node.file
    assert file is not None
    with Image.open(file) as image:
        assert (compiled.tex_width[0], compiled.tex_height[0]) == image.size
    assert compiled.ntex == 1 and compiled.nmat == 1
    assert compiled.geom_matid[0] == 0


def test_invalid_textures_raise_like_robosuite() -> None:
    """An unknown name lists the valid ones; an RGBA of 3 numbers is refused; robosuite agrees."""
    with pytest.raises(MjcfValueError) as caught:
        CustomMaterial(texture="Oak", tex_name="t", mat_name="m")
    assert isinstance(caught.value, ValueError)
    assert all(name in str(caught.value) for name in TEXTURE_FILES)
    with pytest.raises(AssertionError):
        _robosuite_material(texture="Oak", tex_name="t", mat_name="m")
    with pytest.raises(MjcfValueError, match="4 numbers, found 3"):
        CustomMaterial(texture=[1, 0, 0], tex_name="t", mat_name="m")
    with pytest.raises(AssertionError):
        _robosuite_material(texture=[1, 0, 0], tex_name="t", mat_name="m")
    with pytest.raises(MjcfValueError):
        CustomMaterial(texture=["a", "b", "c", "d"], tex_name="t", mat_name="m")


def test_named_texture_needs_robosuite(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without robosuite a named texture's node raises a lookup error saying so."""
    find_spec = importlib.util.find_spec

    def without_robosuite(name: str, package: str | None = None) -> Any:
        return None if name == "robosuite" else find_spec(name, package)

    monkeypatch.setattr(importlib.util, "find_spec", without_robosuite)
    wood = CustomMaterial(**WOOD)
    with pytest.raises(MjcfLookupError, match="robosuite"):
        _ = wood.texture_node
    flat = CustomMaterial(texture=(1, 1, 1, 1), tex_name="t", mat_name="m")
    assert flat.texture_node.builtin == "flat"


def test_custom_material_is_frozen_and_leaves_its_inputs_alone() -> None:
    """The value is immutable and hashable; the caller's dicts are not changed."""
    tex_attrib = {"type": "cube"}
    mat_attrib: dict[str, Any] = {"texrepeat": [3, 3]}
    wood = CustomMaterial(
        texture="WoodDark", tex_name="t", mat_name="m", tex_attrib=tex_attrib, mat_attrib=mat_attrib
    )
    assert tex_attrib == {"type": "cube"} and mat_attrib == {"texrepeat": [3, 3]}
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        wood.tex_name = "x"  # type: ignore[misc]
    with pytest.raises(TypeError):
        wood.tex_attrib["type"] = "2d"  # type: ignore[index]
    same = CustomMaterial(
        texture="WoodDark",
        tex_name="t",
        mat_name="m",
        tex_attrib={"type": "cube"},
        mat_attrib={"texrepeat": "3 3"},
    )
    assert wood == same and hash(wood) == hash(same)
    assert CustomMaterial(texture=np.array([1, 0, 0, 1]), tex_name="t", mat_name="m").texture == (
        1.0,
        0.0,
        0.0,
        1.0,
    )


def test_prefixed_adds_the_prefix_unless_shared() -> None:
    """Texture and material names get the prefix, always; shared materials keep theirs."""
    wood = CustomMaterial(**WOOD)
    prefixed = wood.prefixed("p_")
    assert (prefixed.tex_name, prefixed.mat_name) == ("p_dark_wood", "p_dark_wood_mat")
    assert prefixed.material_node.texture == "p_dark_wood"
    assert prefixed.prefixed("p_").name == "p_p_dark_wood_mat"
    assert wood.tex_name == "dark_wood"
    shared = attrs.evolve(wood, shared=True)
    assert shared.prefixed("p_") is shared


def _robosuite_add_material(
    xml: str, prefix: str, material: mjcf_utils.CustomMaterial | None
) -> tuple[ET.Element, ET.Element, ET.Element, bool]:
    root = ET.fromstring(xml)
    texture, mat, _, used = mjcf_utils.add_material(
        root, naming_prefix=prefix, custom_material=material
    )
    return root, texture, mat, used


def test_with_material_default_matches_robosuite() -> None:
    """The default material: same geoms changed, same texture and material (as dicts)."""
    snapshot = dumps(TREE)
    result = with_material(TREE, naming_prefix="p_")
    root, texture, material, used = _robosuite_add_material(dumps(TREE), "p_", None)
    assert _geom_states(to_etree(result.tree)) == _geom_states(root)
    assert result.used is used is True
    # robosuite writes ``name`` last (new_element); compare as unordered dicts.
    texture_attributes = _attributes(result.texture)
    assert sorted(texture_attributes) == sorted(texture.attrib)
    _same_values({k: texture_attributes[k] for k in texture.attrib}, dict(texture.attrib))
    material_attributes = _attributes(result.material)
    _same_values({k: material_attributes[k] for k in material.attrib}, dict(material.attrib))
    assert dumps(TREE) == snapshot
    _assert_shared(TREE, result.tree)
    assert isinstance(result, MaterialResult) and isinstance(result.tree, Mujoco)


def test_with_material_shared_and_custom_match_robosuite() -> None:
    """A shared material keeps its names; a custom one is prefixed, like robosuite."""
    for shared in (False, True):
        kwargs = {**WOOD, "shared": shared}
        result = with_material(TREE, CustomMaterial(**kwargs), "obj_")
        root, _, material, used = _robosuite_add_material(
            dumps(TREE), "obj_", _robosuite_material(**kwargs)
        )
        assert _geom_states(to_etree(result.tree)) == _geom_states(root)
        assert result.material.name == material.get("name")
        assert result.texture.name == material.get("texture")
        assert result.used == used


def test_with_material_always_prefixes() -> None:
    """A material name already starting with the prefix still gets it (robosuite skips it)."""
    material = CustomMaterial(texture=None, tex_name="t", mat_name="p_m")
    result = with_material(TREE, material, "p_")
    assert (result.material.name, result.texture.name) == ("p_p_m", "p_t")
    _, _, theirs, _ = _robosuite_add_material(
        dumps(TREE), "p_", _robosuite_material(texture=None, tex_name="t", mat_name="p_m")
    )
    assert (theirs.get("name"), theirs.get("texture")) == ("p_m", "t")


def test_with_material_unused_returns_the_input() -> None:
    """When no geom is visual and bare the tree is the input itself and ``used`` is False."""
    body = Body(children=[Geom(name="g", group=1, material="x"), Geom(name="h")])
    result = with_material(body)
    assert result.tree is body and result.used is False
    assert result.material.name == "default_mat"
    visual = Geom(group=1)
    assert with_material(visual).tree.material == "default_mat"


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_with_material_matches_add_material_on_the_corpus(path: Path) -> None:
    """On every corpus file the same geoms get the same material as with robosuite."""
    model = load(path)
    snapshot = dumps(model)
    root = ET.parse(path).getroot()
    material = {**WOOD, "mat_attrib": {"specular": "0.4"}}
    result = with_material(model, CustomMaterial(**material), "p_")
    _, theirs, _, used = mjcf_utils.add_material(root, "p_", _robosuite_material(**material))
    assert _geom_states(to_etree(result.tree)) == _geom_states(root)
    assert result.used == used
    assert result.material.name == theirs.get("name")
    assert dumps(model) == snapshot and model == load(path)
    _assert_shared(model, result.tree)


def test_recolored_collision_geoms_matches_robosuite() -> None:
    """Group 0 and unset geoms are recoloured and lose their material; exclude is honoured."""
    snapshot = dumps(TREE)
    rgba = np.array([0.5, 0.0, 0.0, 1.0])
    new = recolored_collision_geoms(TREE, rgba, lambda g: get_attribute(g, "name") == "floor")
    root = ET.fromstring(dumps(TREE))
    mjcf_utils.recolor_collision_geoms(root, rgba, exclude=lambda e: e.get("name") == "floor")
    assert _geom_states(to_etree(new)) == _geom_states(root)
    changed = [g.get("name") for g in to_etree(new).iter("geom") if g.get("rgba") is not None]
    assert changed == ["col", "nogroup"]
    assert dumps(TREE) == snapshot
    _assert_shared(TREE, new)
    untouched = TREE.worldbody.bodies[1]  # type: ignore[union-attr]
    assert new.worldbody.bodies[1] is untouched  # type: ignore[union-attr]


def test_recolored_keeps_the_attribute_position() -> None:
    """An existing rgba keeps its place, a new one goes last, as ElementTree's ``set`` does."""
    tree = loads(
        '<mujoco><worldbody><geom rgba="1 1 1 1" size="1"/><geom size="1"/></worldbody></mujoco>'
    )
    new = recolored_collision_geoms(tree, [0, 1, 0, 1])
    root = ET.fromstring(dumps(tree))
    mjcf_utils.recolor_collision_geoms(root, [0, 1, 0, 1])
    for ours, theirs in zip(to_etree(new).iter("geom"), root.iter("geom"), strict=True):
        _same_values(dict(ours.attrib), dict(theirs.attrib))


def test_recolored_without_collision_geoms_returns_the_input() -> None:
    """Nothing to recolour: the input comes back; a wrong rgba is refused."""
    body = Body(children=[Geom(group=1), Geom(group=3)])
    assert recolored_collision_geoms(body, (1, 0, 0, 1)) is body
    with pytest.raises(MjcfValueError):
        recolored_collision_geoms(body, (1, 0, 0))


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_recolored_matches_robosuite_on_the_corpus(path: Path) -> None:
    """On every corpus file the same geoms are recoloured as with robosuite."""
    model = load(path)
    snapshot = dumps(model)
    root = ET.parse(path).getroot()
    rgba = [0.5, 0, 0, 1]
    new = recolored_collision_geoms(model, rgba, lambda g: get_attribute(g, "name") == "floor")
    mjcf_utils.recolor_collision_geoms(root, rgba, exclude=lambda e: e.get("name") == "floor")
    assert _geom_states(to_etree(new)) == _geom_states(root)
    assert dumps(model) == snapshot and model == load(path)
    _assert_shared(model, new)


def test_robosuite_corpus_is_covered() -> None:
    """The corpus tests above include robosuite's own models."""
    assert len(ROBOSUITE_CORPUS) >= 50


@settings(max_examples=30, deadline=None)
@given(models())
def test_recolored_drawn_models_compile_with_only_collision_colors_changed(
    model: Mujoco,
) -> None:
    """MuJoCo compiles every recoloured drawn model; only geoms' colours and materials change.

    A spatial tendon's ``<geom geom="..."/>`` is a wrapping reference: painting it (as
    robosuite's own function does) made models MuJoCo rejects ("unrecognized attribute
    'rgba'"). The oracle: every geom MuJoCo puts in group 0 has the colour and no
    material; any other geom keeps its colour and material or, when it takes them from a
    default class whose geom the function painted (robosuite's convention, by the group
    written on each ``geom`` element), has the colour and no material; every other
    compiled array is unchanged.
    """
    rgba = (1.0, 0.0, 0.0, 1.0)
    color = np.float32(rgba)
    before = mujoco.MjModel.from_xml_string(dumps(model))
    after = mujoco.MjModel.from_xml_string(dumps(recolored_collision_geoms(model, rgba)))
    for index, group in enumerate(before.geom_group):
        painted = (after.geom_rgba[index] == color).all() and after.geom_matid[index] == -1
        if group == 0:
            assert painted
        else:
            kept = (after.geom_rgba[index] == before.geom_rgba[index]).all() and (
                after.geom_matid[index] == before.geom_matid[index]
            )
            assert kept or (after.geom_rgba[index] == color).all()
    assert model_differences(before, after, ignore={"geom_rgba", "geom_matid"}) == []
