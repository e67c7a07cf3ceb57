"""Materials: CustomMaterial, with_material and recolored_collision_geoms against robosuite."""

from __future__ import annotations

import importlib.util
import os
import uuid
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest
from hypothesis import given
from PIL import Image
from robosuite.utils import mjcf_utils

from mjcf_model import (
    Asset,
    Body,
    Geom,
    MjcfLookupError,
    MjcfValueError,
    Mujoco,
    Node,
    Worldbody,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.compat.materials import (
    CustomMaterial,
    MaterialResult,
    material_nodes,
    recolored_collision_geoms,
    with_material,
)
from mjcf_model.compat.mjcf_utils.materials import default_material, flat_material
from mjcf_model.nodes.base import AnyElement, Element, get_attribute
from mjcf_model.serializers import dumps, load, loads, to_etree
from mjcf_model.strategies import models
from tests.conftest import corpus_id, loading_corpus
from tests.support.compat_utils import DEFAULT_MATERIAL_TEXTURE

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


MATERIALS: list[dict[str, Any]] = [
    *({"texture": name, "tex_name": "t", "mat_name": "m"} for name in mjcf_utils.TEXTURE_FILES),
    WOOD,
    {
        "texture": "WoodRed",
        "tex_name": "redwood",
        "mat_name": "redwood_mat",
        "tex_attrib": {"type": "cube", "width": 64},
        "mat_attrib": {"texrepeat": [1, 1], "specular": 0.4, "shininess": np.float64(0.1)},
    },
    {"texture": "/data/textures/marble.png", "tex_name": "t", "mat_name": "m"},
    {"texture": "textures/marble.png", "tex_name": "t", "mat_name": "m", "shared": True},
    {
        "texture": None,
        "tex_name": "default_tex",
        "mat_name": "default_mat",
        "tex_attrib": {"type": "cube", "builtin": "flat", "rgb1": np.ones(3), "width": 100},
    },
]


@pytest.mark.parametrize("kwargs", MATERIALS, ids=lambda kwargs: str(kwargs["texture"]))
def test_the_one_material_class_is_robosuites(kwargs: dict[str, Any]) -> None:
    """Named, numeric, path and file-less materials: robosuite's dicts, text and order."""
    ours = CustomMaterial(**kwargs)
    theirs = _robosuite_material(**kwargs)
    assert list(ours.tex_attrib.items()) == list(theirs.tex_attrib.items())
    assert list(ours.mat_attrib.items()) == list(theirs.mat_attrib.items())
    assert (ours.name, ours.shared) == (theirs.name, theirs.shared)
    file = ours.tex_attrib.get("file")
    if isinstance(kwargs["texture"], str) and kwargs["texture"] in mjcf_utils.TEXTURE_FILES:
        assert file is not None and os.path.isfile(file)


def test_the_default_material_is_robosuites_and_new_each_time() -> None:
    """``default_material()`` is what ``add_material`` uses; each call a new object."""
    theirs = _robosuite_material(
        texture=None,
        tex_name="default_tex",
        mat_name="default_mat",
        tex_attrib=DEFAULT_MATERIAL_TEXTURE,
    )
    ours = default_material()
    assert list(ours.tex_attrib.items()) == list(theirs.tex_attrib.items())
    assert list(ours.mat_attrib.items()) == list(theirs.mat_attrib.items())
    assert default_material() is not ours and "file" not in ours.tex_attrib


def _compiled_with(material: Any) -> mujoco.MjModel:
    texture, own = material_nodes(material)
    geom = Geom(size=[0.1], material=own.attributes["name"])
    model = Mujoco(children=[Asset(children=[texture, own]), Worldbody(children=[geom])])
    return mujoco.MjModel.from_xml_string(dumps(model))


def test_a_flat_material_compiles_to_robosuites_pixels_without_a_file() -> None:
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
    ours = flat_material(rgba, tex_name, "m")
    assert "file" not in ours.tex_attrib and not png.exists()
    compiled = _compiled_with(ours)
    texels = compiled.tex_data.reshape(-1, compiled.tex_nchannel[0])
    assert {tuple(int(v) for v in texel) for texel in texels} == {pixel[:3]}
    assert compiled.tex_width[0] == size[0]
    assert list(compiled.mat_rgba[0]) == pytest.approx([1, 1, 1, pixel[3] / 255], abs=1 / 255)
    opaque = flat_material((1, 0, 0, 1), "t", "m")
    assert "rgba" not in opaque.mat_attrib
    with pytest.raises(MjcfValueError, match="4 numbers, found 3"):
        flat_material([1, 0, 0], "t", "m")


def test_named_texture_compiles_with_the_image_size() -> None:
    """MuJoCo loads the named texture's image: the texture has the PNG's size."""
    wood = CustomMaterial(**WOOD)
    compiled = _compiled_with(wood)
    with Image.open(wood.tex_attrib["file"]) as image:
        assert (compiled.tex_width[0], compiled.tex_height[0]) == image.size
    assert compiled.ntex == 1 and compiled.nmat == 1
    assert compiled.geom_matid[0] == 0


def test_invalid_textures_raise_as_robosuites() -> None:
    """An unknown name and an RGBA of 3 numbers raise robosuite's AssertionError, its words."""
    for texture in ("Oak", [1, 0, 0]):
        with pytest.raises(AssertionError) as ours:
            CustomMaterial(texture=texture, tex_name="t", mat_name="m")
        with pytest.raises(AssertionError) as theirs:
            _robosuite_material(texture=texture, tex_name="t", mat_name="m")
        assert str(ours.value) == str(theirs.value)


def test_named_texture_needs_robosuite(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without robosuite a named texture raises a lookup error saying so; a flat one works."""
    find_spec = importlib.util.find_spec

    def without_robosuite(name: str, package: str | None = None) -> Any:
        return None if name == "robosuite" else find_spec(name, package)

    monkeypatch.setattr(importlib.util, "find_spec", without_robosuite)
    with pytest.raises(MjcfLookupError, match="robosuite"):
        CustomMaterial(**WOOD)
    assert flat_material((1, 1, 1, 1), "t", "m").tex_attrib["builtin"] == "flat"


def test_material_nodes_prefix_names_unless_shared_and_leave_the_material_alone() -> None:
    """Texture and material names get the prefix, always; shared materials keep theirs."""
    wood = CustomMaterial(**WOOD)
    before = (dict(wood.tex_attrib), dict(wood.mat_attrib), wood.name)
    texture, own = material_nodes(wood, "p_")
    assert texture.attributes["name"] == "p_dark_wood"
    assert (own.attributes["name"], own.attributes["texture"]) == ("p_dark_wood_mat", "p_dark_wood")
    assert (dict(wood.tex_attrib), dict(wood.mat_attrib), wood.name) == before
    assert list(own.attributes.items())[1:] == [
        ("specular", "0.4"),
        ("shininess", "0.1"),
        ("name", "p_dark_wood_mat"),
        ("texture", "p_dark_wood"),
    ]
    shared = CustomMaterial(**WOOD, shared=True)
    assert material_nodes(shared, "p_")[1].attributes["name"] == "dark_wood_mat"


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
        assert result.material.attributes["name"] == material.get("name")
        assert result.texture.attributes["name"] == material.get("texture")
        assert result.used == used


def test_with_material_always_prefixes() -> None:
    """A material name already starting with the prefix still gets it (robosuite skips it)."""
    material = CustomMaterial(texture=None, tex_name="t", mat_name="p_m")
    result = with_material(TREE, material, "p_")
    names = (result.material.attributes["name"], result.texture.attributes["name"])
    assert names == ("p_p_m", "p_t")
    _, _, theirs, _ = _robosuite_add_material(
        dumps(TREE), "p_", _robosuite_material(texture=None, tex_name="t", mat_name="p_m")
    )
    assert (theirs.get("name"), theirs.get("texture")) == ("p_m", "t")


def test_with_material_unused_returns_the_input() -> None:
    """When no geom is visual and bare the tree is the input itself and ``used`` is False."""
    body = Body(children=[Geom(name="g", group=1, material="x"), Geom(name="h")])
    result = with_material(body)
    assert result.tree is body and result.used is False
    assert result.material.attributes["name"] == "default_mat"
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
    assert result.material.attributes["name"] == theirs.get("name")
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
