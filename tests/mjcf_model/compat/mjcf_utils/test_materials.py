"""Tests of ``mjcf_model.compat.mjcf_utils.materials``."""

from __future__ import annotations

import os
import uuid
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from PIL import Image
from robosuite.models import assets_root as RS_ASSETS

from mjcf_model import MjcfLookupError
from tests.support.compat_utils import (
    CASES,
    DEFAULT_MATERIAL_TEXTURE,
    at,
    comparable,
    differential,
    finite,
    messy_trees,
    name_sets,
    ours,
    prefixes,
    rs,
    run,
)

# -- compat ``mjcf_utils``: the same names and signatures as robosuite's, and the golden checks.
#
# The golden checks are items 1 to 6 of section 6 of the robosuite contract
# (``/work/shared/reference/robosuite_contract.md``), each run against robosuite
# 1.5.2 itself and against the exact text the contract recorded.


# -- golden check 5: CustomMaterial ---------------------------------------------------------


def _material(module: Any, *args: Any, **kwargs: Any) -> tuple[Any, Any]:
    material, error = run(module.CustomMaterial, *args, **kwargs)
    if error is not None:
        return error, None
    return None, (material.name, material.shared, material.tex_attrib, material.mat_attrib)


@pytest.mark.parametrize(
    ("args", "kwargs", "tex_attrib", "mat_attrib"),
    [
        (
            ("WoodDark", "dark_wood", "dark_wood_mat"),
            {
                "tex_attrib": {"type": "cube"},
                "mat_attrib": {"texrepeat": "3 3", "specular": "0.4", "shininess": "0.1"},
            },
            {"type": "cube", "name": "dark_wood", "file": "textures/dark-wood.png"},
            {
                "texrepeat": "3 3",
                "specular": "0.4",
                "shininess": "0.1",
                "name": "dark_wood_mat",
                "texture": "dark_wood",
            },
        ),
        (
            (None, "default_tex", "default_mat"),
            {"tex_attrib": DEFAULT_MATERIAL_TEXTURE},
            {
                "type": "cube",
                "builtin": "flat",
                "width": "100",
                "height": "100",
                "rgb1": "1.0 1.0 1.0",
                "rgb2": "1.0 1.0 1.0",
                "name": "default_tex",
            },
            {"name": "default_mat", "texture": "default_tex"},
        ),
        (
            ("objects/../textures/soda.png", "t", "m"),
            {"mat_attrib": {"flag": True, "n": np.float64(0.1)}},
            {"name": "t", "file": "objects/../textures/soda.png"},
            {"flag": "True", "n": "0.1", "name": "m", "texture": "t"},
        ),
        (
            ("/abs/a.png", "t", "m"),
            {"shared": True},
            {"name": "t", "file": "/abs/a.png"},
            {"name": "m", "texture": "t"},
        ),
    ],
    ids=["named", "builtin", "relative-path", "absolute-path"],
)
def test_golden_custom_material(
    args: Any, kwargs: Any, tex_attrib: dict[str, str], mat_attrib: dict[str, str]
) -> None:
    """CustomMaterial holds robosuite's dicts, in robosuite's order (golden check 5)."""
    mine, theirs = _material(ours, *args, **kwargs), _material(rs, *args, **kwargs)
    CASES["CustomMaterial"] += 1
    assert comparable(mine, {}) == comparable(theirs, {})
    if "file" in tex_attrib:
        tex_attrib = {**tex_attrib, "file": os.path.join(RS_ASSETS, tex_attrib["file"])}
    _, (_, _, my_tex, my_mat) = mine
    assert list(my_tex.items()) == list(tex_attrib.items())
    assert list(my_mat.items()) == list(mat_attrib.items())


@pytest.mark.parametrize(
    ("texture", "error"),
    [("Oak", AssertionError), ([0.1, 0.2, 0.3], AssertionError), (5, TypeError)],
)
def test_golden_custom_material_errors(texture: Any, error: type[Exception]) -> None:
    """An unknown texture name or an RGBA of three values fail as in robosuite (golden check 5)."""
    mine, theirs = _material(ours, texture, "t", "m"), _material(rs, texture, "t", "m")
    CASES["CustomMaterial"] += 1
    assert mine == theirs == (error, None)
    with pytest.raises(AssertionError, match=r"Got array of length 3\.Expected rgba"):
        ours.CustomMaterial([0.1, 0.2, 0.3], "t", "m")
    with pytest.raises(AssertionError, match="Valid options are:\ndict_keys"):
        ours.CustomMaterial("Oak", "t", "m")


def _pixels(path: str) -> Any:
    with Image.open(path) as image:
        return image.mode, image.size, np.asarray(image).copy()


def test_golden_custom_material_rgba_writes_robosuite_png() -> None:
    """An RGBA texture writes the PNG robosuite writes, at the same path (golden check 5)."""
    name = f"compat_{uuid.uuid4().hex}"
    theirs = rs.CustomMaterial([0.2, 0.4, 0.6, 1.0], name, "mat")
    their_pixels = _pixels(theirs.tex_attrib["file"])
    mine = ours.CustomMaterial([0.2, 0.4, 0.6, 1.0], name, "mat")
    my_pixels = _pixels(mine.tex_attrib["file"])
    Path(mine.tex_attrib["file"]).unlink()
    assert (
        mine.tex_attrib
        == theirs.tex_attrib
        == {"name": name, "file": f"/tmp/robosuite_temp_tex/{name}.png"}
    )
    assert mine.mat_attrib == theirs.mat_attrib == {"name": "mat", "texture": name}
    assert my_pixels[:2] == their_pixels[:2] == ("RGBA", (100, 100))
    assert np.array_equal(my_pixels[2], their_pixels[2])
    assert tuple(my_pixels[2][50, 50]) == (51, 102, 153, 255)


# -- golden check 6: add_material and recolor_collision_geoms ------------------------------

E5 = (
    '<body name="b"><geom name="v" group="1"/><geom name="c" group="0"/>'
    '<geom name="v2" group="1" material="x"/><geom name="n"/></body>'
)


@pytest.mark.parametrize(
    "material",
    [
        None,
        ("t", "m", False),
        ("t", "m", True),
        ("t", "p_m", False),
    ],
    ids=["default", "custom", "shared", "already-prefixed"],
)
def test_golden_add_material(material: tuple[str, str, bool] | None) -> None:
    """add_material changes the tree, the material and returns elements like robosuite (check 6)."""

    def operation(module: Any, root: ET.Element) -> Any:
        custom = None
        if material is not None:
            tex_name, mat_name, shared = material
            custom = module.CustomMaterial(None, tex_name, mat_name, shared=shared)
        return module.add_material(root, "p_", custom)

    differential("add_material", ET.fromstring(E5), operation)
    collision_only = ET.fromstring('<body><geom group="0"/><geom/></body>')
    differential("add_material", collision_only, operation)
    root = ET.fromstring(E5)
    texture, mat, _, used = operation(ours, root)
    assert used
    if material is None:
        assert ET.tostring(texture, encoding="unicode") == (
            '<texture type="cube" builtin="flat" width="100" height="100" rgb1="1.0 1.0 1.0" '
            'rgb2="1.0 1.0 1.0" name="p_default_tex" />'
        )
        assert ET.tostring(mat) == b'<material texture="p_default_tex" name="p_default_mat" />'
        assert ET.tostring(root[0]) == b'<geom name="v" group="1" material="p_default_mat" />'
    if material == ("t", "p_m", False):
        assert ET.tostring(mat) == b'<material texture="t" name="p_m" />'


def test_golden_recolor_collision_geoms() -> None:
    """recolor_collision_geoms paints group 0/none geoms and drops materials (golden check 6)."""
    xml = (
        '<body><geom name="a" material="m"/><geom name="floor"/><geom name="v" group="1"/>'
        '<geom name="g3" group="3"/><geom name="z" group="0" rgba="1 1 1 1"/></body>'
    )

    def operation(module: Any, root: ET.Element) -> None:
        module.recolor_collision_geoms(root, [0.5, 0, 0, 1], lambda e: e.get("name") == "floor")

    differential("recolor_collision_geoms", ET.fromstring(xml), operation)
    root = ET.fromstring(xml)
    operation(ours, root)
    assert ET.tostring(root[0]) == b'<geom name="a" rgba="0.5 0 0 1" />'
    assert ET.tostring(root[4]) == b'<geom name="z" group="0" rgba="0.5 0 0 1" />'
    assert [e.get("rgba") for e in root[1:4]] == [None, None, None]


def test_named_textures_and_relative_paths_need_robosuite(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without robosuite, a relative path or a named texture raises MjcfLookupError."""
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(
        importlib.util,
        "find_spec",
        lambda name, *a: None if name == "robosuite" else real(name, *a),
    )
    with pytest.raises(MjcfLookupError, match="robosuite is not installed"):
        ours.xml_path_completion("textures/a.png")
    with pytest.raises(MjcfLookupError):
        ours.CustomMaterial("WoodDark", "t", "m")
    assert ours.xml_path_completion("/abs/a.png") == "/abs/a.png"


# -- compat ``mjcf_utils`` tree functions against robosuite's, on generated models and the
#    corpus.
#
# Every case runs robosuite's function and ours on copies of one tree and
# requires the same bytes from ``ET.tostring``, the same return value (elements
# compared by position) and the same exception type. Where robosuite crashes on
# valid MJCF (numbers separated by several spaces; unnamed elements and
# ``return_first`` in ``find_elements_by_substring``), ours must give what
# robosuite gives on the input it can read.


colors = st.lists(st.floats(0, 1), min_size=4, max_size=4) | st.lists(
    st.floats(0, 1), min_size=4, max_size=4
).map(np.array)


# -- generated trees ------------------------------------------------------------------------


@given(
    messy_trees(aim=("geom", "material", "asset")),
    st.floats(0, 1) | st.integers(0, 1),
    colors,
    name_sets,
    prefixes,
    st.data(),
)
def test_color_functions_match_robosuite_on_generated_trees(
    tree: tuple[ET.Element, tuple[int, ...]],
    alpha: float,
    rgba: Any,
    names: frozenset[str],
    prefix: str,
    data: st.DataObject,
) -> None:
    """set_alpha, recolor_collision_geoms and add_material give robosuite's bytes and results."""
    root, path = tree
    subtree = at(root, path)
    differential("set_alpha", subtree, lambda m, r: m.set_alpha(r, alpha), right_on_crash=True)
    exclude = data.draw(st.sampled_from([None, lambda e: e.get("name") in names]))
    differential(
        "recolor_collision_geoms",
        subtree,
        lambda m, r: m.recolor_collision_geoms(r, rgba, exclude=exclude),
    )
    mat_name = data.draw(st.sampled_from(["m", prefix + "m", "default_mat"]))
    shared = data.draw(st.booleans())
    custom = data.draw(st.booleans())

    def material(module: Any, root: ET.Element) -> Any:
        chosen = module.CustomMaterial(None, "t", mat_name, {"builtin": "flat"}, shared=shared)
        return module.add_material(root, prefix, chosen if custom else None)

    differential("add_material", subtree, material)


# -- compat ``mjcf_utils`` value helpers and constructors against robosuite's, on generated
#    values.
#
# Each example calls robosuite's function and ours with the same arguments and
# requires the same result (or the same exception type).


textures = (
    st.sampled_from(["WoodDark", "Metal", "Lemon", "Oak", "textures/a.png", "/abs/b.png"])
    | st.none()
    | st.lists(st.floats(-0.5, 1.5) | st.just(float("nan")), min_size=3, max_size=5)
    | st.lists(st.floats(0, 1), min_size=4, max_size=4).map(np.array)
)
material_values = st.text(max_size=3) | st.integers(0, 9) | finite | st.booleans()
material_values = material_values | st.lists(finite, max_size=3) | st.none()
material_attributes = st.none() | st.dictionaries(
    st.sampled_from(["type", "builtin", "rgb1", "specular", "name", "texture"]),
    material_values | st.lists(finite, min_size=3, max_size=3).map(np.array),
    max_size=3,
)


def _png(path: str) -> Any:
    with Image.open(path) as image:
        return image.mode, image.size, np.asarray(image).tolist()


@given(textures, material_attributes, material_attributes, st.booleans())
def test_custom_material_matches_robosuite(
    texture: Any, tex_attrib: Any, mat_attrib: Any, shared: bool
) -> None:
    """CustomMaterial holds robosuite's dicts and writes robosuite's PNG, or fails alike."""
    tex_name = f"compat_{uuid.uuid4().hex}"
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        arguments = (texture, tex_name, "mat", tex_attrib, mat_attrib, shared)
        theirs, their_error = run(rs.CustomMaterial, *arguments)
        file = "" if theirs is None else theirs.tex_attrib.get("file", "")
        their_png = _png(file) if "robosuite_temp_tex" in file else None
        mine, my_error = run(ours.CustomMaterial, *arguments)
    CASES["CustomMaterial"] += 1
    assert my_error == their_error
    if mine is None:
        return
    assert comparable(mine, {}) == comparable(theirs, {})
    assert list(mine.tex_attrib) == list(theirs.tex_attrib)
    assert list(mine.mat_attrib) == list(theirs.mat_attrib)
    if their_png is not None:
        assert _png(mine.tex_attrib["file"]) == their_png
        os.unlink(mine.tex_attrib["file"])
