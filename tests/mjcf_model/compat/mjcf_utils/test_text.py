"""Tests of ``mjcf_model.compat.mjcf_utils.text``."""

from __future__ import annotations

import tempfile
import types
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.support.compat_utils import (
    CASES,
    arrays,
    comparable,
    finite,
    ours,
    rs,
    run,
    same_arrays,
    scalars,
    values,
)

# -- compat ``mjcf_utils``: the same names and signatures as robosuite's, and the golden checks.
#
# The golden checks are items 1 to 6 of section 6 of the robosuite contract
# (``/work/shared/reference/robosuite_contract.md``), each run against robosuite
# 1.5.2 itself and against the exact text the contract recorded.


# -- golden check 1: number text ----------------------------------------------------------


@pytest.mark.parametrize(
    ("value", "text"),
    [
        ([0.5, 0, 1], "0.5 0 1"),
        (np.array([0.5, 0, 1]), "0.5 0.0 1.0"),
        (np.array([1, 2, 3]), "1 2 3"),
        (np.float32([0.1, 0.2]), "0.10000000149011612 0.20000000298023224"),
        ([1e-8, 1e20], "1e-08 1e+20"),
        ([0.1 + 0.2], "0.30000000000000004"),
        ([], ""),
    ],
)
def test_golden_array_to_string(value: Any, text: str) -> None:
    """array_to_string gives robosuite's text (golden check 1)."""
    assert ours.array_to_string(value) == rs.array_to_string(value) == text


@pytest.mark.parametrize("text", [" 0 1 2 ", "1 None 2", "0  1", ""])
def test_golden_string_to_array(text: str) -> None:
    """string_to_array gives robosuite's array, or its ValueError (golden check 1)."""
    mine, my_error = run(ours.string_to_array, text)
    theirs, their_error = run(rs.string_to_array, text)
    assert my_error == their_error and same_arrays(mine, theirs)
    assert (my_error is ValueError) == (text in ("0  1", ""))


# -- compat ``mjcf_utils`` value helpers and constructors against robosuite's, on generated
#    values.
#
# Each example calls robosuite's function and ours with the same arguments and
# requires the same result (or the same exception type).


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
