"""Tests of ``mjcf_model.tree.indexes``: lookups that come back use an index of the tree."""

from __future__ import annotations

import gc
import weakref

from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import Mujoco, find, find_all, prefixed
from mjcf_model.serializers import loads
from mjcf_model.strategies import models
from mjcf_model.tree import indexes
from mjcf_model.tree.indexes import TagIndex, elements_below, index_of
from mjcf_model.tree.traversal import walk


@given(models(), st.data())
def test_indexed_lookups_find_what_a_walk_finds(model: Mujoco, data: st.DataObject) -> None:
    """Every lookup, asked again (from the index), answers as a walk of the whole tree does.

    The referee is the walk itself: every element of the tag, in document order, whose
    attributes match. Lookups by tag, by a collection of tags, by name (names that exist,
    and one that does not) and by another attribute, on the model and on a subtree.
    """
    elements = [element for _, element in walk(model)]
    node = data.draw(st.sampled_from(elements))
    below = [element for _, element in walk(node)]
    present = sorted({e.tag for e in below})
    tags_drawn = st.sampled_from([*present, "nothing"])  # the tags below, and one absent
    tag = data.draw(tags_drawn)
    names = sorted({e.name for e in below if isinstance(getattr(e, "name", None), str)})
    name = data.draw(st.sampled_from([*names, "no such name"]))
    tags = data.draw(st.sets(tags_drawn, max_size=3))
    for _ in range(3):  # the first query walks; the later ones read the index
        assert find_all(node, tag) == [e for e in below if e.tag == tag]
        assert find_all(node, tags) == [e for e in below if e.tag in tags]
        assert find_all(node, set(present)) == below  # every element, in document order
        by_name = [e for e in below if e.tag == tag and getattr(e, "name", None) == name]
        assert find_all(node, tag, name=name) == by_name
        first = find(node, tag, name=name)
        assert first is (by_name[0] if by_name else None)
        assert find_all(node, tag, name=None) == [
            e for e in below if e.tag == tag and getattr(e, "name", None) is None
        ]


def test_an_index_is_built_on_the_second_query_and_goes_with_its_tree() -> None:
    """The first query builds nothing; the second builds the index; it never keeps the tree."""
    model = loads(
        "<mujoco><worldbody>"
        + "".join(f'<body name="b{i}"><geom name="g{i}" size="1"/></body>' for i in range(50))
        + "</worldbody></mujoco>"
    )
    assert index_of(model) is None
    index = index_of(model)
    assert isinstance(index, TagIndex) and index_of(model) is index
    assert index.named("geom", "g49") is find(model, "geom", name="g49")
    assert model not in index.order and index.order == list(elements_below(model))
    assert len(index.order) == len(list(walk(model))) - 1
    alive = weakref.ref(model)
    key = id(model)
    del model
    gc.collect()
    assert alive() is None and key not in indexes._INDEXES


def test_a_transformed_tree_gets_its_own_index() -> None:
    """A tree returned by a transform is another tree: its lookups answer for it."""
    model = loads(
        '<mujoco><worldbody><body name="a"><geom name="g" size="1"/></body></worldbody></mujoco>'
    )
    assert find(model, "geom", name="g") is find(model, "geom", name="g") is not None
    renamed = prefixed(model, "p_")
    for _ in range(2):
        assert find(renamed, "geom", name="g") is None
        assert find(renamed, "geom", name="p_g") is renamed.worldbody.bodies[0].geoms[0]


def test_the_first_of_two_equal_names_is_found_first() -> None:
    """Two elements of one name (allowed for some tags): the index gives the first."""
    model = loads(
        "<mujoco><worldbody><geom name='x' size='1'/><site name='x'/><geom name='x' size='2'/>"
        "</worldbody></mujoco>"
    )
    for _ in range(3):
        assert find(model, "geom", name="x").size == (1.0,)
        assert [g.size for g in find_all(model, "geom", name="x")] == [(1.0,), (2.0,)]
        assert find(model, ("site", "geom"), name="x").tag == "geom"
