"""compat ``mjcf_utils`` tree functions against robosuite's, on generated models and the corpus.

Every case runs robosuite's function and ours on copies of one tree and
requires the same bytes from ``ET.tostring``, the same return value (elements
compared by position) and the same exception type. Where robosuite crashes on
valid MJCF (numbers separated by several spaces; unnamed elements and
``return_first`` in ``find_elements_by_substring``), ours must give what
robosuite gives on the input it can read.
"""

from __future__ import annotations

import warnings
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mjcf_model import Mujoco
from mjcf_model.compat.mjcf_utils.constants import MUJOCO_NAMED_ATTRIBUTES
from mjcf_model.compat.mjcf_utils.naming import prefixed_attributes
from mjcf_model.nodes import Body, Geom, Joint, Mesh, Site
from mjcf_model.strategies import elements, models
from serializers import to_etree
from tests.conftest import corpus_files, corpus_id
from tests.support.compat_utils import (
    TAGS,
    _parts,
    at,
    check_by_substring,
    differential,
    element_filters,
    find_parents,
    messy_trees,
    name_sets,
    named_elements,
    prefix_logging,
    prefix_twice,
    prefixes,
    rs,
    scale_each,
    scale_model,
    tag_filter,
)

CORPUS = corpus_files()
ATTRIBUTES = [*sorted(MUJOCO_NAMED_ATTRIBUTES), "rgba", "refname", "site1", "file"]
tag_choices = (
    st.just("default")
    | st.sampled_from(TAGS)
    | st.lists(st.sampled_from(TAGS), max_size=3)
    | st.frozensets(st.sampled_from(TAGS), max_size=3)
)
attribute_choices = (
    st.just("default")
    | st.sampled_from(ATTRIBUTES)
    | st.lists(st.sampled_from(ATTRIBUTES), max_size=4)
)
scales = (
    st.integers(1, 4)
    | st.floats(0.1, 10)
    | st.lists(st.floats(0.1, 10), min_size=3, max_size=3)
    | st.lists(st.integers(1, 3), min_size=3, max_size=3).map(np.array)
)
colors = st.lists(st.floats(0, 1), min_size=4, max_size=4) | st.lists(
    st.floats(0, 1), min_size=4, max_size=4
).map(np.array)


def _quiet(operation: Any) -> Any:
    """The operation with numpy's overflow warnings silenced (extreme generated numbers)."""

    def quiet(module: Any, root: ET.Element) -> Any:
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            return operation(module, root)

    return quiet


# -- operations shared by the generated and the corpus cases -----------------------------


def find_with(tags: Any, attribs: Any, return_first: bool) -> Any:
    """``find_elements`` with these arguments."""
    return lambda m, r: m.find_elements(r, tags, attribs, return_first)


def corpus_cases(root: ET.Element) -> list[tuple[str, Any, bool]]:
    """``(function, operation, right_on_crash)`` for one corpus tree."""
    first_name = next((e.get("name") for e in root.iter() if e.get("name")), "x")
    first_geom = next((e.get("name") for e in root.iter("geom") if e.get("name")), "floor")
    cases: list[tuple[str, Any, bool]] = [
        ("add_prefix", prefix_twice("p_"), False),
        ("add_prefix", prefix_twice(first_name[:2]), False),
        ("add_prefix", prefix_twice("p_", tags="geom"), False),
        ("add_prefix", prefix_twice("p_", tags=["body", "joint"], attribs="name"), False),
        (
            "add_prefix",
            prefix_twice("p_", exclude=lambda x: isinstance(x, str) and "a" in x),
            False,
        ),
        ("add_prefix", prefix_logging("p_", frozenset({first_name}), "default", "default"), False),
        ("set_alpha", lambda m, r: m.set_alpha(r, 0.3), True),
        ("set_alpha", lambda m, r: m.set_alpha(r), True),
        (
            "recolor_collision_geoms",
            lambda m, r: m.recolor_collision_geoms(r, [0.5, 0, 0, 1]),
            False,
        ),
        (
            "recolor_collision_geoms",
            lambda m, r: m.recolor_collision_geoms(
                r, np.array([0, 0.5, 0, 1]), exclude=lambda e: e.get("name") == first_geom
            ),
            False,
        ),
        ("add_material", lambda m, r: m.add_material(r, "p_"), False),
        (
            "add_material",
            lambda m, r: m.add_material(r, "p_", m.CustomMaterial(None, "t", "p_m", {"a": 1})),
            False,
        ),
        (
            "add_material",
            lambda m, r: m.add_material(r, "p_", m.CustomMaterial(None, "t", "m", shared=True)),
            False,
        ),
        ("sort_elements", lambda m, r: m.sort_elements(r), False),
        ("sort_elements", lambda m, r: m.sort_elements(r, element_filter=tag_filter), False),
        ("sort_elements", lambda m, r: m.sort_elements(_parts(r)[0], parent=r), False),
        ("_element_filter", element_filters, False),
        ("find_elements", lambda m, r: m.find_elements(r, "geom"), False),
        ("find_elements", lambda m, r: m.find_elements(r, ["body", "site"], None, False), False),
        ("find_elements", lambda m, r: m.find_elements(r, "geom", {"group": "1"}, False), False),
        ("find_elements", lambda m, r: m.find_elements(r, {"geom"}, {"group": None}), False),
        ("find_elements", lambda m, r: m.find_elements(r, "geom", {"group": 1}, False), False),
        ("find_elements", lambda m, r: m.find_elements(r, "nothing", None, False), False),
        ("find_parent", find_parents, False),
        ("get_elements", lambda m, r: m.get_elements(r, "geom"), False),
        ("get_elements", lambda m, r: m.get_elements(r, "body"), False),
        ("get_elements", lambda m, r: m.get_elements(r, "worldbody"), False),
        ("get_elements", lambda m, r: m.get_elements(_parts(r)[0], "body", _parent=r), False),
        ("scale_mjcf_model", scale_model(2, True, True), True),
        ("scale_mjcf_model", scale_model([1, 2, 3], True, False), True),
        ("scale_mjcf_model", scale_model(np.array([0.5, 0.5, 2.0]), False, True), True),
        ("scale_geom_element", scale_each("scale_geom_element", "geom", [1, 2, 3]), True),
        ("scale_site_element", scale_each("scale_site_element", "site", 1.5), True),
        ("scale_body_element", scale_each("scale_body_element", "body", [2, 1, 1]), True),
        ("scale_mesh_element", scale_each("scale_mesh_element", "mesh", 2), True),
        ("scale_joint_element", scale_each("scale_joint_element", "joint", [1, 2, 3]), True),
        (
            "scale_joint_element",
            scale_each("scale_joint_element", "joint", [1, 2, 3], False),
            True,
        ),
    ]
    return cases


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_tree_functions_match_robosuite_on_the_corpus(path: Path) -> None:
    """Every tree function gives robosuite's bytes and results on each corpus file."""
    root = ET.parse(path).getroot()
    for name, operation, right_on_crash in corpus_cases(root):
        differential(name, root, operation, right_on_crash=right_on_crash)
    check_by_substring(root, "geom", ["a", "1"])
    check_by_substring(root, ["body", "joint"], ["0"])


# -- generated trees ------------------------------------------------------------------------


@given(
    messy_trees(),
    prefixes,
    tag_choices,
    attribute_choices,
    name_sets,
    st.sampled_from(["none", "elements", "values", "both"]),
)
def test_add_prefix_matches_robosuite_on_generated_trees(
    tree: tuple[ET.Element, tuple[int, ...]],
    prefix: str,
    tags: Any,
    attribs: Any,
    names: frozenset[str],
    exclusion: str,
) -> None:
    """add_prefix (twice) gives robosuite's bytes, and calls exclude as robosuite does."""
    root, path = tree
    subtree = at(root, path)
    exclude = {
        "none": None,
        "elements": lambda x: not isinstance(x, str) and x.get("name") in names,
        "values": lambda x: isinstance(x, str) and x in names,
        "both": lambda x: (x if isinstance(x, str) else x.get("name")) in names,
    }[exclusion]
    differential(
        "add_prefix", subtree, prefix_twice(prefix, tags=tags, attribs=attribs, exclude=exclude)
    )
    differential("add_prefix", subtree, prefix_logging(prefix, names, tags, attribs))


@given(models(), prefixes)
def test_prefixed_attributes_of_a_typed_model_is_robosuites_add_prefix(
    model: Mujoco, prefix: str
) -> None:
    """On typed nodes (not only a tree's generic ones), the prefixing is robosuite's."""
    theirs = to_etree(model)
    rs.add_prefix(theirs, prefix)
    mine = prefixed_attributes(model, prefix, None, MUJOCO_NAMED_ATTRIBUTES)
    assert ET.tostring(to_etree(mine)) == ET.tostring(theirs)


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


#: The tags robosuite's scale_* functions read.
SCALED_TAGS = ("geom", "site", "body", "mesh", "joint")


@given(messy_trees(aim=("geom", "body", "joint", "site", "motor")), st.data())
def test_queries_match_robosuite_on_generated_trees(
    tree: tuple[ET.Element, tuple[int, ...]], data: st.DataObject
) -> None:
    """sort_elements, _element_filter, find_*, get_elements give robosuite's elements."""
    root, path = tree
    subtree = at(root, path)
    differential("sort_elements", subtree, lambda m, r: m.sort_elements(r))
    differential(
        "sort_elements", subtree, lambda m, r: m.sort_elements(r, element_filter=tag_filter)
    )
    differential("_element_filter", subtree, element_filters)
    tags = data.draw(st.sampled_from(TAGS) | st.lists(st.sampled_from(TAGS), max_size=3))
    attribs = data.draw(
        st.none()
        | st.dictionaries(
            st.sampled_from(["group", "name", "type", "class"]),
            st.none() | st.sampled_from(["0", "1", "1.0", "geom0", "body0", "sphere"]),
            max_size=2,
        )
    )
    for first in (True, False):
        differential("find_elements", subtree, find_with(tags, attribs, first))
    check_by_substring(
        subtree,
        tags,
        data.draw(st.lists(st.sampled_from(["0", "1", "o", "p_"]), min_size=1, max_size=2)),
    )
    differential("find_parent", subtree, find_parents)
    element_type = data.draw(st.sampled_from(TAGS))
    differential("get_elements", subtree, lambda m, r: m.get_elements(r, element_type))


@given(messy_trees(aim=SCALED_TAGS), scales, st.booleans(), st.booleans())
def test_scaling_matches_robosuite_on_generated_trees(
    tree: tuple[ET.Element, tuple[int, ...]], scale: Any, sites: bool, slide: bool
) -> None:
    """scale_mjcf_model and each scale_*_element give robosuite's bytes."""
    root, _path = tree
    differential("scale_mjcf_model", root, scale_model(scale, sites, slide), right_on_crash=True)
    for function, tag in [
        ("scale_geom_element", "geom"),
        ("scale_site_element", "site"),
        ("scale_body_element", "body"),
        ("scale_mesh_element", "mesh"),
    ]:
        differential(function, root, scale_each(function, tag, scale), right_on_crash=True)
    differential(
        "scale_joint_element",
        root,
        scale_each("scale_joint_element", "joint", scale, slide),
        right_on_crash=True,
    )


ELEMENT_SCALERS = {
    Geom: "scale_geom_element",
    Site: "scale_site_element",
    Body: "scale_body_element",
    Mesh: "scale_mesh_element",
    Joint: "scale_joint_element",
}


@given(
    st.sampled_from(sorted(ELEMENT_SCALERS, key=lambda c: c.__name__)).flatmap(elements),
    scales,
    st.booleans(),
)
def test_element_scaling_matches_robosuite_on_generated_elements(
    node: Any, scale: Any, slide: bool
) -> None:
    """Each scale_*_element gives robosuite's bytes (or error) on arbitrary attribute values."""
    function = ELEMENT_SCALERS[type(node)]
    extra = (slide,) if function == "scale_joint_element" else ()
    element = to_etree(node)
    differential(function, element, _quiet(scale_each(function, element.tag, scale, *extra)))


def test_generated_trees_hold_what_the_functions_look_for() -> None:
    """The generated trees hold visual and collision geoms, slide joints, sites and actuators."""
    seen: set[str] = set()

    @settings(max_examples=30, database=None)
    @given(messy_trees())
    def collect(tree: tuple[ET.Element, tuple[int, ...]]) -> None:
        root, _ = tree
        for element in named_elements(root):
            if element.tag == "geom":
                seen.add(f"geom group {element.get('group')}")
            if element.tag == "joint" and element.get("type") == "slide":
                seen.add("slide")
            seen.add(element.tag)

    collect()
    assert {"geom group 1", "geom group None", "slide", "site", "body", "motor"} <= seen
