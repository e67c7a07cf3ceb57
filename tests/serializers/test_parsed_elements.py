"""Tests of ``mjcf_model.serializers.parsed_elements``."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any
from xml.sax.saxutils import quoteattr

import attrs
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import (
    Geom,
    Joint,
    Mesh,
    Unparsed,
    prefixed,
)
from mjcf_model.nodes.base import Element, TypedElement, attribute_items, build_node
from mjcf_model.nodes.node_info import xml_name
from mjcf_model.serializers import dumps, loads
from mjcf_model.serializers.etree_view import paired
from mjcf_model.serializers.layout import Layout, SourceText, detail
from mjcf_model.serializers.parsed_elements import (
    DEFERRED_TEXT,
    build_element,
    read_typed,
    recorded_values,
    written_text,
)
from mjcf_model.strategies import element_values, models
from mjcf_model.values import format_value
from tests.conftest import PER_CLASS
from tests.support.node_classes import TYPED_CLASSES

# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


# -- only MjcfError escapes ------------------------------------------------------------


def test_a_long_number_list_reads_as_a_short_one_does() -> None:
    """Converted after parsing (over 1 MiB of text), a list is the value the builder makes."""
    numbers = " ".join(f"{i / 7:.6f}" for i in range(3 * 60_000))
    text = f'<mujoco><asset><mesh name="m" vertex="{numbers}"/></asset></mujoco>'
    assert len(numbers) > DEFERRED_TEXT
    mesh = loads(text).asset.meshes[0]
    assert mesh.vertex == build_node(Mesh, {"vertex": numbers}).vertex
    assert type(mesh.vertex) is tuple and len(mesh.vertex) == 180_000
    assert dumps(loads(text)) == text
    assert dumps(prefixed(loads(text), "p_")) == text.replace('name="m"', 'name="p_m"')


# -- The text reader's fast path for typed elements gives what the general builder gives. ------


def _layout(tag: str, pairs: list[tuple[str, str]]) -> Layout:
    """The layout of an empty element written with ``pairs``, as the reader makes it."""
    attributes = "".join(f" {name}={quoteattr(text)}" for name, text in pairs)
    written = f"<{tag}{attributes}/>".encode()
    return Layout(
        SourceText(written),
        tag,
        0,
        len(written),
        len(written),
        [p for pair in pairs for p in pair],
        (),
        None,
    )


def _texts(cls: type[TypedElement], values: dict[str, Any]) -> list[tuple[str, str]]:
    """Each given value as the attribute text a file would hold."""
    names = {f.name: xml_name(f) for f in attrs.fields(cls)}
    given = {field: value for field, value in values.items() if value is not None}
    return [(names[field], format_value(value)) for field, value in given.items()]


@pytest.mark.parametrize("cls", TYPED_CLASSES, ids=lambda cls: cls.__name__)
@PER_CLASS
@given(data=st.data())
def test_fast_path_holds_what_the_field_converters_make(
    cls: type[TypedElement], data: st.DataObject
) -> None:
    """Each field holds its converter's value of the text; the layout records those values."""
    pairs = data.draw(st.permutations(_texts(cls, data.draw(element_values(cls)))))
    names = tuple(name for name, _ in pairs)
    flat = [part for pair in pairs for part in pair]
    layout = _layout(cls.tag, pairs)
    node = read_typed(cls, flat, (), layout, {}, {})
    assert node is not None
    table = cls.__node_info__.table
    for field in attrs.fields(cls):
        given = {table[name]: text for name, text in pairs}
        if field.name in given:
            converted = field.converter(given[field.name])  # type: ignore[misc]
            assert getattr(node, field.name) == converted, field.name
        elif field.name == "attribute_order":
            assert node.attribute_order == names
        elif field.name == "layout":
            assert node.layout is layout
        else:
            assert getattr(node, field.name) == field.default, field.name
    if names:  # the writer works out again what the reader read, and compares
        cut = detail(layout)
        recorded = recorded_values(cut, cls, layout)
        assert recorded == tuple(getattr(node, table[name]) for name in names)
        assert cut.stored == node.__dict__.keys()
    key = cls.__node_info__.keys[0]
    general = build_element(key, cls.tag, pairs, [], None, None, _layout(cls.tag, pairs))
    assert node == general and vars(node).keys() == vars(general).keys()


def test_fast_path_leaves_unknown_attributes_and_unreadable_values_to_the_general_builder() -> None:
    """An attribute without a field, or a value its field cannot read, gives no node."""
    for cls, name, text in (
        (Geom, "colour", "red"),
        (Geom, "size", "1 x"),
        (Joint, "type", "bend"),
    ):
        layout = _layout(cls.tag, [(name, text)])
        assert read_typed(cls, [name, text], (), layout, {}, {}) is None


def test_a_document_keeps_unknown_attributes_and_unreadable_values() -> None:
    """Where the fast path gives up, the reader keeps the text as the general builder does."""
    geom = loads('<mujoco><worldbody><geom colour="red" size="1 x"/></worldbody></mujoco>')
    read = geom.worldbody.geoms[0]
    assert dict(read.extra) == {"colour": "red"}
    assert isinstance(read.size, Unparsed) and read.size.text == "1 x"


def test_equal_attribute_texts_share_one_value() -> None:
    """A text met twice in a document is read once: the nodes share the value."""
    model = loads('<mujoco><worldbody><geom pos="1 2 3"/><geom pos="1 2 3"/></worldbody></mujoco>')
    first, second = model.worldbody.geoms
    assert first.pos == (1.0, 2.0, 3.0) and first.pos is second.pos


def _written_texts_match_the_writer(model: Any) -> int:
    """Check ``written_text`` of every attribute against the text ``dumps`` writes."""
    checked = 0
    keeping_comments = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))
    for element, node in paired(ET.fromstring(dumps(model), parser=keeping_comments), model):
        if not isinstance(node, Element):
            continue
        for name, _ in attribute_items(node):
            assert written_text(node, name) == element.get(name), (node.tag, name)
            checked += 1
        assert written_text(node, "no-such-attribute") is None
    return checked


@pytest.mark.parametrize(
    "text",
    [
        '<mujoco><worldbody><geom group="01" size=" 0.10  0.2" rgba="1 0 0 1"/>'
        "</worldbody></mujoco>",
        '<mujoco><worldbody><body pos="0 0 1e0"><joint range="-1.570 1.570"/></body>'
        "</worldbody></mujoco>",
    ],
)
def test_written_text_is_what_dumps_writes_for_each_attribute(text: str) -> None:
    """Unchanged: the file's spelling; changed: the formatted value (``dumps`` is the referee)."""
    model = loads(text)
    assert _written_texts_match_the_writer(model) > 0
    assert _written_texts_match_the_writer(prefixed(model, "p_")) > 0
    (geom_or_body,) = model.worldbody.children
    changed = attrs.evolve(geom_or_body, pos=(0.5, 0.0, 0.0))
    assert written_text(changed, "pos") == "0.5 0 0"


@given(models())
def test_written_text_of_a_drawn_model_read_back_is_what_dumps_writes(model: Any) -> None:
    """Every attribute of a drawn model, dumped and read again, and of its prefixed copy."""
    loaded = loads(dumps(model))
    _written_texts_match_the_writer(loaded)
    _written_texts_match_the_writer(prefixed(loaded, "p_"))
