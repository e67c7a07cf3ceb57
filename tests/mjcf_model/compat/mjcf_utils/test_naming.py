"""Tests of ``mjcf_model.compat.mjcf_utils.naming``."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import Mujoco
from mjcf_model.compat.mjcf_utils.constants import MUJOCO_NAMED_ATTRIBUTES
from mjcf_model.compat.mjcf_utils.naming import prefixed_attributes
from mjcf_model.serializers import to_etree
from mjcf_model.strategies import models
from tests.support.compat_utils import (
    E2,
    TAGS,
    at,
    differential,
    messy_trees,
    name_sets,
    ours,
    prefix_logging,
    prefix_twice,
    prefixes,
    rs,
)

# -- compat ``mjcf_utils``: the same names and signatures as robosuite's, and the golden checks.
#
# The golden checks are items 1 to 6 of section 6 of the robosuite contract
# (``/work/shared/reference/robosuite_contract.md``), each run against robosuite
# 1.5.2 itself and against the exact text the contract recorded.


# -- golden check 3: add_prefix -------------------------------------------------------------


E2_PREFIXED = (
    '<body name="p_b" childclass="p_c"><geom name="p_g" material="p_m" mesh="p_mesh" '
    'class="p_k" /><joint name="p_j" /><site name="p_s" type="sphere" />'
    '<weld body1="p_b" body2="p_x" /><camera name="p_cam" mode="fixed" /><light name="p_l" />'
    '<foo name="p_f" rgba="1 0 0 1" texture="p_t" /><exclude body1="p_a" body2="p_b" />'
    '<pair geom1="p_g" geom2="p_h" /><motor joint="p_j" name="p_mot" />'
    '<fixed name="p_fx"><joint joint="p_j" coef="1" /></fixed></body>'
)


@pytest.mark.parametrize(
    "options",
    [
        {},
        {"tags": "geom"},
        {"tags": ["geom", "joint"], "attribs": "name"},
        {"exclude": lambda x: not isinstance(x, str) and x.tag == "body"},
        {"exclude": lambda x: x in ("g", "m")},
    ],
    ids=["default", "tags", "tags-attribs", "exclude-element", "exclude-string"],
)
def test_golden_add_prefix(options: dict[str, Any]) -> None:
    """add_prefix on the contract's e2 tree, applied twice, gives robosuite's bytes (check 3)."""

    def twice(module: Any, root: ET.Element) -> None:
        module.add_prefix(root, "p_", **options)
        module.add_prefix(root, "p_", **options)

    differential("add_prefix", ET.fromstring(E2), twice)
    if not options:
        root = ET.fromstring(E2)
        ours.add_prefix(root, "p_")
        assert ET.tostring(root, encoding="unicode") == E2_PREFIXED


def test_golden_add_prefix_skips_values_that_start_with_the_prefix() -> None:
    """Prefix "p" leaves "p_x" and "pp" alone; an empty name becomes the prefix (check 3)."""
    root = ET.fromstring('<body name="p_x"><geom name="pp"/><site name=""/></body>')
    ours.add_prefix(root, "p")
    assert ET.tostring(root) == b'<body name="p_x"><geom name="pp" /><site name="p" /></body>'
    differential("add_prefix", ET.fromstring('<body name="p_x"><geom name="pp"/></body>'), twice_p)


def twice_p(module: Any, root: ET.Element) -> None:
    """add_prefix with prefix "p", twice."""
    module.add_prefix(root, "p")
    module.add_prefix(root, "p")


# -- compat ``mjcf_utils`` tree functions against robosuite's, on generated models and the
#    corpus.
#
# Every case runs robosuite's function and ours on copies of one tree and
# requires the same bytes from ``ET.tostring``, the same return value (elements
# compared by position) and the same exception type. Where robosuite crashes on
# valid MJCF (numbers separated by several spaces; unnamed elements and
# ``return_first`` in ``find_elements_by_substring``), ours must give what
# robosuite gives on the input it can read.


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
