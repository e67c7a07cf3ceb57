"""compat ``mjcf_utils`` value helpers and constructors against robosuite's, on generated values.

Each example calls robosuite's function and ours with the same arguments and
requires the same result (or the same exception type).
"""

from __future__ import annotations

import os
import tempfile
import types
import uuid
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
from hypothesis import given
from hypothesis import strategies as st
from PIL import Image

from tests.support.compat_utils import (
    CASES,
    arrays,
    comparable,
    finite,
    ours,
    rs,
    run,
    scalars,
    values,
)

texts = st.lists(
    st.sampled_from(["0", "1", "-2.5", "1e-3", "+.5", "None", "inf", "nan", "x", "", " ", "\t"]),
    max_size=5,
).map(" ".join) | st.text("0123456789. -eN\t\n", max_size=12)


def same_call(name: str, *args: Any, **kwargs: Any) -> tuple[Any, Any]:
    """Call robosuite's and our ``name``; assert the same result or exception type."""
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        theirs, their_error = run(getattr(rs, name), *args, **kwargs)
        mine, my_error = run(getattr(ours, name), *args, **kwargs)
    CASES[name] += 1
    assert my_error == their_error, f"{name}: robosuite raised {their_error}, we {my_error}"
    assert comparable(mine, {}) == comparable(theirs, {}), name
    return mine, theirs


@given(values)
def test_array_to_string_matches_robosuite(value: Any) -> None:
    """array_to_string gives robosuite's text, or its exception type."""
    same_call("array_to_string", value)


@given(texts)
def test_string_to_array_matches_robosuite(text: str) -> None:
    """string_to_array gives robosuite's array (dtype, shape, items), or its ValueError."""
    same_call("string_to_array", text)


@given(values)
def test_convert_to_string_matches_robosuite(value: Any) -> None:
    """convert_to_string gives robosuite's text, or its ValueError for numpy scalars and others."""
    same_call("convert_to_string", value)


attribute_names = st.sampled_from(
    ["quat", "euler", "density", "friction", "damping", "axis", "flag"]
)
attributes = st.dictionaries(attribute_names, values, max_size=4)
names = st.none() | st.text(max_size=3) | st.sampled_from(["g", "main"])


def same_element(name: str, *args: Any, **kwargs: Any) -> None:
    """Build with robosuite's and our ``name``; assert the same bytes or exception types."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        theirs, their_error = run(getattr(rs, name), *args, **kwargs)
        mine, my_error = run(getattr(ours, name), *args, **kwargs)
    CASES[name] += 1
    assert my_error == their_error, f"{name}: robosuite raised {their_error}, we {my_error}"
    if theirs is not None:
        their_text, their_text_error = run(ET.tostring, theirs)
        my_text, my_text_error = run(ET.tostring, mine)
        assert (my_text, my_text_error) == (their_text, their_text_error), name


@given(
    st.sampled_from(["body", "geom", "wheel", "position"]),
    names,
    attributes,
    st.data(),
)
def test_constructors_match_robosuite(
    tag: str, name: str | None, extra: dict[str, Any], data: st.DataObject
) -> None:
    """Every new_* gives robosuite's bytes (or exception) for the same arguments."""
    same_element("new_element", tag, name, **extra)
    same_element("new_joint", name, **extra)
    joint = data.draw(st.none() | st.sampled_from(["j", "hinge0"]))
    act_type = data.draw(st.sampled_from(["actuator", "motor", "position"]))
    same_element("new_actuator", name, joint, act_type, **extra)
    named = data.draw(
        st.fixed_dictionaries({}, optional={"rgba": values, "pos": values, "size": values})
    )
    same_element("new_site", name, **named, **extra)
    geom_type = data.draw(st.none() | st.sampled_from(["box", "sphere"]))
    size = data.draw(values)
    geom_named = data.draw(st.fixed_dictionaries({}, optional={"pos": values, "group": values}))
    same_element("new_geom", name, geom_type, size, **geom_named, **extra)
    body_named = data.draw(st.fixed_dictionaries({}, optional={"pos": values}))
    same_element("new_body", name, **body_named, **extra)
    inertial = data.draw(st.fixed_dictionaries({}, optional={"pos": values, "mass": values}))
    same_element("new_inertial", **inertial, **extra)


bounds = st.none() | st.lists(st.floats(0, 1), min_size=1, max_size=3)


@given(
    st.none() | st.lists(finite, max_size=3) | st.lists(st.integers(0, 9), max_size=3),
    bounds,
    bounds,
    st.lists(st.floats(0.5, 1), min_size=1, max_size=3),
    st.lists(st.floats(0, 0.5), min_size=1, max_size=3),
    st.integers(0, 2**32 - 1),
    st.booleans(),
)
def test_get_size_matches_robosuite(
    size: Any,
    size_max: Any,
    size_min: Any,
    default_max: Any,
    default_min: Any,
    seed: int,
    legacy: bool,
) -> None:
    """get_size gives robosuite's array from the same random generator, or its error."""

    def rng() -> Any:
        return np.random.RandomState(seed) if legacy else np.random.default_rng(seed)

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        theirs = run(rs.get_size, size, size_max, size_min, default_max, default_min, rng())
        mine = run(ours.get_size, size, size_max, size_min, default_max, default_min, rng())
    CASES["get_size"] += 1
    assert comparable(mine, {}) == comparable(theirs, {})


@given(
    st.lists(
        st.dictionaries(st.sampled_from(["a", "b", "geom_types", "sizes"]), scalars, max_size=3),
        max_size=4,
    ),
    st.booleans(),
    scalars,
)
def test_add_to_dict_matches_robosuite(
    calls: list[dict[str, Any]], fill_in_defaults: bool, default_value: Any
) -> None:
    """add_to_dict grows the same lists as robosuite's, quirks included, and returns the dict."""
    theirs: dict[str, list[Any]] = {}
    mine: dict[str, list[Any]] = {}
    for kwargs in calls:
        their_result = run(rs.add_to_dict, theirs, fill_in_defaults, default_value, **kwargs)
        my_result = run(ours.add_to_dict, mine, fill_in_defaults, default_value, **kwargs)
        CASES["add_to_dict"] += 1
        assert comparable(my_result, {}) == comparable(their_result, {})
        assert my_result[0] is None or my_result[0] is mine


@given(
    st.integers(-3, 3)
    | finite
    | st.lists(finite, max_size=4)
    | st.lists(st.lists(st.integers(0, 3), min_size=1, max_size=2), max_size=3)
    | arrays
)
def test_normalize_scale_array_matches_robosuite(scale: Any) -> None:
    """normalize_scale_array gives robosuite's array (dtype included), or its ValueError."""
    same_call("normalize_scale_array", scale)


@given(st.text("ab/._ ", max_size=8), st.none() | st.text("ab/", max_size=5))
def test_xml_path_completion_matches_robosuite(path: str, root: str | None) -> None:
    """xml_path_completion gives robosuite's path (its assets directory by default)."""
    same_call("xml_path_completion", path, root)


@given(
    st.sampled_from(["a", "b", 3]) | st.lists(st.sampled_from(["a", "b", 0, 7]), max_size=4),
    st.sampled_from(["geom", "body", "joint", "sensor", "light", "mesh"]),
    st.booleans(),
)
def test_get_ids_matches_robosuite(elements: Any, element_type: str, inplace: bool) -> None:
    """get_ids gives robosuite's ids, changes the given list as robosuite does, and fails alike."""
    table = {"a": 10, "b": 11}
    model = types.SimpleNamespace(
        **{f"{kind}_name2id": table.__getitem__ for kind in ["geom", "body", "joint", "sensor"]},
        light_name2id=table.__getitem__,
    )
    sim = types.SimpleNamespace(model=model)
    their_input = list(elements) if isinstance(elements, list) else elements
    my_input = list(elements) if isinstance(elements, list) else elements
    theirs = run(rs.get_ids, sim, their_input, element_type, inplace)
    mine = run(ours.get_ids, sim, my_input, element_type, inplace)
    CASES["get_ids"] += 1
    assert mine == theirs and my_input == their_input


def test_save_sim_model_matches_robosuite() -> None:
    """save_sim_model writes what sim.save writes, as robosuite does."""
    sim = types.SimpleNamespace(save=lambda file, format: file.write(f"<mujoco {format}/>"))
    folder = Path(tempfile.mkdtemp())
    rs.save_sim_model(sim, str(folder / "theirs.xml"))
    ours.save_sim_model(sim, str(folder / "ours.xml"))
    CASES["save_sim_model"] += 1
    written = (folder / "ours.xml").read_text()
    assert written == (folder / "theirs.xml").read_text() == "<mujoco xml/>"


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
