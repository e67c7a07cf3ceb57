"""The text reader: expat events straight into nodes, for one document.

:class:`Reader` drives expat directly and builds nodes as elements close, so it
knows the line of every element for error messages, keeps comments, and never
sees a DTD or an entity: both are refused. Text that MuJoCo's parser reads and
expat refuses is repaired (:mod:`mjcf_model.serializers.repairs`) and read again.

>>> from mjcf_model.serializers.includes import Session
>>> top = Reader("<string>", Session(inline_includes=False, main_dir=None), None).parse(
...     "<!-- a --><mujoco/>"
... )
>>> [type(node).__name__ for node in top]
['Comment', 'Mujoco']
"""

from __future__ import annotations

from typing import Any, NoReturn
from xml.parsers import expat

from mjcf_model.errors import (
    MjcfError,
    MjcfIncludeError,
    MjcfSecurityError,
    MjcfSyntaxError,
    MjcfValueError,
)
from mjcf_model.nodes.base import AnyElement, Comment, Element, Node, TypedElement
from mjcf_model.nodes.root import Include
from mjcf_model.serializers.includes import PendingInclude, Session
from mjcf_model.serializers.layout import (
    DocumentText,
    Layout,
    SourceText,
    layout_of,
    new_layout,
)
from mjcf_model.serializers.open_element import STEPS, OpenElement, step_of
from mjcf_model.serializers.parsed_elements import (
    Deferred,
    ReadMemo,
    build_element,
    element_step,
    element_text,
    read_typed,
    reduced_from_text,
)
from mjcf_model.serializers.repairs import (
    NUMERIC_ATTRIBUTES,
    blank_text_before_root,
    character_hint,
    epilog_end,
    escape_stray_markup,
    exact_attributes,
    not_xml,
)
from mjcf_model.serializers.scanning import BREAK, may_hold_text, start_tag_end
from mjcf_model.tree.indexes import NotedOrder, TagIndex
from mjcf_model.values import Unparsed
from mjcf_model.values.encoding import encoded, with_placeholders, without_placeholders

__all__ = ["Reader"]


#: The first two bytes by which expat recognises UTF-16, and the codec that reads it.
#: The byte order marks of UTF-32, which neither MuJoCo nor expat reads.
_UTF32_BOMS = frozenset({b"\xff\xfe\x00\x00", b"\x00\x00\xfe\xff"})
_UTF16_STARTS = {
    b"\xff\xfe": "utf-16",
    b"\xfe\xff": "utf-16",
    b"<\x00": "utf-16-le",
    b"\x00<": "utf-16-be",
}


class Reader:
    """Builds nodes from expat events for one document."""

    def __init__(self, filename: str, session: Session, include_context: str | None) -> None:
        self.filename = filename
        self.session = session
        self.inline_includes = session.inline_includes
        #: For an included file, the context its root's children are read in.
        self.include_context = include_context
        self.stack: list[OpenElement] = []
        self.top: list[Node] = []  # comments around the root, and the root itself
        #: The ``<include>`` elements read, when includes are inlined.
        self.includes: list[PendingInclude] = []
        #: The bytes being parsed, and the same as text when they are ASCII (byte offsets
        #: are then text offsets), else ``None``.
        self.raw = b""
        self.ascii: str | None = None
        #: Whether the bytes held bytes that are not UTF-8, given to expat as placeholders
        #: (:mod:`mjcf_model.values.encoding`): what expat reports is escaped again.
        self.escaped = False
        #: The same, shared by the layouts of the elements read.
        self.origin: SourceText | None = None
        #: Each attribute text's converted value, per field converter: converted once.
        self.memo: dict[tuple[Any, str], Any] = {}
        #: Per typed class, each ``(name, text)`` attribute read, as its field and value.
        self.known: ReadMemo = {}
        #: Whether the text holds a tab or line break anywhere (a start tag may hold one).
        self.breaks = True
        #: Each tuple of attribute names read, once (elements share them).
        self.names: dict[tuple[str, ...], tuple[str, ...]] = {}
        #: Where the root's start tag begins and its end tag ends, and where reading stopped.
        self.root_begin = self.root_end = 0
        #: The element being closed, for :meth:`locate`.
        self.closing: OpenElement | None = None
        #: Every element below the root in document order (each has its place from its
        #: start tag on, and is put there at its end tag): the lookup index of the tree read.
        self.noted = NotedOrder()
        #: Each long attribute left to convert after parsing: its node, and where it
        #: stands, with what :func:`~mjcf_model.serializers.parsed_elements.read_typed` deferred.
        self.deferred: list[tuple[TypedElement, int, str, Deferred]] = []
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
        """Refuse a DTD (expat's handler)."""
        raise MjcfSecurityError(
            f"DTD <!DOCTYPE {name}> refused: MJCF needs no DTD and entities are never"
            " expanded (MuJoCo ignores a DTD: remove it)",
            file=self.filename,
            line=self.parser.CurrentLineNumber,
        )

    def refuse_entity(self, name: str, *_args: Any) -> NoReturn:
        """Refuse an entity declaration (expat's handler)."""
        raise MjcfSecurityError(
            f"entity declaration {name!r} refused: entities are never expanded",
            file=self.filename,
            line=self.parser.CurrentLineNumber,
        )

    def refuse_external(self, *_args: Any) -> NoReturn:
        """Refuse an external entity reference (expat's handler)."""
        raise MjcfSecurityError(
            "external entity reference refused: nothing is fetched",
            file=self.filename,
            line=self.parser.CurrentLineNumber,
        )

    def path_to(self, item: OpenElement | None) -> str:
        """The element path of ``item`` (or of the innermost open element), for errors.

        Built only when an error is raised: ``item`` has been closed, so the open
        elements on the stack are its ancestors.
        """
        chain = self.stack if item is None else [*self.stack, item]
        steps = [
            element_step(o.tag, o.pairs(), 1 if index == 0 else chain[index - 1].index_of(o.tag))
            for index, o in enumerate(chain)
        ]
        return "".join(f"/{step}" for step in steps)

    # -- events -------------------------------------------------------------------

    def source(self, begin: int, end: int) -> str:
        """The source text between two byte offsets."""
        if self.ascii is not None:
            return self.ascii[begin:end]
        text = self.raw[begin:end].decode("utf-8", "surrogatepass")
        return without_placeholders(text) if self.escaped else text

    def start(self, tag: str, flat: list[str]) -> None:
        """Open an element at its start tag (expat's handler)."""
        raw = self.raw
        begin = self.parser.CurrentByteIndex
        stop = raw.find(b">", begin) + 1  # the tag's end, unless a value holds a ">"
        stack = self.stack
        parent = stack[-1] if stack else None
        context = parent.context if parent is not None else None
        if flat:
            joined = "".join(flat)  # attribute names hold neither ">" nor white space
            if ">" in joined:
                stop = start_tag_end(raw, begin)
            # expat turns a tab or line break in a value into a space; tinyxml2 keeps
            # it. Only a tag written over lines or with tabs can hold one.
            if " " in joined and self.breaks and BREAK.search(raw, begin, stop) is not None:
                flat = self.exact_attributes(tag, context, flat, begin)
        if self.escaped:
            tag, flat = without_placeholders(tag), [without_placeholders(part) for part in flat]
        if parent is None:
            self.root_begin = begin
        step = STEPS.get((context, tag))
        if step is None:
            step = step_of(context, tag)
        key, inner, typed = step
        place = -1  # the root: not in its own index
        if parent is None:
            if self.include_context is not None:
                inner = self.include_context  # MuJoCo takes the root's children, whatever its tag
        else:
            place = self.noted.reserve(tag)
        stack.append(
            OpenElement(
                tag, flat, key, typed, inner, self.parser.CurrentLineNumber, begin, stop, place
            )
        )

    def exact_attributes(
        self, tag: str, context: str | None, flat: list[str], begin: int
    ) -> list[str]:
        """``flat`` with the tabs and line breaks of text values kept, or ``flat`` itself.

        Numbers read the same either way; a text value with a space may have held one.
        """
        numeric = NUMERIC_ATTRIBUTES[context][tag]
        pairs = list(zip(flat[::2], flat[1::2], strict=True))
        if all(name in numeric or " " not in value for name, value in pairs):
            return flat
        return [part for pair in exact_attributes(self.raw, begin, pairs) for part in pair]

    def locate(self, error: MjcfError) -> MjcfError:
        """``error`` with the file, line and path of the element being closed."""
        item = self.closing
        assert item is not None
        return error.located(file=self.filename, line=item.line, path=self.path_to(item))

    def end(self, _tag: str) -> None:
        """Build the element being closed and give it to its parent (expat's handler)."""
        stack = self.stack
        item = stack.pop()
        children = tuple(item.children)
        text = element_text(item.text, bool(children)) if item.text else None
        stop = item.stop
        if self.raw[stop - 2] == _SLASH:  # an empty-element tag: it ends there
            after = stop
        else:
            after = self.raw.index(b">", self.parser.CurrentByteIndex) + 1
        layout = new_layout(
            Layout,
            (
                self.origin,
                item.tag,
                item.begin,
                stop,
                after,
                tuple(item.attributes),  # a tuple of strings: the collector stops tracking it
                children,
                text,
                item.comments,
            ),
        )
        typed = item.typed
        node: AnyElement | None = None
        if typed is not None and text is None:
            later: list[Deferred] = []
            node = read_typed(
                typed, item.attributes, children, layout, self.known, self.names, later
            )
            if node is not None and later:
                path = self.path_to(item)
                self.deferred += [(node, item.line, path, attribute) for attribute in later]
        if node is None:
            self.closing = item
            try:
                node = build_element(
                    item.key,
                    item.tag,
                    item.pairs(),
                    children,
                    text,
                    self.locate,
                    layout,
                    self.memo,
                )
            except MjcfError as error:
                raise self.locate(error) from None
            if node.children is not children:  # the layout holds the tuple the node holds
                node.__dict__["layout"] = layout._replace(children=node.children)
        if self.inline_includes and isinstance(node, Include):
            if not node.file:
                raise MjcfIncludeError(
                    "<include> needs a 'file' attribute",
                    file=self.filename,
                    line=item.line,
                    path=self.path_to(item),
                )
            context = self.stack[-1].context if self.stack else None
            self.includes.append(
                PendingInclude(
                    node, self.filename, item.line, self.path_to(item), context or "mujoco"
                )
            )
        if stack:  # after the include's path is taken: the path counts its siblings so far
            stack[-1].add_child(node)
            self.noted.order[item.place] = node
        else:
            self.top.append(node)
            self.root_end = after

    def comment(self, text: str) -> None:
        """Keep a comment as a child; its exact text stays in the file's (expat's handler)."""
        node = Comment(text=without_placeholders(text) if self.escaped else text)
        if not self.stack:
            self.top.append(node)  # its text is kept in the root's document text
            return
        parent = self.stack[-1]
        begin = self.parser.CurrentByteIndex
        after = self.raw.index(b"-->", begin + 4) + 3
        if parent.comments is None:
            parent.comments = {}
        parent.comments[len(parent.children)] = (begin, after)
        parent.add_child(node)

    def characters(self, data: str) -> None:
        """Note character data of the innermost open element (expat's handler)."""
        if self.escaped:
            data = without_placeholders(data)
        if self.stack:
            item = self.stack[-1]
            if item.text is None:
                item.text = [data]
            else:
                item.text.append(data)

    # -- driver -------------------------------------------------------------------

    def parse(self, data: str | bytes) -> list[Node]:
        """Read one document; text MuJoCo's lenient parser reads is repaired first."""
        top = self.read(data)
        self.convert_deferred()
        return top

    def convert_deferred(self) -> None:
        """Convert the long attributes read left as text, now that expat let go of its copies.

        The nodes are not yet handed out, so they get their values in place; a text
        the field cannot read is kept as :class:`~mjcf_model.values.Unparsed`, as
        :func:`~mjcf_model.serializers.parsed_elements.build_element` keeps it.
        """
        deferred, self.deferred = self.deferred, []
        for node, line, path, (field, name, text, convert) in deferred:
            try:
                value = convert(text)
            except MjcfValueError as error:
                problem = MjcfValueError(f"attribute {name!r}: {error.detail}")
                located = problem.located(file=self.filename, line=line, path=path)
                assert isinstance(located, MjcfValueError)
                value = Unparsed(text, located)
            else:
                self.known.setdefault(type(node), {})[(name, text)] = (field, value)
            node.__dict__[field] = value

    def read(self, data: str | bytes) -> list[Node]:
        """:meth:`parse`, but for the long attributes :meth:`convert_deferred` converts."""
        raw = data if isinstance(data, bytes) else self.encoded(data)
        if raw[:4] in _UTF32_BOMS:
            raise MjcfSyntaxError(
                "a UTF-32 file; save it as UTF-8, which MuJoCo reads", file=self.filename
            )
        utf16 = _UTF16_STARTS.get(raw[:2])
        if utf16 is not None:
            # expat follows a UTF-16 byte order mark, and detects UTF-16 from a first
            # "<" without one; read as UTF-8, so that byte offsets are text offsets
            try:
                raw = raw.decode(utf16).encode("utf-8", "surrogatepass")
            except UnicodeDecodeError as error:
                raise MjcfSyntaxError(
                    f"malformed UTF-16: {error.reason}; save the file as UTF-8, which MuJoCo reads",
                    file=self.filename,
                ) from None
        if b"\x00" in raw[:2]:  # expat would take the text for UTF-16, whatever it is
            raise MjcfSyntaxError(
                "a NUL byte at the start, which XML cannot carry; save the file as UTF-8",
                file=self.filename,
                line=1,
            )
        given = raw
        placeheld = with_placeholders(raw)
        if placeheld is not None:  # bytes that are not UTF-8, which MuJoCo reads
            raw, self.escaped = placeheld, True
        try:
            self.raw = raw
            self.origin = SourceText(raw, self.filename, reducer=reduced_from_text)
            self.origin.escaped = self.escaped
            self.origin.values = self.known
            if not self.origin.raw:
                self.ascii = self.origin.text
            self.breaks = BREAK.search(raw) is not None
            if not may_hold_text(raw):
                self.parser.CharacterDataHandler = None  # white space alone: nothing to keep
            self.parser.Parse(raw, True)
            self.record_document(len(raw))
        except expat.ExpatError as error:
            if self.completed_root(raw):
                # MuJoCo reads the first root element and ignores what follows
                self.record_document(epilog_end(raw, self.root_end, self.parser.ErrorByteIndex))
                return self.top
            blanked = blank_text_before_root(raw)
            repaired = escape_stray_markup(blanked or raw) or blanked
            if repaired is not None:
                retry = Reader(self.filename, self.session, self.include_context)
                if self.escaped:  # the bytes as they were: the retry escapes them again
                    repaired = encoded(without_placeholders(repaired.decode()))
                try:
                    top = retry.parse(repaired)
                except MjcfSyntaxError:
                    pass
                else:
                    self.includes = retry.includes
                    self.noted = retry.noted
                    return top
            raise self.syntax_error(error, raw, given) from None
        finally:
            self.release()
        return self.top

    def encoded(self, text: str) -> bytes:
        """``text`` as the bytes of a file: each escaped byte the byte it was read from."""
        try:
            return encoded(text)
        except UnicodeEncodeError as error:
            character = text[error.start]
            raise MjcfSyntaxError(
                f"the text holds U+{ord(character):04X}, a lone surrogate that no file "
                "holds and XML cannot carry; remove it",
                file=self.filename,
                line=text.count("\n", 0, error.start) + 1,
            ) from None

    def index(self) -> TagIndex:
        """The lookup index of the root read: every element below it, noted as it was read.

        Valid for the root's children as read (an inlined include replaces elements).
        """
        return self.noted.index()

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
        del self.parser  # and its buffers: a long attribute is converted after this

    def record_document(self, stop: int) -> None:
        """Give the root's layout the text around the root, up to byte ``stop``."""
        comments = [n for n in self.top if isinstance(n, Comment)]
        root = next((n for n in self.top if not isinstance(n, Comment)), None)
        layout = layout_of(root)
        if not isinstance(root, Element) or layout is None:
            return
        count = self.top.index(root)
        origin = layout.origin
        origin.root_begin = layout.begin
        origin.document = DocumentText(
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

    def syntax_error(self, error: expat.ExpatError, raw: bytes, given: bytes) -> MjcfSyntaxError:
        """The error to raise for what expat refused in ``raw``, located and explained.

        ``given`` is the text as given (``raw`` may hold placeholders for its bytes).
        """
        kind = not_xml(given)
        if kind is not None:
            return MjcfSyntaxError(
                f"not an MJCF model: {kind}, not XML; give the model's XML file "
                "(its root element is <mujoco>)",
                file=self.filename,
            )
        path = self.path_to(None) if self.stack else None
        message = expat.errors.messages[error.code] if error.code else str(error)
        detail = f"malformed XML: {message} (column {error.offset + 1})"
        index = self.parser.ErrorByteIndex
        if index >= 0:
            detail += character_hint(raw[index : index + 4])
        return MjcfSyntaxError(detail, file=self.filename, line=error.lineno, path=path)


#: The byte of ``/``: a start tag that ends with ``/>`` is an empty element.
_SLASH = ord("/")
