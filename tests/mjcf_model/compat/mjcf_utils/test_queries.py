"""Tests of ``mjcf_model.compat.mjcf_utils.queries``."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import attrs
import pytest
from hypothesis import given
from hypothesis import strategies as st
from robosuite.utils import mjcf_utils

from mjcf_model import serializers
from mjcf_model.compat.mjcf_utils.queries import Categories, categorized
from mjcf_model.serializers import load
from mjcf_model.tree.queries import find
from tests.conftest import corpus_id
from tests.support.compat_utils import (
    TAGS,
    at,
    check_by_substring,
    differential,
    element_filters,
    find_parents,
    messy_trees,
    ours,
    rs,
    tag_filter,
)
from tests.support.query_models import CORPUS, MODEL, _names

# -- Queries: find, find_all, parent_of and categorized, checked against robosuite's mjcf_utils.


def test_categorized_by_robosuite_rules() -> None:
    """Joint references, nested bodies, geom groups and section children are sorted."""
    found = categorized(MODEL)
    assert _names(found.root_body) == ["arm", "framed"]
    assert _names(found.bodies) == ["hand"]
    assert _names(found.joints) == ["shoulder"]
    assert _names(found.actuators) == ["m", "g"]
    assert _names(found.sites) == ["tip"]
    assert _names(found.sensors) == ["touch", "clock"]
    assert _names(found.contact_geoms) == [None, "floor", "collide"]
    assert _names(found.visual_geoms) == [None, "upper"]
    theirs = mjcf_utils.sort_elements(ET.fromstring(serializers.dumps(MODEL)))
    for field in attrs.fields(Categories):
        expected = [e.get("name") for e in theirs.get(field.name, [])]
        if field.name == "sensors":  # <clock> is not in robosuite's SENSOR_TYPES
            expected.append("clock")
        assert _names(getattr(found, field.name)) == expected


def test_categorized_node_itself_is_the_root_body() -> None:
    """A body queried on its own is the root body even if it came from inside another."""
    hand = find(MODEL, "body", name="hand")
    assert hand is not None
    found = categorized(hand)
    assert found.root_body == (hand,)
    assert found.bodies == ()
    assert _names(found.sites) == ["tip"]
    assert found.contact_geoms == () and found.visual_geoms == ()


def test_categorized_returns_the_tree_nodes() -> None:
    """The categories hold the tree's own nodes."""
    found = categorized(MODEL)
    assert found.joints[0] is find(MODEL, "joint", name="shoulder")
    assert found.actuators[1] is find(MODEL, "general")
    assert isinstance(found, Categories)


def _sensor_sections(root: ET.Element) -> list[ET.Element]:
    return [child for section in root.iter("sensor") for child in section]


def _robosuite_sensor_types_agree(root: ET.Element) -> bool:
    """Whether robosuite's tag-based sensors are exactly the children of ``<sensor>``."""
    in_sections = _sensor_sections(root)
    by_tag = [e for e in root.iter() if e.tag in mjcf_utils.SENSOR_TYPES]
    return [id(e) for e in in_sections] == [id(e) for e in by_tag]


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_categorized_matches_robosuite_sort_elements(path: Path) -> None:
    """Names (None when unnamed) per category equal robosuite's ``sort_elements``.

    Sensors: robosuite takes every element whose tag is in ``SENSOR_TYPES``, this
    library every child of ``<sensor>``. Where the two definitions pick different
    elements (``<distance>`` sensors in dm_control's ``robot_arm.xml``) the
    sensors are compared with the children of ``<sensor>`` read from ElementTree.
    """
    root = ET.parse(path).getroot()
    theirs = mjcf_utils.sort_elements(root)
    ours = categorized(load(path))
    for field in attrs.fields(Categories):
        expected = [e.get("name") for e in theirs.get(field.name, [])]
        if field.name == "sensors" and not _robosuite_sensor_types_agree(root):
            expected = [e.get("name") for e in _sensor_sections(root)]
        assert _names(getattr(ours, field.name)) == expected, field.name


def test_sensor_definitions_differ_somewhere_in_the_corpus() -> None:
    """The corpus has a file where robosuite's SENSOR_TYPES misses a sensor (so both paths run)."""
    differing = [p for p in CORPUS if not _robosuite_sensor_types_agree(ET.parse(p).getroot())]
    assert [corpus_id(p) for p in differing] == ["dm_control/mjcf/test_assets/robot_arm.xml"]
    root = ET.parse(differing[0]).getroot()
    missed = [e.tag for e in _sensor_sections(root) if e.tag not in mjcf_utils.SENSOR_TYPES]
    assert missed == ["distance", "distance"]
    assert len(categorized(load(differing[0])).sensors) == len(_sensor_sections(root))


# -- compat ``mjcf_utils``: the same names and signatures as robosuite's, and the golden checks.
#
# The golden checks are items 1 to 6 of section 6 of the robosuite contract
# (``/work/shared/reference/robosuite_contract.md``), each run against robosuite
# 1.5.2 itself and against the exact text the contract recorded.


# -- golden check 4: queries ----------------------------------------------------------------


E3 = (
    '<worldbody><body name="a"><geom name="g1" group="1"/><body name="b"><geom name="g2"/>'
    '<geom name="g3" group="0"/><geom name="g4" group="2"/><joint name="j1"/><site name="s1"/>'
    '</body></body><body name="c"><geom name="g5" type="box"/></body></worldbody>'
)


def _names_compat_utils(value: Any) -> Any:
    if isinstance(value, ET.Element):
        return value.get("name") or value.tag
    if isinstance(value, dict):
        return [(k, _names_compat_utils(v)) for k, v in value.items()]
    if isinstance(value, (list, tuple)):
        return [_names_compat_utils(v) for v in value]
    return value


QUERIES = {
    "sort_elements": lambda m, r: m.sort_elements(r),
    "find_elements": lambda m, r: m.find_elements(r, "geom"),
    "find_elements list": lambda m, r: m.find_elements(r, "geom", return_first=False),
    "find_elements none": lambda m, r: m.find_elements(r, "camera"),
    "find_elements list none": lambda m, r: m.find_elements(r, "camera", return_first=False),
    "find_elements group": lambda m, r: m.find_elements(r, "geom", {"group": None}, False),
    "get_elements": lambda m, r: m.get_elements(r, "geom"),
    "get_elements root": lambda m, r: m.get_elements(r, "worldbody"),
    "find_parent": lambda m, r: m.find_parent(r, r[0][1][2]),
    "find_parent root": lambda m, r: m.find_parent(r, r),
}
QUERY_RESULTS = {
    "sort_elements": [
        ("root_body", ["a", "c"]),
        ("visual_geoms", ["g1"]),
        ("bodies", ["b"]),
        ("contact_geoms", ["g2", "g3", "g5"]),
        ("joints", ["j1"]),
        ("sites", ["s1"]),
    ],
    "find_elements": "g1",
    "find_elements list": ["g1", "g2", "g3", "g4", "g5"],
    "find_elements none": None,
    "find_elements list none": None,
    "find_elements group": ["g2", "g5"],
    "get_elements": [["a", "g1"], ["b", "g2"], ["b", "g3"], ["b", "g4"], ["c", "g5"]],
    "get_elements root": [],
    "find_parent": "b",
    "find_parent root": None,
}


@pytest.mark.parametrize("query", sorted(QUERIES))
def test_golden_queries(query: str) -> None:
    """Queries on the contract's e3 tree return robosuite's live elements (golden check 4)."""
    root = ET.fromstring(E3)
    function = query.split()[0]
    differential(function, root, QUERIES[query])
    assert _names_compat_utils(QUERIES[query](ours, root)) == QUERY_RESULTS[query]
    found = QUERIES[query](ours, root)
    elements = found if isinstance(found, list) else [found]
    live = {id(e) for e in root.iter()}
    assert all(id(e) in live for e in elements if isinstance(e, ET.Element))


def test_golden_find_elements_by_substring_returns_the_first_match() -> None:
    """With return_first, the first element whose name matches (robosuite returns None)."""
    root = ET.fromstring(E3)
    assert rs.find_elements_by_substring(root, "geom", "g", return_first=True) is None
    assert ours.find_elements_by_substring(root, "geom", "g", return_first=True) is root[0][0]
    assert _names_compat_utils(ours.find_elements_by_substring(root, "geom", ["4", "5"])) == [
        "g4",
        "g5",
    ]


def test_golden_actuators_and_sensors_are_sorted_like_robosuite() -> None:
    """Children of <actuator> and sensor tags are filed as robosuite files them (golden check 4)."""
    root = ET.fromstring(
        '<mujoco><actuator><motor name="m1"/><general name="m2"/></actuator><sensor>'
        '<touch name="t"/><jointpos name="p"/><user name="u"/><framepos name="f"/>'
        '<clock name="c"/></sensor></mujoco>'
    )
    differential("sort_elements", root, lambda m, r: m.sort_elements(r))
    assert _names_compat_utils(ours.sort_elements(root)) == [
        ("actuators", ["m1", "m2"]),
        ("sensors", ["t", "p", "u", "f"]),
    ]


# -- compat ``mjcf_utils`` tree functions against robosuite's, on generated models and the
#    corpus.
#
# Every case runs robosuite's function and ours on copies of one tree and
# requires the same bytes from ``ET.tostring``, the same return value (elements
# compared by position) and the same exception type. Where robosuite crashes on
# valid MJCF (numbers separated by several spaces; unnamed elements and
# ``return_first`` in ``find_elements_by_substring``), ours must give what
# robosuite gives on the input it can read.


# -- operations shared by the generated and the corpus cases -----------------------------


def find_with(tags: Any, attribs: Any, return_first: bool) -> Any:
    """``find_elements`` with these arguments."""
    return lambda m, r: m.find_elements(r, tags, attribs, return_first)


# -- generated trees ------------------------------------------------------------------------


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
