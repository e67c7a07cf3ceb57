"""Tests of ``mjcf_model.serializers.scanning``: the reader's byte scans beside expat."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from mjcf_model.serializers.scanning import BREAK, may_hold_text, start_tag_end
from tests.conftest import FIXTURES


@pytest.mark.parametrize(
    "raw",
    [
        b"<geom/>",
        b"<geom size='0.1'/><site/>",
        b'<geom name="a>b" size="1"/>',
        b"<geom name='\"' rgba='>>'>text</geom>",
        b'<geom\n  name="x"\n  size="1"\n/>',
    ],
)
def test_the_start_tag_found_holds_every_attribute_elementtree_reads(raw: bytes) -> None:
    """The offset is just after the ``>`` that ends the tag, whatever the values hold."""
    end = start_tag_end(raw, 0)
    tag = raw[:end]
    assert tag.endswith(b">")
    closed = tag if tag.endswith(b"/>") else tag + b"</geom>"
    assert ET.fromstring(closed).attrib == ET.fromstring(raw.split(b"<site")[0]).attrib


def test_a_later_start_tag_is_found_from_its_own_offset() -> None:
    """Scanning from a later ``<`` ends that tag, not an earlier one."""
    raw = b"<a x='>'><b y=\"'>'\"/></a>"
    begin = raw.index(b"<b")
    assert raw[begin : start_tag_end(raw, begin)] == b"<b y=\"'>'\"/>"


def _holds_text(raw: bytes) -> bool:
    return any((e.text or "").strip() or (e.tail or "").strip() for e in ET.fromstring(raw).iter())


@pytest.mark.parametrize("path", sorted(FIXTURES.glob("*.xml")), ids=lambda p: p.name)
def test_a_file_elementtree_finds_text_in_is_said_to_hold_some(path: Path) -> None:
    """``may_hold_text`` may say yes needlessly, never no when ElementTree finds text."""
    raw = path.read_bytes()
    if _holds_text(raw):
        assert may_hold_text(raw)


def test_text_and_cdata_are_seen_and_bare_markup_is_not() -> None:
    """Character data, a CDATA section or a tail say yes; white space between tags says no."""
    for raw in (b"<a> x </a>", b"<a><![CDATA[ ]]></a>", b"<a><b/>tail</a>", b"<a>\t<b/>\n</a>x"):
        assert may_hold_text(raw) is True, raw
    for raw in (b"<a>\n  <b/>\n</a>", b"<a/>", b"<a>\r\n\t<b c='1'/></a>\n"):
        assert may_hold_text(raw) is False, raw
        assert not _holds_text(raw)
    assert [m.group() for m in BREAK.finditer(b"a\tb\nc\rd e")] == [b"\t", b"\n", b"\r"]
