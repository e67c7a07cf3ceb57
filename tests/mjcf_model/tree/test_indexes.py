"""Tests of ``mjcf_model.tree.indexes``: lookups that come back use an index of the tree."""

from __future__ import annotations

import gc
import operator
import weakref
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import (
    Body,
    GenericElement,
    Include,
    Mujoco,
    Node,
    find,
    find_all,
    map_elements,
    prefixed,
    renamed,
    scaled,
    with_attributes,
)
from mjcf_model.nodes.base import AnyElement
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.strategies import models
from mjcf_model.tree import indexes
from mjcf_model.tree.indexes import TagIndex, elements_below, index_of
from mjcf_model.tree.traversal import walk, with_children
from tests.conftest import compiling_corpus, corpus_id

CORPUS = compiling_corpus()


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


def _scene(bodies: int) -> str:
    return (
        "<mujoco><worldbody>"
        + "".join(f'<body name="b{i}"><geom name="g{i}" size="1"/></body>' for i in range(bodies))
        + "</worldbody></mujoco>"
    )


def test_an_index_is_built_on_the_second_query_and_goes_with_its_tree() -> None:
    """The first query of a built tree builds nothing; the second builds the index.

    The index never keeps the tree alive.
    """
    read = prefixed(loads(_scene(50)), "p_")
    model = Mujoco(children=read.children)  # a tree built in code: nothing noted its index
    assert index_of(model) is None
    index = index_of(model)
    assert isinstance(index, TagIndex) and index_of(model) is index
    assert index.named("geom", "p_g49") is find(model, "geom", name="p_g49")
    assert model not in index.order and index.order == list(elements_below(model))
    assert len(index.order) == len(list(walk(model))) - 1
    alive = weakref.ref(model)
    key = id(model)
    del model
    gc.collect()
    assert alive() is None and key not in indexes._INDEXES


@given(models(), st.sampled_from(["prefixed", "scaled", "renamed", "map_elements"]))
def test_a_transform_that_keeps_the_shape_indexes_its_result(model: Mujoco, how: str) -> None:
    """A transform's result has its index from its first query, noted as it was built.

    Referee: the index a walk of the result builds, element for element (``is``). A
    scaled model may have a section rebuilt at its root; its first query then walks.
    """
    changed = {
        "prefixed": lambda: prefixed(model, "p_"),
        "scaled": lambda: scaled(model, 2),
        "renamed": lambda: renamed(model, {"body0": "moved"}),
        "map_elements": lambda: map_elements(
            lambda e, key, _: with_attributes(e, {"x": "1"}), model
        ),
    }[how]()
    index = index_of(changed)
    if how == "scaled" and index is None:
        # scaling may rebuild a section at the root (friction defaults): no index then
        assert find_all(changed, "geom") == [e for _, e in walk(changed) if e.tag == "geom"]
    elif changed is not model:
        _assert_the_walks_index(changed, index)


@given(models())
def test_a_transform_that_changes_the_shape_gives_no_index(model: Mujoco) -> None:
    """Elements added or a tag changed: no index is noted, and lookups still answer right."""

    def grown(element: AnyElement, key: str | None, _: object) -> AnyElement:
        if element.tag == "worldbody":
            return with_children(element, [*element.children, Body(name="added")])
        if element.tag == "geom":
            return GenericElement(tag="thing", attributes={"name": "t"})
        return element

    changed = map_elements(grown, model)
    assert index_of(changed) is None  # the first query: nothing noted
    assert find(changed, "body", name="added") is changed.worldbody.children[-1]
    assert find_all(changed, "geom") == []
    assert find_all(changed, "thing") == [e for _, e in walk(changed) if e.tag == "thing"]


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


def _assert_the_walks_index(model: Node, index: TagIndex | None) -> None:
    """``index`` lists what a walk of ``model`` lists: every element below it, by tag."""
    assert index is not None
    walked = TagIndex(model)
    assert index.order == walked.order and all(map(operator.is_, index.order, walked.order))
    for tag, elements in walked.by_tag.items():
        assert [id(e) for e in index.tagged(tag)] == [id(e) for e in elements]
    assert index.tagged("no such tag") == []


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_a_loaded_tree_is_indexed_by_its_reader(path: Path) -> None:
    """A model read from a file has its index from the first query: the reader noted it.

    Referee: the index a walk of the returned tree builds, element for element (``is``).
    With its includes inlined, the tree holds other elements than the ones read: the
    reader's index is not given, and the first query walks.
    """
    model = load(path)
    _assert_the_walks_index(model, index_of(model))
    inlined = load(path, inline_includes=True)
    if any(isinstance(e, Include) for e in elements_below(model)):
        assert index_of(inlined) is None
    else:
        _assert_the_walks_index(inlined, index_of(inlined))


@given(models(), st.sampled_from(["", "<!-- before -->", "<?xml version='1.0'?>\n"]))
def test_a_read_text_is_indexed_by_its_reader(model: Mujoco, before: str) -> None:
    """A drawn model, written and read back (with a comment or declaration before its root)."""
    read = loads(before + dumps(model) + "<!-- after -->")
    _assert_the_walks_index(read, index_of(read))


def test_a_repaired_text_is_indexed_by_the_reader_that_read_it() -> None:
    """Text MuJoCo reads leniently is read again, repaired: the index is the second reader's."""
    read = loads('<mujoco><worldbody><geom name="a&b" size="1"/><site/></worldbody></mujoco>')
    assert find(read, "geom").name == "a&b"
    _assert_the_walks_index(read, index_of(read))


def test_a_tree_with_a_long_attribute_is_indexed() -> None:
    """Attributes converted after parsing (over a megabyte) change no element of the index."""
    numbers = " ".join(["1"] * 600_000)
    read = loads(f'<mujoco><custom><numeric name="n" data="{numbers}"/></custom></mujoco>')
    _assert_the_walks_index(read, index_of(read))
    assert len(find(read, "numeric", name="n").data) == 600_000


def test_the_first_query_of_a_built_tree_walks_without_an_index() -> None:
    """A walk answers the first query by name (the first of that name, document order)."""
    model = loads(_scene(20))
    twice = Mujoco(children=[*model.children, *model.children])
    assert find(twice, "geom", name="g3") is model.worldbody.bodies[3].geoms[0]
    assert index_of(twice) is not None  # the second query built it
