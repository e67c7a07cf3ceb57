"""Tests of ``mjcf_model.serializers.parsing``."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import mujoco
import pytest

from mjcf_model import (
    MjcfError,
    MjcfSyntaxError,
)
from mjcf_model.serializers import dumps, from_etree, load, loads
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


def test_bytes_that_are_not_utf8_are_a_syntax_error() -> None:
    """A Latin-1 file is refused with the reason; MuJoCo's Python binding fails on it too."""
    with pytest.raises(MjcfSyntaxError, match="byte 0xE9 is not UTF-8") as caught:
        loads(b'<mujoco model="\xe9"/>')
    assert caught.value.line == 1


def test_a_latin1_comment_is_refused_naming_byte_line_and_column(tmp_path: Path) -> None:
    """MuJoCo compiles a file with a Latin-1 comment; mjcf-model refuses it, saying exactly where.

    The decision (documented in the README): a node holds text as Unicode, so
    the byte could not be written back as it was; the error names the byte, file,
    line and column, and says how to convert the file.
    """
    path = tmp_path / "old.xml"
    path.write_bytes(
        b'<mujoco>\n  <!-- caf\xe9 -->\n  <worldbody><geom size="1"/></worldbody>\n</mujoco>\n'
    )
    assert mujoco.MjModel.from_xml_path(str(path)).ngeom == 1  # MuJoCo reads it
    with pytest.raises(MjcfSyntaxError) as caught:
        load(path)
    error = caught.value
    assert (error.file, error.line) == (str(path), 2)
    assert "(column 11)" in str(error) and "byte 0xE9 is not UTF-8" in str(error)
    assert "iconv -f latin1 -t utf-8" in str(error)


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
