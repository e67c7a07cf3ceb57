"""Reading MJCF: text and files into nodes, and ElementTree into nodes.

The text reader drives expat directly and builds nodes as elements close, so
it knows the line of every element for error messages, keeps comments, and
never sees a DTD or an entity: both are refused.

>>> model = loads('<mujoco model="m"><worldbody><geom size="0.1"/></worldbody></mujoco>')
>>> model.model, model.worldbody.geoms[0].size
('m', (0.1,))
"""

from __future__ import annotations

import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path
from typing import IO, Any, NoReturn
from xml.parsers import expat

import attrs

from mjcf_model.base import AnyElement, Comment, GenericElement, Node, TypedElement, field_table
from mjcf_model.errors import (
    MjcfError,
    MjcfIncludeError,
    MjcfSecurityError,
    MjcfSyntaxError,
)
from mjcf_model.layout import DocumentText, Layout
from mjcf_model.namespaces import child_key, children_context, guess_context
from mjcf_model.node_building import build_node
from mjcf_model.nodes.root import Include, Mujoco
from mjcf_model.provenance import FILE_TAGS, with_included_paths
from mjcf_model.registry import CLASS_BY_KEY
from mjcf_model.traversal import map_tree, with_children
from mjcf_model.values import NOT_XML_CHARACTER
from serializers.building import build_element, element_step, element_text

__all__ = ["from_etree", "load", "loads"]

_STRING = "<string>"


class _Open:
    """An element whose start tag was read and whose end tag was not yet."""

    __slots__ = (
        "attributes",
        "children",
        "comments",
        "context",
        "counts",
        "cursor",
        "gap",
        "gaps",
        "index",
        "key",
        "line",
        "names",
        "sources",
        "start",
        "tag",
        "text",
    )

    def __init__(
        self,
        tag: str,
        attributes: list[tuple[str, str]],
        names: tuple[str, ...],
        key: str | None,
        context: str | None,
        line: int,
        index: int,
        start: str,
        cursor: int,
        gap: str,
    ) -> None:
        self.tag = tag
        self.attributes = attributes
        #: The attribute names in source order.
        self.names = names
        self.key = key
        self.context = context
        self.line = line
        #: 1-based position among the parent's children with the same tag.
        self.index = index
        #: The start tag's source text.
        self.start = start
        #: The byte offset where the text not yet given to a gap or a child begins.
        self.cursor = cursor
        #: The source text between the previous sibling (or the parent's start tag) and this.
        self.gap = gap
        #: The character data read, or ``None`` before any.
        self.text: list[str] | None = None
        #: What the children need, made at the first child (most elements have none):
        #: the children, the count of each tag among them, the source text before each
        #: child, and each child's layout or the comment node (:attr:`Layout.sources`).
        self.children: list[Node] = _NO_CHILDREN
        self.counts: dict[str, int] | None = None
        self.gaps: list[str] = _NO_CHILDREN
        self.sources: list[Any] = _NO_CHILDREN
        #: The exact text of comment children that ``<!--text-->`` would not give back.
        self.comments: dict[int, str] | None = None

    def add_child(self, gap: str, child: Node, source: Any) -> None:
        """Note a child and the source text before it."""
        if self.counts is None:
            self.counts = {}
            self.children, self.gaps, self.sources = [], [], []
        self.gaps.append(gap)
        self.children.append(child)
        self.sources.append(source)


#: What an element without children holds as its children (never appended to).
_NO_CHILDREN: list[Any] = []


@attrs.define
class _Session:
    """What one ``load`` call shares across the files it reads."""

    inline_includes: bool
    main_dir: Path | None
    include_chain: tuple[Path, ...] = ()


@attrs.define
class _PendingInclude:
    """An ``<include>`` met while reading a file, to be replaced by its file's elements."""

    node: Include
    #: The file the ``<include>`` stands in, and where, for errors.
    filename: str
    line: int
    path: str
    #: The schema context of the including element: the included elements are read in it.
    context: str


class _Reader:
    """Builds nodes from expat events for one document."""

    def __init__(self, filename: str, session: _Session, include_context: str | None) -> None:
        self.filename = filename
        self.session = session
        #: For an included file, the context its root's children are read in.
        self.include_context = include_context
        self.stack: list[_Open] = []
        self.top: list[Node] = []  # comments around the root, and the root itself
        #: The ``<include>`` elements read, when includes are inlined.
        self.includes: list[_PendingInclude] = []
        #: The bytes being parsed, and the same as text when they are ASCII (byte offsets
        #: are then text offsets), else ``None``.
        self.raw = b""
        self.ascii: str | None = None
        #: Each attribute text's converted value, per field converter: converted once.
        self.memo: dict[tuple[Any, str], Any] = {}
        #: Where the root's start tag begins and its end tag ends, and where reading stopped.
        self.root_begin = self.root_end = 0
        #: The element being closed, for :meth:`locate`.
        self.closing: _Open | None = None
        # MuJoCo reads the bytes as UTF-8 whatever the XML declaration says; so do we.
        self.parser = expat.ParserCreate(encoding="utf-8")
        self.parser.ordered_attributes = True
        self.parser.buffer_text = True
        self.parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
        self.parser.StartElementHandler = self.start
        self.parser.EndElementHandler = self.end
        self.parser.CommentHandler = self.comment
        self.parser.CharacterDataHandler = self.characters
        self.parser.StartDoctypeDeclHandler = self.refuse_doctype
        self.parser.EntityDeclHandler = self.refuse_entity
        self.parser.ExternalEntityRefHandler = self.refuse_external

    # -- security -----------------------------------------------------------------

    def refuse_doctype(self, name: str, *_args: Any) -> NoReturn:
        raise MjcfSecurityError(
            f"DTD <!DOCTYPE {name}> refused: MJCF needs no DTD and entities are never"
            " expanded (MuJoCo ignores a DTD: remove it)",
            file=self.filename,
            line=self.parser.CurrentLineNumber,
        )

    def refuse_entity(self, name: str, *_args: Any) -> NoReturn:
        raise MjcfSecurityError(
            f"entity declaration {name!r} refused: entities are never expanded",
            file=self.filename,
            line=self.parser.CurrentLineNumber,
        )

    def refuse_external(self, *_args: Any) -> NoReturn:
        raise MjcfSecurityError(
            "external entity reference refused: nothing is fetched",
            file=self.filename,
            line=self.parser.CurrentLineNumber,
        )

    def path_to(self, item: _Open | None) -> str:
        """The element path of ``item`` (or of the innermost open element), for errors.

        Built only when an error is raised: ``item`` has been closed, so the open
        elements on the stack are its ancestors.
        """
        chain = self.stack if item is None else [*self.stack, item]
        return "".join(f"/{element_step(o.tag, o.attributes, o.index)}" for o in chain)

    # -- events -------------------------------------------------------------------

    def source(self, begin: int, end: int) -> str:
        """The source text between two byte offsets."""
        if self.ascii is not None:
            return self.ascii[begin:end]
        return self.raw[begin:end].decode("utf-8", "surrogatepass")

    def start(self, tag: str, flat: list[str]) -> None:
        raw = self.raw
        begin = self.parser.CurrentByteIndex
        stop = raw.find(b">", begin) + 1  # the tag's end, unless a value holds a ">"
        stack = self.stack
        context = stack[-1].context if stack else None
        names = flat[::2]
        attributes = list(zip(names, flat[1::2], strict=True))
        numeric = None
        for name, value in attributes:
            if ">" in value:
                stop = _start_tag_end(raw, begin)
            # expat turns a tab or line break in a value into a space; tinyxml2 keeps
            # it. Only text fields care, and only values with a space can be affected.
            if " " in value:
                if numeric is None:
                    numeric = _NUMERIC_ATTRIBUTES[context][tag]
                if name not in numeric:
                    attributes = _exact_attributes(raw, begin, attributes)
                    stop = _start_tag_end(raw, begin)
                    break
        text = self.ascii
        if stack:
            parent = stack[-1]
            counts = parent.counts
            index = 1 if counts is None else counts.get(tag, 0) + 1
            cursor = parent.cursor
            gap = text[cursor:begin] if text is not None else self.source(cursor, begin)
        else:
            index, gap = 1, ""
            self.root_begin = begin
        key = child_key(context, tag)
        inner = children_context(key, context)
        if not stack and self.include_context is not None:
            inner = self.include_context  # MuJoCo takes the root's children, whatever its tag
        stack.append(
            _Open(
                tag,
                attributes,
                tuple(names),
                key,
                inner,
                self.parser.CurrentLineNumber,
                index,
                text[begin:stop] if text is not None else self.source(begin, stop),
                stop,
                gap,
            )
        )

    def locate(self, error: MjcfError) -> MjcfError:
        """``error`` with the file, line and path of the element being closed."""
        item = self.closing
        assert item is not None
        return error.located(file=self.filename, line=item.line, path=self.path_to(item))

    def end(self, _tag: str) -> None:
        item = self.stack.pop()
        text = element_text(item.text, bool(item.children)) if item.text else None
        if item.start.endswith("/>"):
            layout = Layout(item.tag, item.start, _NO_GAPS, "", item.names, (), (), text, None)
            after = item.cursor
        else:
            begin = self.parser.CurrentByteIndex
            after = self.raw.index(b">", begin) + 1
            source = self.ascii
            if source is not None:
                last = source[item.cursor : begin]
                end_tag = source[begin:after]
            else:
                last = self.source(item.cursor, begin)
                end_tag = self.source(begin, after)
            layout = Layout(
                item.tag,
                item.start,
                (*item.gaps, last),
                end_tag,
                item.names,
                (),
                tuple(item.sources),
                text,
                item.comments,
            )
        self.closing = item
        try:
            node = build_element(
                item.key,
                item.tag,
                item.attributes,
                item.children,
                text,
                self.locate,
                layout,
                self.memo,
            )
        except MjcfError as error:
            raise self.locate(error) from None
        if self.stack:
            parent = self.stack[-1]
            parent.add_child(item.gap, node, layout)
            if parent.counts is not None:
                parent.counts[item.tag] = item.index
            parent.cursor = after
        else:
            self.top.append(node)
            self.root_end = after
        if self.session.inline_includes and isinstance(node, Include):
            if not node.file:
                raise MjcfIncludeError(
                    "<include> needs a 'file' attribute",
                    file=self.filename,
                    line=item.line,
                    path=self.path_to(item),
                )
            context = self.stack[-1].context if self.stack else None
            self.includes.append(
                _PendingInclude(
                    node, self.filename, item.line, self.path_to(item), context or "mujoco"
                )
            )

    def comment(self, text: str) -> None:
        node = Comment(text=text)
        if not self.stack:
            self.top.append(node)  # its text is kept in the root's document text
            return
        parent = self.stack[-1]
        begin = self.parser.CurrentByteIndex
        after = self.raw.index(b"-->", begin + 4) + 3
        if b"\r" in self.raw[begin:after]:  # expat gives the text with line feeds only
            if parent.comments is None:
                parent.comments = {}
            parent.comments[len(parent.children)] = self.source(begin, after)
        parent.add_child(self.source(parent.cursor, begin), node, node)
        parent.cursor = after

    def characters(self, data: str) -> None:
        if self.stack:
            item = self.stack[-1]
            if item.text is None:
                item.text = [data]
            else:
                item.text.append(data)

    # -- driver -------------------------------------------------------------------

    def parse(self, data: str | bytes) -> list[Node]:
        """Read one document; text MuJoCo's lenient parser reads is repaired first."""
        raw = data.encode("utf-8", "surrogatepass") if isinstance(data, str) else data
        if raw.startswith((b"\xff\xfe", b"\xfe\xff")):
            # expat follows a UTF-16 byte order mark; read as UTF-8, offsets are text offsets
            try:
                raw = raw.decode("utf-16").encode("utf-8", "surrogatepass")
            except UnicodeDecodeError as error:
                raise MjcfSyntaxError(
                    f"malformed UTF-16 after a byte order mark: {error.reason}; save the file"
                    " as UTF-8, which MuJoCo reads",
                    file=self.filename,
                ) from None
        try:
            self.raw = raw
            if raw.isascii():
                self.ascii = raw.decode("ascii")
            self.parser.Parse(raw, True)
            self.record_document(len(raw))
        except expat.ExpatError as error:
            if self.completed_root(raw):
                # MuJoCo reads the first root element and ignores what follows
                self.record_document(_epilog_end(raw, self.root_end, self.parser.ErrorByteIndex))
                return self.top
            blanked = _blank_text_before_root(raw)
            repaired = _escape_stray_markup(blanked or raw) or blanked
            if repaired is not None:
                retry = _Reader(self.filename, self.session, self.include_context)
                try:
                    top = retry.parse(repaired)
                except MjcfSyntaxError:
                    pass
                else:
                    self.includes = retry.includes
                    return top
            raise self.syntax_error(error, raw) from None
        finally:
            self.release()
        return self.top

    def release(self) -> None:
        """Let go of the parser and the text: the parser holds this reader's handlers.

        Without this, each reader would be a reference cycle that keeps the file's
        text alive until the cyclic garbage collector runs.
        """
        parser = self.parser
        parser.StartElementHandler = parser.EndElementHandler = None
        parser.CommentHandler = parser.CharacterDataHandler = None
        parser.StartDoctypeDeclHandler = parser.EntityDeclHandler = None
        parser.ExternalEntityRefHandler = None
        self.raw, self.ascii, self.closing = b"", None, None

    def record_document(self, stop: int) -> None:
        """Give the root's layout the text around the root, up to byte ``stop``."""
        comments = [n for n in self.top if isinstance(n, Comment)]
        root = next((n for n in self.top if not isinstance(n, Comment)), None)
        if not isinstance(root, (TypedElement, GenericElement)) or root.layout is None:
            return
        count = self.top.index(root)
        root.layout.document = DocumentText(
            self.source(0, self.root_begin),
            self.source(self.root_end, stop),
            tuple(comments[:count]),
            tuple(comments[count:]),
        )

    def completed_root(self, raw: bytes) -> bool:
        """Whether expat stopped at markup after a complete root, which MuJoCo ignores."""
        if self.stack or not any(not isinstance(n, Comment) for n in self.top):
            return False
        index = self.parser.ErrorByteIndex  # at the "<" or just after it
        start = index if raw[index : index + 1] == b"<" else index - 1
        return raw[start : start + 1] == b"<" and start + 1 < len(raw)

    def syntax_error(self, error: expat.ExpatError, raw: bytes) -> MjcfSyntaxError:
        path = self.path_to(None) if self.stack else None
        message = expat.errors.messages[error.code] if error.code else str(error)
        detail = f"malformed XML: {message} (column {error.offset + 1})"
        index = self.parser.ErrorByteIndex
        if index >= 0:
            detail += _character_hint(raw[index : index + 4])
        return MjcfSyntaxError(detail, file=self.filename, line=error.lineno, path=path)


def _start_tag_end(raw: bytes, index: int) -> int:
    """The offset after the ``>`` that ends the start tag at ``index`` (expat read it whole)."""
    while True:
        mark = _TAG_END_MARK.search(raw, index)
        assert mark is not None
        position = mark.start()
        if raw[position] == ord(">"):
            return position + 1
        index = raw.index(raw[position : position + 1], position + 1) + 1


def _epilog_end(raw: bytes, index: int, limit: int) -> int:
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


def _character_hint(found: bytes) -> str:
    """What to say about the bytes where expat stopped, when they are the cause."""
    try:
        char = found.decode("utf-8", "strict")[:1]
    except UnicodeDecodeError as error:
        if error.start > 0:
            return ""
        return (
            f"; byte 0x{found[0]:02X} is not UTF-8: MuJoCo reads every file as UTF-8,"
            " whatever its declaration says; save the file as UTF-8"
        )
    if char and NOT_XML_CHARACTER.match(char):
        return (
            f"; U+{ord(char):04X} is a character XML cannot carry (MuJoCo's own parser"
            " reads it, mjcf-model refuses it: remove it or write it out)"
        )
    return ""


#: The gaps of an element with nothing inside (shared: most elements).
_NO_GAPS = ("",)
#: What ends a start tag, or opens a value that may hold a ``>``.
_TAG_END_MARK = re.compile(b"[\"'>]")
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
_NUMERIC_ATTRIBUTES = _NumericAttributesByContext()
#: What a tab or line break inside an attribute value becomes so that expat keeps it;
#: tinyxml2 reads a carriage return (alone or before a line feed) as a line feed.
_KEPT_WHITESPACE = {9: b"&#9;", 10: b"&#10;", 13: b"&#10;"}


def _exact_attributes(
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


def _blank_text_before_root(raw: bytes) -> bytes | None:
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


def _escape_stray_markup(raw: bytes) -> bytes | None:
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


@attrs.define
class _Document:
    """One file being read, and the ``<include>`` elements in it not yet replaced."""

    root: Mujoco | AnyElement
    includes: list[_PendingInclude]
    filename: str
    #: The included elements found so far, by the ``<include>`` node they replace.
    found: dict[int, tuple[Node, ...]] = attrs.field(factory=dict)


def _parse(
    data: str | bytes, filename: str, session: _Session, include_context: str | None = None
) -> _Document:
    """Parse one document; the main file's root must be ``<mujoco>``.

    Comments before and after the root become its first and last children. An
    included file's root children are read in ``include_context``, the context of
    the element that includes it; MuJoCo takes them whatever the root's tag is.
    """
    reader = _Reader(filename, session, include_context)
    top = reader.parse(data)
    roots = [n for n in top if not isinstance(n, Comment)]
    root = roots[0] if roots else None
    if root is None or (include_context is None and not isinstance(root, Mujoco)):
        found = root.tag if isinstance(root, (TypedElement, GenericElement)) else "nothing"
        raise MjcfSyntaxError(f"expected a <mujoco> root element, found <{found}>", file=filename)
    assert isinstance(root, (TypedElement, GenericElement))
    index = top.index(root)
    before = top[:index]
    after = [n for n in top[index + 1 :] if isinstance(n, Comment)]
    if before or after:
        root = with_children(root, [*before, *root.children, *after])
    return _Document(root, reader.includes, filename)


def _read(data: str | bytes, filename: str, session: _Session) -> Mujoco:
    """Read the main document, and with ``inline_includes`` every file it includes.

    Included files are read one after another from an explicit stack, not by
    recursion, so an include chain as long as MuJoCo follows (it has no limit)
    is read too.
    """
    stack = [_parse(data, filename, session)]
    reading = {path: 0 for path in session.include_chain}
    origins: dict[int, tuple[AnyElement, Path]] = {}
    while True:
        document = stack[-1]
        if len(document.found) < len(document.includes):
            pending = document.includes[len(document.found)]
            path = _resolve_include(pending, session)
            if path in reading:
                chain = [*session.include_chain, *(Path(d.filename) for d in stack[1:]), path]
                cycle = " -> ".join(str(p) for p in chain[chain.index(path) :])
                raise MjcfIncludeError(
                    f"include cycle: {cycle}",
                    file=pending.filename,
                    line=pending.line,
                    path=pending.path,
                )
            try:
                data = path.read_bytes()
            except OSError as error:
                raise _include_error(
                    pending, f"cannot read included file {str(path)!r}", error
                ) from None
            reading[path] = len(stack)
            stack.append(_parse(data, str(path), session, pending.context))
            continue
        stack.pop()
        root = _splice(document)
        if not stack:
            assert isinstance(root, Mujoco)
            if session.main_dir is None:
                return root
            root = build_node(Mujoco, {"base_dir": session.main_dir}, root)
            return with_included_paths(root, origins)
        reading.pop(Path(document.filename), None)
        parent = stack[-1]
        parent.found[id(parent.includes[len(parent.found)].node)] = root.children
        _record_origins(root.children, Path(document.filename).parent, origins)


def _record_origins(
    nodes: tuple[Node, ...], folder: Path, origins: dict[int, tuple[AnyElement, Path]]
) -> None:
    """Note ``folder`` as the origin of each element in ``nodes`` that may name a file.

    Elements of a file included deeper keep the folder noted first, their own:
    MuJoCo looks beside the innermost included file.
    """
    stack = list(nodes)
    while stack:
        node = stack.pop()
        if isinstance(node, (TypedElement, GenericElement)):
            if node.tag in FILE_TAGS and id(node) not in origins:
                origins[id(node)] = (node, folder)
            stack.extend(node.children)


def _splice(document: _Document) -> Mujoco | AnyElement:
    """The document's root with each ``<include>`` replaced by the elements it stands for."""
    if not document.found:
        return document.root
    found = document.found

    def expand(node: Node) -> Node:
        if isinstance(node, (TypedElement, GenericElement)) and any(
            id(c) in found for c in node.children
        ):
            children: list[Node] = []
            for child in node.children:
                children.extend(found.get(id(child), (child,)))
            return with_children(node, children)
        return node

    return map_tree(expand, document.root)  # type: ignore[return-value]


def _include_error(pending: _PendingInclude, what: str, error: OSError) -> MjcfIncludeError:
    return MjcfIncludeError(
        f"{what}: {error.strerror or error}",
        file=pending.filename,
        line=pending.line,
        path=pending.path,
    )


def _resolve_include(pending: _PendingInclude, session: _Session) -> Path:
    """Find an included file as MuJoCo does.

    MuJoCo looks beside the main model first, then beside the including file.
    """
    file = pending.node.file
    assert file
    candidates: list[Path] = []
    if session.main_dir is not None:
        candidates.append(session.main_dir / file)
    if pending.filename != _STRING:
        here = Path(pending.filename).parent / file
        if here not in candidates:
            candidates.append(here)
    for candidate in candidates:
        try:
            if candidate.is_file():
                return candidate.resolve()
        except OSError as error:  # a name too long, a loop of links
            raise _include_error(
                pending, f"cannot look for included file {file!r}", error
            ) from None
    looked = ", ".join(repr(str(c)) for c in candidates) or "nowhere (no base directory)"
    raise MjcfIncludeError(
        f"included file {file!r} not found; looked in {looked}",
        file=pending.filename,
        line=pending.line,
        path=pending.path,
    )


def loads(
    text: str | bytes,
    *,
    inline_includes: bool = False,
    base_dir: str | os.PathLike[str] | None = None,
    filename: str | None = None,
    inline_attachments: bool = False,
) -> Mujoco:
    """Read an MJCF model from text.

    Args:
        text: The XML.
        inline_includes: Replace each ``<include>`` by the elements of the file it
            names (found relative to ``base_dir``). By default includes are kept as
            :class:`~mjcf_model.Include` nodes and written back as includes.
        base_dir: Where included files are looked for; the main model's directory.
        filename: The name errors should report (default ``"<string>"``).
        inline_attachments: Replace each ``<attach>`` by what MuJoCo attaches there
            (see :func:`mjcf_model.attachments.inlined_attachments`).

    Raises:
        MjcfSyntaxError: The text is not well-formed XML or its root is not ``<mujoco>``.
        MjcfValueError: An attribute value has the wrong form.
        MjcfIncludeError: An included file is missing or files include each other.
        MjcfSecurityError: The text declares a DTD or entities.

    Example:
        >>> loads("<mujoco><!-- hi --></mujoco>").children
        (Comment(text=' hi '),)

    """
    session = _Session(
        inline_includes=inline_includes, main_dir=Path(base_dir) if base_dir is not None else None
    )
    return _attachments_inlined(_read(text, filename or _STRING, session), inline_attachments)


def _attachments_inlined(model: Mujoco, inline: bool) -> Mujoco:
    if not inline:
        return model
    from mjcf_model.attachments import inlined_attachments

    return inlined_attachments(model)


def load(
    source: str | os.PathLike[str] | IO[bytes] | IO[str],
    *,
    inline_includes: bool = False,
    inline_attachments: bool = False,
) -> Mujoco:
    """Read an MJCF model from a file path or an open file.

    Args:
        source: A path, or a file object opened for reading.
        inline_includes: Replace each ``<include>`` by the elements of the file it
            names, looked up beside the main file first and then beside the
            including file, as MuJoCo does. Include cycles raise.
        inline_attachments: Replace each ``<attach>`` by what MuJoCo attaches there
            (see :func:`mjcf_model.attachments.inlined_attachments`).

    Example:
        >>> import tempfile, pathlib
        >>> path = pathlib.Path(tempfile.mkdtemp()) / "m.xml"
        >>> _ = path.write_text('<mujoco model="m"/>')
        >>> load(path).model
        'm'

    """
    if isinstance(source, (str, os.PathLike)):
        path = Path(source)
        try:
            data = path.read_bytes()
        except OSError as error:
            raise MjcfIncludeError(f"cannot read {str(path)!r}: {error.strerror}") from None
        session = _Session(
            inline_includes=inline_includes,
            # the folder MuJoCo resolves from: the link's own, when the path is a link
            main_dir=Path(os.path.abspath(path)).parent,
            include_chain=(path.resolve(),),
        )
        return _attachments_inlined(_read(data, str(path), session), inline_attachments)
    name = getattr(source, "name", None)
    filename = name if isinstance(name, str) else _STRING
    base = Path(filename).parent if filename != _STRING else None
    return loads(
        source.read(),
        inline_includes=inline_includes,
        base_dir=base,
        filename=filename,
        inline_attachments=inline_attachments,
    )


def from_etree(element: ET.Element, *, context: str | None = None, typed: bool = True) -> Node:
    """Convert an ElementTree element (and its subtree) to nodes.

    Args:
        element: The element; ``<mujoco>`` gives a :class:`~mjcf_model.Mujoco`, any
            other element the node of that element.
        context: The schema key of the element's parent (``"body"``, ``"asset"``, ...).
            By default it is guessed from the tag, which is right except for tags
            that mean different things in different sections (``<joint>`` inside
            ``<equality>``): pass the context for those.
        typed: With ``False`` every element becomes a
            :class:`~mjcf_model.GenericElement` holding its attribute text exactly
            as given, so text MuJoCo would reject (``group="1.0"``) still converts.

    Example:
        >>> import xml.etree.ElementTree as ET
        >>> from_etree(ET.fromstring('<geom size="0.1"/>')).size
        (0.1,)
        >>> from_etree(ET.fromstring('<geom group="1.0"/>'), typed=False).attributes["group"]
        '1.0'

    """
    if element.tag is ET.Comment:  # type: ignore[comparison-overlap]
        return Comment(text=element.text or "")
    if context is None:
        context = guess_context(element.tag)
    return _from_etree(element, context, typed)


@attrs.define
class _EtreeFrame:
    """An ElementTree element being converted: its children are converted first."""

    element: ET.Element
    key: str | None
    #: The schema context of the element's children.
    inner: str | None
    #: This element's step in the element path, for errors.
    step: str
    pending: Any
    children: list[Node] = attrs.field(factory=list)
    chunks: list[str | None] = attrs.field(factory=list)
    counts: dict[str, int] = attrs.field(factory=dict)


def _from_etree(root: ET.Element, context: str | None, typed: bool) -> AnyElement:
    """Convert ``root`` and its subtree with an explicit stack, so any depth is converted."""

    def frame(element: ET.Element, context: str | None, index: int) -> _EtreeFrame:
        key = child_key(context, element.tag)
        step = element_step(element.tag, list(element.attrib.items()), index)
        return _EtreeFrame(
            element, key, children_context(key, context), step, iter(element), [], [element.text]
        )

    def path() -> str:
        return "".join(f"/{f.step}" for f in stack)

    stack = [frame(root, context, 1)]
    while True:
        top = stack[-1]
        for child in top.pending:
            if child.tag is ET.Comment:
                top.children.append(Comment(text=child.text or ""))
                top.chunks.append(child.tail)
            elif isinstance(child, ET.Element) and isinstance(child.tag, str):
                index = top.counts[child.tag] = top.counts.get(child.tag, 0) + 1
                stack.append(frame(child, top.inner, index))
                break
            else:
                top.chunks.append(child.tail)
        else:
            element = top.element
            try:
                node = build_element(
                    top.key if typed else None,
                    element.tag,
                    list(element.attrib.items()),
                    top.children,
                    element_text(top.chunks, bool(top.children)),
                    lambda error: error.located(path=path()),
                )
            except MjcfError as error:
                raise error.located(path=path()) from None
            stack.pop()
            if not stack:
                return node
            stack[-1].children.append(node)
            stack[-1].chunks.append(element.tail)
