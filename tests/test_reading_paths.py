"""The text reader's fast path for typed elements gives what the general builder gives."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any
from xml.sax.saxutils import quoteattr

import attrs
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mjcf_model import Geom, Joint
from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.layout import Layout, SourceText, detail
from mjcf_model.nodes.node_info import xml_name
from mjcf_model.strategies import element_values
from mjcf_model.values import Unparsed, format_value
from serializers import from_etree, loads
from serializers.parsed_elements import build_element, read_typed, recorded_values
from tests.conftest import corpus_id, loading_corpus
from tests.support.node_classes import TYPED_CLASSES


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
@settings(max_examples=10)
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


@pytest.mark.parametrize("path", loading_corpus(), ids=corpus_id)
def test_corpus_reads_as_elementtree_reads_it(path: Path) -> None:
    """Each corpus file read from text equals the same file read through ElementTree.

    ElementTree keeps no comment outside the root, so the text is read without them.
    """
    parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))
    tree = ET.fromstring(path.read_bytes(), parser)
    model = loads(ET.tostring(tree))
    assert model == from_etree(tree)


@pytest.mark.parametrize(
    "inner",
    [
        "<geom/>x",  # after an empty-element tag
        "<body></body> x ",  # after an end tag
        "<!-- c -->x",  # after a comment
        "<?pi data?>x",  # after a processing instruction
        "<![CDATA[x]]>",  # in a CDATA section
        "&amp;",  # an entity reference alone
        "\u00a0x",  # after a space XML does not count as white space
        '<site name="a>b"/>',  # a ">" in a value, and no text at all
        "\n  <geom/>\n",  # white space alone
    ],
)
def test_element_text_is_read_whatever_markup_it_follows(inner: str) -> None:
    """Text after any markup, or none, reads as ElementTree reads it (blank text is skipped).

    Text alone is kept exactly; between children, each piece is stripped and joined.
    """
    text = f"<mujoco><worldbody><body name='b'>{inner}</body></worldbody></mujoco>"
    body = loads(text).worldbody.bodies[0]
    element = ET.fromstring(text).find("worldbody/body")
    assert element is not None
    chunks = [element.text or "", *(child.tail or "" for child in element)]
    if len(element):
        expected = " ".join(c.strip() for c in chunks if c.strip()) or None
    else:
        expected = chunks[0] if chunks[0].strip() else None
    assert body.text == expected
