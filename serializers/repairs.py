r"""Repairs of text MuJoCo's parser (tinyxml2) reads and expat refuses, so both read the same.

tinyxml2 is lenient: it reads text and declarations before the root and ignores
markup after it, reads a stray ``&`` or ``<`` as itself, accepts ``--`` in a
comment and no space between attributes, and keeps tabs and line breaks in
attribute values. The text reader (:mod:`mjcf_model.serializers.parsing`) parses with
expat; when expat refuses the text, it reads it again as repaired here.

>>> escape_stray_markup(b'<mujoco model="a & b"/>')
b'<mujoco model="a &amp; b"/>'
>>> blank_text_before_root(b'junk\n<mujoco/>')
b'\n<mujoco/>'
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any
from xml.parsers import expat

import attrs

from mjcf_model.nodes.base import field_table
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema.namespaces import child_key
from mjcf_model.values.kinds import NOT_XML_CHARACTER

__all__ = [
    "NUMERIC_ATTRIBUTES",
    "blank_text_before_root",
    "character_hint",
    "epilog_end",
    "escape_stray_markup",
    "exact_attributes",
    "not_xml",
]


def epilog_end(raw: bytes, index: int, limit: int) -> int:
    """Where the white space, comments and processing instructions from ``index`` end.

    Nothing past ``limit`` (where expat found an error) is included.
    """
    while True:
        while index < limit and raw[index : index + 1] in (b" ", b"\t", b"\r", b"\n"):
            index += 1
        for opening, closing in ((b"<!--", b"-->"), (b"<?", b"?>")):
            if raw.startswith(opening, index):
                end = raw.find(closing, index + len(opening))
                if end < 0 or end + len(closing) > limit:
                    return index
                index = end + len(closing)
                break
        else:
            return index


#: What to say of a byte that is not UTF-8 the reader could not read: MuJoCo's parser
#: passes such bytes through, and so does the reader (:mod:`mjcf_model.values.encoding`),
#: but for a file that also holds one of the characters standing in for them.
NOT_UTF8_ADVICE = (
    "MuJoCo passes such bytes through, and mjcf-model reads them too, but not in a file "
    "that also holds one of the private-use characters U+10FE80 to U+10FEFF, which stand "
    "in for them while it reads; save the file as UTF-8 "
    "(for a Latin-1 file: iconv -f latin1 -t utf-8)"
)


#: The first bytes of files people give by mistake for a model, and what they are.
_FILE_KINDS = (
    (b"\x89PNG\r\n\x1a\n", "a PNG image"),
    (b"\xff\xd8\xff", "a JPEG image"),
    (b"GIF8", "a GIF image"),
    (b"PK\x03\x04", "a zip archive"),
    (b"%PDF", "a PDF document"),
    (b"\x7fELF", "a program"),
    (b"\x1f\x8b", "a gzip archive"),
)


def not_xml(raw: bytes) -> str | None:
    r"""What ``raw`` is instead of XML, when it plainly is no XML at all; ``None`` otherwise.

    Examples:
        >>> not_xml(b"\x89PNG\r\n\x1a\n..."), not_xml(b"v 0 0 0"), not_xml(b"<mujoco/>")
        ('a PNG image', 'a file without any XML element (it begins with "v 0 0 0")', None)

    """
    for start, kind in _FILE_KINDS:
        if raw.startswith(start):
            return kind
    if b"<" in raw:
        return None
    begins = raw[:40].decode("utf-8", "replace").strip().splitlines()
    shown = f' (it begins with "{begins[0]}")' if begins else " (it is empty)"
    return f"a file without any XML element{shown}"


def character_hint(found: bytes) -> str:
    """What to say about the bytes where expat stopped, when they are the cause."""
    try:
        char = found.decode("utf-8", "strict")[:1]
    except UnicodeDecodeError as error:
        if error.start > 0:
            return ""
        return f"; byte 0x{found[0]:02X} is not UTF-8: {NOT_UTF8_ADVICE}"
    if char and NOT_XML_CHARACTER.match(char):
        return (
            f"; U+{ord(char):04X} is a character XML cannot carry (MuJoCo's own parser"
            " reads it, mjcf-model refuses it: remove it or write it out)"
        )
    return ""


#: The characters that start markup or a reference (single character classes).
_TEXT_MARK = re.compile(b"[<&\\]]")
_TAG_MARK = re.compile(b"[<&\"'>]")
_AFTER_VALUE = (b"", b" ", b"\t", b"\n", b"\r", b"/", b">", b"?")
_VALUE_MARK = re.compile(b"[\t\n\r\"'>]")
_REFERENCES = (b"&amp;", b"&lt;", b"&gt;", b"&quot;", b"&apos;")


def _reference_length(raw: bytes, index: int) -> int | None:
    """The length of the reference the ``&`` at ``index`` starts, as tinyxml2 reads it.

    ``None`` when tinyxml2 reads the ``&`` as itself (no reference, or a code
    point past U+10FFFF); ``0`` for a reference to nothing (``&#;``, ``&#x;``,
    ``&#0;``), at which tinyxml2 ends the value.
    """
    for name in _REFERENCES:
        if raw.startswith(name, index):
            return len(name)
    if not raw.startswith(b"&#", index):
        return None
    hexadecimal = raw.startswith(b"&#x", index)
    digits = b"0123456789abcdefABCDEF" if hexadecimal else b"0123456789"
    start = index + (3 if hexadecimal else 2)
    end = start
    while end < len(raw) and end - start < 10 and raw[end] in digits:
        end += 1
    if raw[end : end + 1] != b";":
        return None
    value = int(raw[start:end], 16 if hexadecimal else 10) if end > start else 0
    if value > 0x10FFFF:
        return None
    return 0 if value == 0 else end + 1 - index


class _NumericAttributesByContext(dict[str | None, "_NumericAttributes"]):
    """Per context, then per tag: the attributes whose fields read numbers.

    In those, any white space separates numbers, so expat's normalisation of
    tabs and line breaks changes nothing.
    """

    def __missing__(self, context: str | None) -> _NumericAttributes:
        found = self[context] = _NumericAttributes(context)
        return found


class _NumericAttributes(dict[str, frozenset[str]]):
    def __init__(self, context: str | None) -> None:
        super().__init__()
        self.context = context

    def __missing__(self, tag: str) -> frozenset[str]:
        cls = CLASS_BY_KEY.get(child_key(self.context, tag) or "")
        names: frozenset[str] = frozenset()
        if cls is not None and cls.tag == tag:
            table = field_table(cls)
            fields = {f.name: f for f in attrs.fields(cls)}
            names = frozenset(
                xml
                for xml, field in table.items()
                if getattr(fields[field].converter, "__name__", "") in _NUMBER_CONVERTERS
            )
        self[tag] = names
        return names


_NUMBER_CONVERTERS = frozenset(
    {"to_float", "to_floats", "to_int", "to_ints", "to_bool"}
    | {f"to_vec{n}" for n in ("2", "3", "4", "6", "1to2", "1to3", "1to5")}
)
NUMERIC_ATTRIBUTES = _NumericAttributesByContext()
#: What a tab or line break inside an attribute value becomes so that expat keeps it;
#: tinyxml2 reads a carriage return (alone or before a line feed) as a line feed.
_KEPT_WHITESPACE = {9: b"&#9;", 10: b"&#10;", 13: b"&#10;"}


def exact_attributes(
    raw: bytes, index: int, attributes: list[tuple[str, str]]
) -> list[tuple[str, str]]:
    """The attributes of the start tag at ``index`` with tabs and line breaks kept.

    Only called for a tag with a text value holding a space; the tag is read
    again with its tabs and line breaks written as references.
    """
    if index < 0 or raw[index : index + 1] != b"<":
        return attributes
    pieces: list[bytes] = []
    start = position = index
    quote = 0
    changed = False
    while True:
        mark = _VALUE_MARK.search(raw, position)
        if mark is None:
            return attributes
        position = mark.start()
        char = raw[position]
        if quote:
            if char == quote:
                quote = 0
            elif char in _KEPT_WHITESPACE:
                size = 2 if raw.startswith(b"\r\n", position) else 1
                pieces += (raw[start:position], _KEPT_WHITESPACE[char])
                start = position + size
                position += size
                changed = True
                continue
        elif char in b"\"'":
            quote = char
        elif char == ord(">"):
            break
        position += 1
    if not changed:
        return attributes
    pieces.append(raw[start:position].rstrip(b"/"))
    pieces.append(b"/>")
    found: list[str] = []
    parser = expat.ParserCreate(encoding="utf-8")
    parser.ordered_attributes = True
    parser.StartElementHandler = lambda _tag, flat: found.extend(flat)
    try:
        parser.Parse(b"".join(pieces), True)
    except expat.ExpatError:
        return attributes
    return list(zip(found[::2], found[1::2], strict=True))


def blank_text_before_root(raw: bytes) -> bytes | None:
    """Blank out text before the root element, which tinyxml2 reads and MuJoCo ignores.

    Processing instructions and the XML declaration before the root go too
    (MuJoCo reads every file as UTF-8, so the declaration says nothing), as do
    ``<!...>`` declarations other than a DTD. Line breaks are kept, so every
    element keeps its line number. ``None`` when there is nothing to blank.
    Linear in the input.
    """
    index = 3 if raw.startswith(b"\xef\xbb\xbf") else 0
    pieces = [raw[:index]]
    changed = False
    while index < len(raw):
        if raw.startswith(b"<", index):
            for opening, closing in ((b"<!--", b"-->"), (b"<?", b"?>")):
                if raw.startswith(opening, index):
                    end = raw.find(closing, index + len(opening))
                    if end < 0:
                        return None
                    end += len(closing)
                    kept = raw[index:end]
                    if opening == b"<?":  # tinyxml2 reads any <?...?>; expat checks them
                        changed = True
                        kept = b"\n" * kept.count(b"\n")
                    pieces.append(kept)
                    index = end
                    break
            else:
                if not raw.startswith(b"<!", index) or raw.startswith(b"<!DOCTYPE", index):
                    break  # the root element (a DTD is refused when parsed)
                end = raw.find(b">", index)  # tinyxml2 skips other <!...> declarations
                if end < 0:
                    return None
                changed = True
                pieces.append(b"\n" * raw.count(b"\n", index, end))
                index = end + 1
            continue
        following = raw.find(b"<", index)
        following = len(raw) if following < 0 else following
        text = raw[index:following]
        if text.strip():
            changed = True
            text = b"\n" * text.count(b"\n")
        pieces.append(text)
        index = following
    if not changed:
        return None
    pieces.append(raw[index:])
    return b"".join(pieces)


def escape_stray_markup(raw: bytes) -> bytes | None:
    """Escape what MuJoCo's parser (tinyxml2) reads and expat refuses, so both read the same.

    tinyxml2 reads an ``&`` that starts no reference, and a ``<`` inside an
    attribute value, as themselves, reads ``&#;`` as nothing and ``]]>`` in text
    as text, accepts ``--`` inside a comment (kept as ``- -``: a comment
    cannot hold ``--``, and MuJoCo ignores comments), skips ``<!...>`` nodes
    other than comments, CDATA and a DTD, and needs no space between attributes. CDATA sections and
    processing instructions are left alone. ``None`` when there is nothing to
    change. Linear in the input.
    """
    out: list[bytes] = []
    start = index = 0
    length = len(raw)

    def replace(at: int, size: int, new: bytes) -> None:
        nonlocal start
        out.extend((raw[start:at], new))
        start = at + size

    def ampersand(at: int, end: int) -> int:
        """Handle the ``&`` at ``at`` in a value or text that ends at ``end``."""
        size = _reference_length(raw, at)
        if size is None:
            replace(at, 1, b"&amp;")
            return at + 1
        if size == 0:  # a reference to nothing: tinyxml2 ends the value here
            replace(at, end - at, b"")
            return end
        return at + size

    while index < length:
        found = _TEXT_MARK.search(raw, index)
        if found is None:
            break
        index = found.start()
        char = raw[index]
        if char == ord("&"):
            text_end = raw.find(b"<", index)
            index = ampersand(index, length if text_end < 0 else text_end)
            continue
        if char == ord("]"):
            if raw.startswith(b"]]>", index):
                replace(index + 2, 1, b"&gt;")
                index += 3
            else:
                index += 1
            continue
        if raw.startswith(b"<!--", index):
            end = raw.find(b"-->", index + 4)
            if end < 0:
                break
            text = raw[index + 4 : end]
            if b"--" in text or text.endswith(b"-"):
                while b"--" in text:
                    text = text.replace(b"--", b"- -")
                replace(index + 4, end - index - 4, text + b" " if text.endswith(b"-") else text)
            index = end + 3
            continue
        for opening, closing in ((b"<![CDATA[", b"]]>"), (b"<?", b"?>")):
            if raw.startswith(opening, index):
                end = raw.find(closing, index + len(opening))
                index = length if end < 0 else end + len(closing)
                break
        else:
            if raw.startswith(b"<!", index) and not raw.startswith(b"<!DOCTYPE", index):
                end = raw.find(b">", index)  # tinyxml2 skips an unknown <!...> node
                if end < 0:
                    break
                replace(index, end + 1 - index, b"\n" * raw.count(b"\n", index, end))
                index = end + 1
                continue
            index = _escape_in_tag(raw, index + 1, replace, ampersand)
    if not out:
        return None
    out.append(raw[start:])
    return b"".join(out)


def _escape_in_tag(
    raw: bytes, index: int, replace: Callable[[int, int, bytes], None], ampersand: Any
) -> int:
    """Escape ``<`` and stray ``&`` inside the attribute values of the tag at ``index``.

    Returns the index after the tag's ``>``.
    """
    quote = 0
    while True:
        mark = _TAG_MARK.search(raw, index)
        if mark is None:
            return len(raw)
        index = mark.start()
        char = raw[index]
        if quote:
            if char == quote:
                quote = 0
                if raw[index + 1 : index + 2] not in _AFTER_VALUE:  # tinyxml2 needs no space
                    replace(index + 1, 0, b" ")
            elif char == ord("<"):
                replace(index, 1, b"&lt;")
            elif char == ord("&"):
                value_end = raw.find(bytes((quote,)), index)
                index = ampersand(index, len(raw) if value_end < 0 else value_end)
                continue
        elif char in b"\"'":
            quote = char
        elif char == ord(">"):
            return index + 1
        index += 1
