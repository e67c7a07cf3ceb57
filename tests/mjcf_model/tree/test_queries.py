"""Tests of ``mjcf_model.tree.queries``."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from robosuite.utils import mjcf_utils

from mjcf_model import Body, Geom, Mujoco, Site, Worldbody
from mjcf_model.nodes.base import get_attribute
from mjcf_model.serializers import load, loads
from mjcf_model.tree.queries import find, find_all, parent_of
from tests.conftest import corpus_id
from tests.support.query_models import CORPUS, MODEL, _names

# -- Queries: find, find_all, parent_of and categorized, checked against robosuite's mjcf_utils.


def test_find_compares_text_and_typed_values() -> None:
    """``group=1`` and ``group="1"`` both match; vectors match lists, tuples and arrays."""
    world = MODEL.worldbody
    assert world is not None
    upper = find(world, "geom", group=1)
    assert upper is not None and get_attribute(upper, "name") == "upper"
    assert find(world, "geom", group="1") is upper
    assert find(MODEL, "geom", name="upper", size=[0.1]) is upper
    assert find(MODEL, "geom", size=(0.1,)) is upper
    assert find(MODEL, "geom", size=np.array([0.1])) is upper
    assert find(MODEL, "geom", size="0.1") is upper
    assert find(MODEL, "geom", size=0.1) is upper
    assert find(MODEL, "geom", size=[0.1, 0.1]) is None
    assert find(MODEL, "geom", group=np.int64(3)) is find(MODEL, "geom", name="hidden")
    assert find(MODEL, "geom", group=2) is None
    assert find(MODEL, "joint", range=[-1, 1]) is find(MODEL, "joint", name="shoulder")


def test_find_none_means_not_written_and_dclass_means_class() -> None:
    """``attr=None`` matches elements without it; ``dclass`` is the ``class`` attribute."""
    world = MODEL.worldbody
    assert world is not None
    floor = find(world, "geom", group=None)
    assert floor is not None and get_attribute(floor, "name") == "floor"
    assert find(MODEL, "geom", dclass="vis") is find(MODEL, "geom", name="upper")
    assert find(MODEL, "default", dclass="vis") is not None
    assert find(MODEL, "geom", dclass=None, name="upper") is None
    assert find(MODEL, "geom", group=None, rgba=None, name=None) is None


def test_find_accepts_tag_collections_and_includes_the_node() -> None:
    """A set or tuple of tags matches any of them; the start node is a candidate."""
    first = find(MODEL, {"site", "joint"})
    assert first is not None and get_attribute(first, "name") == "shoulder"
    assert find(MODEL, ("site",), size=0.01) is find(MODEL, "site")
    assert find(MODEL, "mujoco") is MODEL
    hand = find(MODEL, "body", name="hand")
    assert hand is not None and find(hand, "body") is hand
    assert find(hand, "joint") is None


def test_find_all_lists_matches_in_document_order() -> None:
    """Matches come in pre-order; no match is an empty list, not None."""
    assert _names(find_all(MODEL, "geom")) == [None, None, "floor", "upper", "collide", "hidden"]
    assert _names(find_all(MODEL, "geom", group=1)) == [None, "upper"]
    assert _names(find_all(MODEL, ["body", "site"])) == ["arm", "hand", "tip", "framed"]
    assert find_all(MODEL, "camera") == []
    assert find_all(MODEL, "geom", name="nope") == []


def test_find_generic_elements_and_extra_attributes_by_text() -> None:
    """Attributes kept as text match a number by its MJCF text."""
    model = loads(
        '<mujoco><worldbody><wheel spokes="5"><geom glow="2"/></wheel></worldbody></mujoco>'
    )
    wheel = find(model, "wheel", spokes=5)
    assert wheel is not None and find(model, "wheel", spokes="5") is wheel
    assert find(model, "geom", glow=2) is not None
    assert find(model, "wheel", spokes=6) is None


def test_parent_of_compares_identity() -> None:
    """The parent holds the very node; the root and equal copies have none."""
    geom = Geom(name="g")
    inner = Body(name="inner", children=[geom])
    root = Mujoco(children=[Worldbody(children=[inner])])
    parent = parent_of(root, geom)
    assert parent is inner
    assert parent_of(root, inner) is root.children[0]
    assert parent_of(root, root) is None
    assert parent_of(root, Geom(name="g")) is None
    assert parent_of(root, Site()) is None


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_find_all_matches_robosuite_find_elements(path: Path) -> None:
    """``find_all``/``find`` pick the same elements as robosuite's ``find_elements``."""
    root = ET.parse(path).getroot()
    model = load(path)
    queries: list[tuple[str | list[str], dict[str, str | None]]] = [
        ("body", {}),
        (["joint", "site"], {}),
        ("geom", {"group": "1"}),
        ("geom", {"group": None}),
        ("geom", {"group": "0"}),
    ]
    for tags, attributes in queries:
        expected = mjcf_utils.find_elements(root, tags, attributes, return_first=False) or []
        found = find_all(model, tags, **attributes)
        assert _names(found) == [e.get("name") for e in expected], (tags, attributes)
        first = mjcf_utils.find_elements(root, tags, attributes, return_first=True)
        match = find(model, tags, **attributes)
        assert (match is None) == (first is None)
        assert match is None or first is None or get_attribute(match, "name") == first.get("name")


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_parent_of_matches_robosuite_find_parent(path: Path) -> None:
    """For every body and joint the parent's tag and name equal robosuite's ``find_parent``."""
    root = ET.parse(path).getroot()
    model = load(path)
    theirs = [e for e in root.iter() if e.tag in ("body", "joint")]
    ours = find_all(model, ["body", "joint"])
    assert len(ours) == len(theirs)
    for mine, their in zip(ours, theirs, strict=True):
        expected = mjcf_utils.find_parent(root, their)
        parent = parent_of(model, mine)
        assert parent is not None and expected is not None
        assert (parent.tag, get_attribute(parent, "name")) == (expected.tag, expected.get("name"))
    assert parent_of(model, model) is None and mjcf_utils.find_parent(root, root) is None
