"""Tests of ``mjcf_model.serializers.parsing``."""

from __future__ import annotations

import json
import pickle
import xml.etree.ElementTree as ET
from pathlib import Path

import attrs
import mujoco
import pytest

from mjcf_model import (
    Body,
    Comment,
    Geom,
    MjcfError,
    MjcfSyntaxError,
    compiled,
    find,
    map_elements,
    prefixed,
    with_attributes,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.nodes.base import AnyElement
from mjcf_model.serializers import dump, dumps, from_dict, from_etree, load, loads, to_dict
from mjcf_model.values.encoding import encoded
from tests.conftest import corpus_id, loading_corpus

# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


# -- bytes and markup as MuJoCo reads them ---------------------------------------------


@pytest.mark.parametrize(
    "declaration",
    ["ISO-8859-1", "no-such-encoding", "UTF-16", "Shift_JIS"],
)
def test_bytes_are_read_as_utf8_whatever_the_declaration(declaration: str) -> None:
    """MuJoCo ignores the declared encoding; a name with é reads the same in both."""
    text = (
        f'<?xml version="1.0" encoding="{declaration}"?>'
        '<mujoco><worldbody><geom name="é" size="1"/></worldbody></mujoco>'
    ).encode()
    assert mujoco.MjModel.from_xml_string(text.decode()).geom(0).name == "é"
    model = loads(text)
    assert model.worldbody.geoms[0].name == "é"
    assert loads(dumps(model)) == model


#: A Latin-1 file: bytes that are not UTF-8 in the model's name, a comment, a body's and a
#: geom's name, a text value and character data; and one UTF-8 "é" among them.
LATIN1 = (
    b'<mujoco model="caf\xe9">\n'
    b"  <!-- r\xe9sum\xe9, d\xe9j\xe0 vu -->\n"
    b"  <custom>\n"
    b'    <text name="note" data="\xe9t\xe9"/>\n'
    b"  </custom>\n"
    b"  <worldbody>\n"
    b'    <body name="b\xe9" pos="0 0 1">\n'
    b'      <joint name="caf\xc3\xa9" type="hinge"/>\n'
    b'      <geom name="g\xe9" size="0.1"/>\n'
    b"    </body>\n"
    b"  </worldbody>\n"
    b"</mujoco>\n"
)


def test_bytes_that_are_not_utf8_read_as_mujoco_reads_them(tmp_path: Path) -> None:
    """MuJoCo passes a Latin-1 byte through; the reader escapes it, and gives it back.

    A byte that is not UTF-8 becomes ``surrogateescape``'s escape (``0xE9``:
    ``"\udce9"``); UTF-8 text reads as text. The file is written back byte for byte,
    the model compiles to MuJoCo's own compile of the file (the names table holds the
    byte), and the text, canonical text, dict, JSON and pickle forms read back equal.
    """
    path = tmp_path / "latin1.xml"
    path.write_bytes(LATIN1)
    model = load(path)
    body = model.worldbody.bodies[0]
    assert (model.model, body.name, body.geoms[0].name) == ("caf\udce9", "b\udce9", "g\udce9")
    assert body.joints[0].name == "café"
    assert model.children[0] == Comment(text=" r\udce9sum\udce9, d\udce9j\udce0 vu ")
    assert find(model, "text", name="note").data == "\udce9t\udce9"
    target = tmp_path / "out.xml"
    dump(model, target)
    assert target.read_bytes() == LATIN1
    reference = mujoco.MjModel.from_xml_path(str(path))
    assert b"\x00b\xe9\x00" in bytes(reference.names) and b"\x00g\xe9\x00" in bytes(reference.names)
    assert model_differences(compiled(model), reference) == []
    canonical = dumps(model, canonical=True)
    assert loads(canonical) == model
    assert model_differences(compiled(loads(canonical, base_dir=tmp_path)), reference) == []
    assert loads(dumps(model)) == model
    assert from_dict(to_dict(model)) == model
    assert from_dict(json.loads(json.dumps(to_dict(model)))) == model
    assert pickle.loads(pickle.dumps(body)) == body
    assert dumps(pickle.loads(pickle.dumps(model))) == dumps(model)


def test_an_edit_to_a_latin1_file_changes_only_what_it_touches() -> None:
    """Edited and prefixed, the bytes stay: MuJoCo compiles the prefixed names with them."""
    model = loads(LATIN1)

    def larger(element: AnyElement, key: str | None, ancestors: object) -> AnyElement:
        return with_attributes(element, {"size": [0.2]}) if key == "body/geom" else element

    edited = map_elements(larger, model)
    assert encoded(dumps(edited)) == LATIN1.replace(b'size="0.1"', b'size="0.2"')
    names = bytes(compiled(prefixed(model, "p_")).names)
    assert b"p_b\xe9\x00" in names and b"p_g\xe9\x00" in names
    built = Body(name="built\udce9", children=[Geom(size=[0.1])])
    world = attrs.evolve(model.worldbody, children=[*model.worldbody.children, built])
    whole = attrs.evolve(
        model, children=[world if c is model.worldbody else c for c in model.children]
    )
    assert b"built\xe9\x00" in bytes(compiled(whole).names)


def test_text_that_cannot_be_written_back_exactly_is_refused() -> None:
    """A lone surrogate no file holds, and a file holding a placeholder the reader uses.

    The first can come only from a program (no bytes read give it); the second
    (Unicode's private use plane, U+10FEE9) would read back as the escape it stands
    for beside a byte that is not UTF-8, so that file is refused as before.
    """
    with pytest.raises(MjcfSyntaxError, match="U\\+D800, a lone surrogate"):
        loads('<mujoco model="\ud800"/>')
    placeholder = chr(0x10FEE9).encode()
    with pytest.raises(MjcfSyntaxError, match="byte 0xE9 is not UTF-8"):
        loads(b'<mujoco model="' + placeholder + b'\xe9"/>')
    assert loads(b'<mujoco model="' + placeholder + b'"/>').model == chr(0x10FEE9)


# -- only MjcfError escapes ------------------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "",
        "<",
        "<mujoco>",
        "<mujoco></robot>",
        "<mujoco><worldbody><geom size='1' size='2'/></worldbody></mujoco>",
        "<mujoco><worldbody><geom size=1/></worldbody></mujoco>",
        "\ufeff<mujoco/>x",
    ],
)
def test_broken_text_raises_only_mjcf_errors(text: str) -> None:
    """Malformed text raises MjcfError subclasses only, from text and from bytes."""
    with pytest.raises(MjcfError):
        loads(text)
    with pytest.raises(MjcfError):
        loads(text.encode("utf-8", "surrogatepass"))


# -- The text reader's fast path for typed elements gives what the general builder gives. ------


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
