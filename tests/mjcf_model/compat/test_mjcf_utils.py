"""Tests of ``mjcf_model.compat.mjcf_utils``."""

from __future__ import annotations

import inspect
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from mjcf_model.compat import mjcf_utils as compat_module
from tests.conftest import corpus_files, corpus_id
from tests.support.compat_utils import (
    E2,
    RS_CONSTANTS,
    _parts,
    check_by_substring,
    differential,
    element_filters,
    find_parents,
    ours,
    prefix_logging,
    prefix_twice,
    rs,
    scale_each,
    scale_model,
    tag_filter,
)

# -- compat ``mjcf_utils``: the same names and signatures as robosuite's, and the golden checks.
#
# The golden checks are items 1 to 6 of section 6 of the robosuite contract
# (``/work/shared/reference/robosuite_contract.md``), each run against robosuite
# 1.5.2 itself and against the exact text the contract recorded.


#: robosuite's public functions and classes (defined in its module) and constants.
RS_FUNCTIONS = sorted(
    name
    for name, value in vars(rs).items()
    if callable(value) and getattr(value, "__module__", None) == rs.__name__
)


def test_every_public_name_of_robosuite_is_here() -> None:
    """Every function, class and constant of robosuite's module exists here, public in __all__."""
    assert len(RS_FUNCTIONS) == 33 and len(RS_CONSTANTS) == 15
    for name in RS_FUNCTIONS + RS_CONSTANTS:
        assert hasattr(compat_module, name), name
        assert (name in compat_module.__all__) == (not name.startswith("_")), name
    assert len(set(compat_module.__all__)) == len(compat_module.__all__)
    assert set(compat_module.__all__) <= set(RS_FUNCTIONS + RS_CONSTANTS)


@pytest.mark.parametrize("name", RS_FUNCTIONS)
def test_signatures_match_robosuite(name: str) -> None:
    """Each function takes the same parameters as robosuite's: names, kinds and defaults."""

    def parameters(function: Any) -> list[tuple[str, Any, Any]]:
        signature = inspect.signature(function)
        return [(p.name, p.kind, p.default) for p in signature.parameters.values()]

    assert parameters(getattr(ours, name)) == parameters(getattr(rs, name))


# -- compat ``mjcf_utils`` tree functions against robosuite's, on generated models and the
#    corpus.
#
# Every case runs robosuite's function and ours on copies of one tree and
# requires the same bytes from ``ET.tostring``, the same return value (elements
# compared by position) and the same exception type. Where robosuite crashes on
# valid MJCF (numbers separated by several spaces; unnamed elements and
# ``return_first`` in ``find_elements_by_substring``), ours must give what
# robosuite gives on the input it can read.


CORPUS = corpus_files()


# -- operations shared by the generated and the corpus cases -----------------------------


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


def test_tree_functions_keep_the_element_objects() -> None:
    """The tree functions change attributes on the same Element objects; none is replaced."""
    root = ET.fromstring(E2)
    before = list(root.iter())
    ours.add_prefix(root, "p_")
    ours.set_alpha(root, 0.5)
    ours.recolor_collision_geoms(root, ours.RED)
    ours.add_material(root, "p_")
    ours.scale_mjcf_model(root, ET.Element("asset"), 2, ours.get_elements, worldbody=root)
    assert all(a is b for a, b in zip(root.iter(), before, strict=True))
    assert root[0].get("rgba") == "1 0 0 1" and root[0].get("name") == "p_g"
