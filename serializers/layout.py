r"""How an element was written in its file, so that writing it back changes nothing.

A loaded element carries a :class:`Layout`: where it stands in its file's text
(two offsets), the attributes and children it was read with, and its text. The
writer copies the source text of what nobody changed and writes only what a
transform changed or added in the canonical form. A layout is never part of a
node's value: ``==``, ``hash`` and the dict form ignore it.

Reading records only what costs nothing to keep; the pieces the writer needs
for an element that did change (its start tag, the gaps between its children,
its end tag) are cut from the text when first asked for (:func:`detail`).
A transform that rebuilds an element keeps its layout (``attrs.evolve`` copies
it), so the writer tells what changed by comparing: the values read with the
element's own, and each child with the child that stood there.

>>> layout = Layout(SourceText(b"<a>\n</a>"), "a", 0, 3, 8, [], (), None)
>>> layout.whole(), detail(layout).gaps, detail(layout).end
('<a>\n</a>', ('\n',), '</a>')
"""

from __future__ import annotations

import contextlib
import weakref
from collections.abc import Callable, Sequence, Set
from typing import Any, NamedTuple
from xml.parsers import expat

from mjcf_model.values.encoding import without_placeholders

__all__ = [
    "DocumentText",
    "Layout",
    "LayoutDetail",
    "Reducer",
    "SourceText",
    "detail",
    "layout_of",
    "new_layout",
    "place_key",
    "read_slots",
]


class SourceText:
    """The text of one file as read, shared by the layouts of its elements.

    Offsets are byte offsets (expat's): for an ASCII file they are text offsets too.

    Examples:
        >>> SourceText(b"<a><b/></a>").slice(3, 7)
        '<b/>'

    """

    __slots__ = (
        "__weakref__",
        "details",
        "document",
        "escaped",
        "filename",
        "first_line",
        "pieces",
        "raw",
        "read_attributes",
        "reducer",
        "root_begin",
        "text",
        "values",
    )

    def __init__(
        self,
        raw: bytes,
        filename: str | None = None,
        first_line: int = 0,
        reducer: Reducer | None = None,
    ) -> None:
        #: The file the text was read from, as the reader was given it (``"<string>"`` for
        #: text), or ``None``: where errors about its elements point.
        self.filename = filename
        #: The bytes read, when they are not ASCII (offsets are byte offsets), else ``b""``.
        self.raw = b"" if raw.isascii() else raw
        #: The text, when the bytes are ASCII (byte offsets are then text offsets).
        self.text = raw.decode("ascii") if not self.raw else ""
        #: Whether ``raw`` holds placeholders for bytes that are not UTF-8, which the text
        #: handed out escapes (:mod:`mjcf_model.values.encoding`).
        self.escaped = False
        #: The text of the file around its root element, and where the root begins.
        self.document: DocumentText | None = None
        self.root_begin = -1
        #: The :class:`LayoutDetail` of each element the writer asked for, by its offset.
        self.details: dict[int, LayoutDetail] = {}
        #: Per typed class, each ``(name, text)`` attribute the reader read, as the
        #: field and value it gave the node (shared with the reader while it reads).
        self.values: dict[type, dict[tuple[str, str], tuple[str, Any]]] = {}
        #: How many lines of the file stand before the text (for a piece of a file's text).
        self.first_line = first_line
        #: The pieces of the text being pickled now: ``(piece, begin, after)``, the piece
        #: held weakly (the pickler's memo holds it while it pickles; see :meth:`piece`).
        self.pieces: list[tuple[weakref.ref[SourceText], int, int]] = []
        #: For an unpickled piece, each element's attribute list by its offset, read again
        #: from the text when first asked for (see :meth:`attributes_at`).
        self.read_attributes: dict[int, list[str]] | None = None
        #: How the reader that read the text pickles an element read from it (see
        #: :meth:`Layout.reduced`), or ``None``: pickled field by field.
        self.reducer = reducer

    def __getstate__(self) -> dict[str, Any]:
        """Pickle the text, not the caches (details may hold getters): they are worked out again.

        Nor the reducer: an element pickled by it is unpickled by the reader, which gives
        the text its reducer again (a pickled geom stays a few hundred bytes).
        """
        state = {name: getattr(self, name) for name in self.__slots__ if name != "__weakref__"}
        state["details"], state["values"], state["pieces"] = {}, {}, []
        state["read_attributes"] = state["reducer"] = None
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.filename, self.first_line = None, 0  # pickled before they were recorded
        self.pieces, self.read_attributes, self.reducer = [], None, None
        self.escaped = False
        for name, value in state.items():
            setattr(self, name, value)

    def piece(self, begin: int, after: int) -> tuple[SourceText, int]:
        r"""The text from ``begin`` to ``after`` as a text of its own, and where it begins here.

        What a pickled element carries instead of its whole file: the piece cut for the
        outermost element being pickled serves every element inside it, as long as the
        pickler holds it (an element pickles its layout before its children). The
        root element's piece is the whole text, with what stands around the root.

        Examples:
            >>> text = SourceText(b"<a>\n  <b/>\n</a>", "a.xml")
            >>> piece, base = text.piece(6, 10)
            >>> piece.slice(0, 4), base, piece.line(0), text.piece(7, 9)[0] is piece
            ('<b/>', 6, 2, True)

        """
        for held, start, stop in self.pieces:
            cut = held()
            if cut is not None and start <= begin and after <= stop:
                return cut, start
        self.pieces = [entry for entry in self.pieces if entry[0]() is not None]
        if begin == self.root_begin:
            cut, begin, after = SourceText(b"", self.filename, self.first_line, self.reducer), 0, -1
            cut.raw, cut.text = self.raw, self.text
            cut.document, cut.root_begin = self.document, self.root_begin
        else:
            raw = self.raw[begin:after] if self.raw else self.text[begin:after].encode("ascii")
            lines = self.line(begin) - 1
            cut = SourceText(raw, self.filename, lines, self.reducer)
        cut.escaped = self.escaped
        self.pieces.append((weakref.ref(cut), begin, after if after >= 0 else 1 << 62))
        return cut, begin

    def attributes_at(self, offset: int) -> list[str]:
        r"""The attribute names and texts of the start tag at byte ``offset``, as expat reads them.

        A pickled layout leaves them out (they repeat its text); the first one unpickled
        reads the whole piece once.

        Examples:
            >>> SourceText(b'<a x="1">\n  <b y="&lt;2"/></a>').attributes_at(12)
            ['y', '<2']

        """
        if self.read_attributes is None:
            found: dict[int, list[str]] = {}
            parser = expat.ParserCreate(encoding="utf-8")
            parser.ordered_attributes = True

            def start(name: str, attributes: list[str]) -> None:
                if self.escaped:
                    attributes = [without_placeholders(part) for part in attributes]
                found[parser.CurrentByteIndex + begin] = attributes

            parser.StartElementHandler = start
            begin = max(self.root_begin, 0)
            whole = self.raw or self.text.encode("ascii")
            with contextlib.suppress(expat.ExpatError):  # after a root: MuJoCo ignores it too
                parser.Parse(whole[begin:], True)
            self.read_attributes = found
        return self.read_attributes[offset]

    def slice(self, begin: int, after: int) -> str:
        """The text between two byte offsets."""
        if self.raw:
            text = self.raw[begin:after].decode("utf-8", "surrogatepass")
            return without_placeholders(text) if self.escaped else text
        return self.text[begin:after]

    def line(self, offset: int) -> int:
        r"""The 1-based line the byte ``offset`` stands on, as MuJoCo counts lines.

        Worked out when asked for (for an error), never while reading.

        Examples:
            >>> SourceText(b"<a>\n  <b/>\n</a>").line(6)
            2

        """
        if self.raw:
            return self.first_line + self.raw.count(b"\n", 0, offset) + 1
        return self.first_line + self.text.count("\n", 0, offset) + 1

    def end_tag_begin(self, begin: int, after: int) -> int:
        """Where the end tag of the element between two offsets begins."""
        if self.raw:
            return self.raw.rindex(b"</", begin, after)
        return self.text.rindex("</", begin, after)


#: How to pickle an element read from a text: what :meth:`object.__reduce_ex__` returns,
#: or ``None`` to pickle it field by field (the text reader's is
#: :func:`mjcf_model.serializers.parsed_elements.reduced_from_text`).
Reducer = Callable[[Any], "tuple[Any, ...] | None"]


class DocumentText:
    r"""The text of a file around its root element: XML declaration, comments, line breaks.

    Examples:
        >>> DocumentText('<?xml version="1.0"?>\\n', "\\n", (), ()).before
        '<?xml version="1.0"?>\\n'

    """

    __slots__ = ("after", "after_comments", "before", "before_comments")

    def __init__(
        self,
        before: str,
        after: str,
        before_comments: tuple[Any, ...],
        after_comments: tuple[Any, ...],
    ) -> None:
        #: Everything before the root's start tag, comments included.
        self.before = before
        #: Everything after the root's end tag, comments and the final line break included.
        self.after = after
        #: The comment nodes read before the root (they lead the root's children).
        self.before_comments = before_comments
        #: The comment nodes read after the root (they end the root's children).
        self.after_comments = after_comments

    def inner_children(self, children: tuple[Any, ...]) -> tuple[Any, ...] | None:
        """``children`` of the root without the comments read around it, or ``None``.

        ``None`` when ``children`` no longer starts and ends with those very comments
        (a program changed them): the text around the root is then not written as read.

        Examples:
            >>> lead, trail = "lead", "trail"
            >>> DocumentText("", "", (lead,), (trail,)).inner_children((lead, "a", trail))
            ('a',)

        """
        lead, trail = self.before_comments, self.after_comments
        inner = len(children) - len(trail)
        if (
            inner >= len(lead)
            and all(a is b for a, b in zip(children, lead, strict=False))
            and all(a is b for a, b in zip(children[inner:], trail, strict=True))
        ):
            return children[len(lead) : inner]
        return None


class Layout(NamedTuple):
    """Where one element was read, and what it was read with.

    Made by the reader, one per element (a tuple: cheap to make, never changed).
    The pieces the writer edits are worked out by :func:`detail` when first
    asked for, and kept with the file's text.

    Examples:
        >>> origin = SourceText(b'<geom size="1.0"/>')
        >>> layout = Layout(origin, "geom", 0, 18, 18, ["size", "1.0"], (), None)
        >>> detail(layout).start, detail(layout).names
        ('<geom size="1.0"/>', ('size',))

    """

    #: The file's text.
    origin: SourceText
    #: The element's tag when it was read.
    tag: str
    #: Where the element begins, where its start tag ends and where it ends, in it
    #: (byte offsets; the last two are one for an empty-element tag).
    begin: int
    stop: int
    after: int
    #: The attribute names and texts as read, alternating, in source order (a tuple of
    #: strings, which the garbage collector stops tracking: a big model's collections
    #: then have a fifth fewer objects to scan).
    attributes: Sequence[str]
    #: The children the element was read with: while the element still holds this
    #: very tuple, nothing below it changed.
    children: tuple[Any, ...]
    #: The element's ``text`` when it was read.
    text: str | None
    #: Where each comment child begins and ends, by child index; ``None`` when none.
    comments: dict[int, tuple[int, int]] | None = None

    def whole(self) -> str:
        """The element's whole source text, from its start tag to its end tag.

        Examples:
            >>> Layout(SourceText(b"<a></a>"), "a", 0, 3, 7, [], (), None).whole()
            '<a></a>'

        """
        return self.origin.slice(self.begin, self.after)

    def where(self) -> tuple[str | None, int]:
        r"""The file the element was read from (as the reader was given it) and its line.

        Examples:
            >>> Layout(SourceText(b"<a>\n<b/></a>", "a.xml"), "b", 4, 8, 8, [], (), None).where()
            ('a.xml', 2)

        """
        return self.origin.filename, self.origin.line(self.begin)

    def reduced(self, element: Any) -> tuple[Any, ...] | None:
        """How to pickle ``element``, read with this layout: as the reader of its text says.

        ``None`` (pickle it field by field) for a text no reader gave a way.
        """
        reducer = self.origin.reducer
        return None if reducer is None else reducer(element)

    def document(self) -> DocumentText | None:
        """For the root element of its file, the text of the file around it."""
        origin = self.origin
        return origin.document if origin.root_begin == self.begin else None

    def __repr__(self) -> str:
        return f"Layout({self.whole()[:40]!r}, ...)"

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle with the piece of the file's text the element stands in, not the whole file.

        Examples:
            >>> import pickle
            >>> origin = SourceText(b"<a>" + b" " * 1000 + b"<b/></a>")
            >>> b = Layout(origin, "b", 1003, 1007, 1007, [], (), None)
            >>> copy = pickle.loads(pickle.dumps(b))
            >>> copy.whole(), len(copy.origin.text)
            ('<b/>', 4)

        """
        piece, base = self.origin.piece(self.begin, self.after)
        comments = self.comments
        if comments is not None and base:
            comments = {index: (a - base, b - base) for index, (a, b) in comments.items()}
        rest = (self.children, self.text, comments)
        return (
            _unpickled,
            (piece, self.tag, self.begin - base, self.stop - base, self.after - base, *rest),
        )

    def without_old_children(self, children: tuple[Any, ...]) -> Layout:
        """The layout for an element that now holds ``children``: keeps no replaced child.

        The writer needs of the children an element was read with only their layouts
        (and comments): an element that holds other children now keeps those in their
        place, so that neither memory nor a pickle keeps the nodes it replaced.

        Examples:
            >>> from mjcf_model import Geom
            >>> geom = Geom(layout=Layout(SourceText(b"<geom/>"), "geom", 0, 7, 7, [], (), None))
            >>> layout = Layout(SourceText(b"<a><geom/></a>"), "a", 0, 3, 14, [], (geom,), None)
            >>> layout.without_old_children(()).children == (geom.layout,)
            True

        """
        if children is self.children:
            return self
        return _with_children(self, tuple([_place(child) for child in self.children]))


def _unpickled(
    origin: SourceText,
    tag: str,
    begin: int,
    stop: int,
    after: int,
    children: tuple[Any, ...],
    text: str | None,
    comments: dict[int, tuple[int, int]] | None,
) -> Layout:
    """A layout as :meth:`Layout.__reduce__` pickled it: its attributes read again."""
    attributes = origin.attributes_at(begin)
    return Layout(origin, tag, begin, stop, after, attributes, children, text, comments)


def _place(child: Any) -> Any:
    """What a child slot needs of ``child``: its layout without its own children, or the comment."""
    source = getattr(child, "layout", child)
    if type(source) is Layout and source.children:
        return _with_children(source, ())
    return source


def _with_children(layout: Layout, children: tuple[Any, ...]) -> Layout:
    """``layout._replace(children=children)``, made in C (the transforms make one per parent).

    Examples:
        >>> layout = Layout(SourceText(b"<a/>"), "a", 0, 4, 4, [], ("old",), None, {0: (1, 2)})
        >>> _with_children(layout, ()) == layout._replace(children=())
        True

    """
    return new_layout(Layout, (*layout[:6], children, *layout[7:]))


#: Makes a layout from a tuple of its fields, in C: ``new_layout(Layout, fields)`` (the
#: reader makes one per element, the transforms one per rebuilt parent).
new_layout = tuple.__new__


def layout_of(node: Any) -> Layout | None:
    """The layout ``node`` was read with; ``None`` for a node built in code, or a comment.

    Examples:
        >>> from mjcf_model import Geom, loads
        >>> layout_of(Geom()) is None
        True
        >>> layout_of(loads("<mujoco/>")).tag
        'mujoco'

    """
    layout = getattr(node, "layout", None)
    return layout if type(layout) is Layout else None


def place_key(source: Any) -> object:
    """What tells one child slot's source from another: an element's place in its text.

    A layout made again for the same element (with :meth:`Layout.without_old_children`)
    stands in the same place; a comment node is its own key.

    Examples:
        >>> origin = SourceText(b"<a><b/></a>")
        >>> b = Layout(origin, "b", 3, 7, 7, [], (), None)
        >>> place_key(b) == place_key(b.without_old_children(("changed",)))
        True

    """
    if type(source) is Layout:
        return (id(source.origin), source.begin)
    return id(source)


def read_slots(cut: LayoutDetail, children: Sequence[Any]) -> list[int]:
    """For each of ``children``, the child slot it was read in, or ``-1`` (added since).

    Examples:
        >>> origin = SourceText(b"<a><b/><c/></a>")
        >>> b = Layout(origin, "b", 3, 7, 7, [], (), None)
        >>> c = Layout(origin, "c", 7, 11, 11, [], (), None)
        >>> cut = detail(Layout(origin, "a", 0, 3, 15, [], (b, c), None))
        >>> read_slots(cut, [c, "new", b])
        [1, -1, 0]

    """
    slots = {place_key(source): index for index, source in enumerate(cut.sources)}
    found = []
    for child in children:
        token = getattr(child, "layout", child)
        found.append(-1 if token is None else slots.get(place_key(token), -1))
    return found


def detail(layout: Layout) -> LayoutDetail:
    r"""The pieces of the element's text, cut once and kept with the file's text.

    Examples:
        >>> layout = Layout(SourceText(b"<a>\n</a>"), "a", 0, 3, 8, [], (), None)
        >>> detail(layout).gaps, detail(layout) is detail(layout)
        (('\n',), True)

    """
    details = layout.origin.details
    found = details.get(layout.begin)
    if found is None:
        found = details[layout.begin] = LayoutDetail(layout)
    return found


class LayoutDetail:
    r"""The pieces of one element's source text, as the writer edits them.

    Examples:
        >>> origin = SourceText(b"<a x='1'>\n  <b/>\n  <!--c-->\n</a>")
        >>> b = Layout(origin, "b", 12, 16, 16, [], (), None)
        >>> comments = {1: (19, 27)}
        >>> layout = Layout(origin, "a", 0, 9, 32, ["x", "1"], ("b", "comment"), None, comments)
        >>> pieces = LayoutDetail(layout, (b, "comment"))
        >>> pieces.tag, pieces.start, pieces.gaps, pieces.end
        ('a', "<a x='1'>", ('\n  ', '\n  ', '\n'), '</a>')
        >>> pieces.comments
        {1: '<!--c-->'}

    """

    __slots__ = (
        "comments",
        "end",
        "fields",
        "gaps",
        "getter",
        "names",
        "sources",
        "spans",
        "start",
        "stored",
        "tag",
        "texts",
        "values",
    )

    def __init__(self, layout: Layout, sources: tuple[Any, ...] | None = None) -> None:
        origin = layout.origin
        begin, stop, after = layout.begin, layout.stop, layout.after
        #: The start tag exactly as written, from ``<`` to ``>`` (``/>`` for an empty element).
        self.start = origin.slice(begin, stop)
        #: The element's tag when it was read.
        self.tag = layout.tag
        #: The attribute names and texts of the start tag, in order.
        self.names: tuple[str, ...] = tuple(layout.attributes[::2])
        self.texts: tuple[str, ...] = tuple(layout.attributes[1::2])
        children = layout.children
        #: What stood in each child slot: a child element's own :class:`Layout`, or the
        #: comment node itself. A child carrying the same token is the same child.
        self.sources: tuple[Any, ...] = (
            sources
            if sources is not None
            else tuple([getattr(child, "layout", child) for child in children])
        )
        #: The exact text of each comment child, by child index.
        self.comments: dict[int, str] = {}
        #: The text between the start tag, each child and the end tag: one more than the
        #: children. White space, and the raw text of an element with character data.
        self.gaps: tuple[str, ...]
        #: The end tag exactly as written, or ``""`` for an empty-element tag.
        self.end: str
        if stop == after:
            self.gaps, self.end = ("",), ""
        else:
            closing = origin.end_tag_begin(stop, after)
            self.end = origin.slice(closing, after)
            gaps: list[str] = []
            cursor = stop
            spans = layout.comments or {}
            for index, source in enumerate(self.sources):
                span = spans.get(index)
                if span is None:
                    span = (source.begin, source.after)
                else:
                    self.comments[index] = origin.slice(*span)
                gaps.append(origin.slice(cursor, span[0]))
                cursor = span[1]
            gaps.append(origin.slice(cursor, closing))
            self.gaps = tuple(gaps)
        #: The values the reader stored for ``names``, worked out for the element's class
        #: by the writer (``None`` until then): a value that is still the same object (or
        #: an equal one) was not changed, and its source text is written back.
        self.values: tuple[Any, ...] | None = None
        #: For a typed element whose attributes all have fields: reads the element's
        #: values for ``names`` at once (``None`` otherwise).
        self.getter: Callable[[Any], tuple[Any, ...]] | None = None
        #: The fields the element stored when it was read: with ``getter``, an element
        #: that stores the same fields, with ``values`` for its attributes, is unchanged
        #: (the writer's fast check).
        self.stored: Set[str] = frozenset()
        #: With ``getter``: the field of each of ``names``, in order.
        self.fields: tuple[str, ...] = ()
        #: Where each attribute stands in ``start``: where the white space before it begins,
        #: the character after its opening quote, and its closing quote; in order. ``None``
        #: until the writer first edits the start tag.
        self.spans: list[tuple[int, int, int]] | None = None
