r"""Byte-level scans the text reader makes beside expat.

Where a start tag ends (expat reports where it begins), and whether a file
holds any character data other than white space. Every pattern is a single
character class (``tests/mjcf_model/values/test_reading.py``): scans stay linear on any text.

>>> start_tag_end(b"<a b='>'/><c/>", 0), may_hold_text(b"<a>\n  <b/>\n</a>")
(10, False)
"""

from __future__ import annotations

import re

__all__ = ["BREAK", "may_hold_text", "start_tag_end"]

#: A tab or line break, inside a start tag.
BREAK = re.compile(b"[\t\n\r]")
#: What ends a start tag, or opens a value that may hold a ``>``.
_TAG_END_MARK = re.compile(b"[\"'>]")


def start_tag_end(raw: bytes, begin: int) -> int:
    """The offset after the ``>`` that ends the start tag at ``begin`` in ``raw``."""
    while True:
        mark = _TAG_END_MARK.search(raw, begin)
        assert mark is not None, "a start tag the reader read ends"
        position = mark.start()
        if raw[position] == ord(">"):
            return position + 1
        begin = raw.index(raw[position : position + 1], position + 1) + 1


def may_hold_text(raw: bytes) -> bool:
    r"""Whether the text may hold character data other than white space.

    Such data can only follow the ``>`` that ends markup, or sit in a CDATA
    section: with the white space taken out, every ``>`` of a file without it is
    followed by ``<`` or ends the file. A ``>`` inside a value says "may": harmless.

    Examples:
        >>> may_hold_text(b"<a>\n  <b/>\n</a>"), may_hold_text(b"<a> x </a>")
        (False, True)

    """
    if b"<![CDATA[" in raw:
        return True
    squeezed = raw.translate(None, b" \t\r\n")
    closing = squeezed.count(b">")
    return closing != squeezed.count(b"><") + squeezed.endswith(b">")
