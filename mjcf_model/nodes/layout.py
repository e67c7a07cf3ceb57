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

from collections.abc import Callable, Set
from typing import Any, NamedTuple

__all__ = ["DocumentText", "Layout", "LayoutDetail", "SourceText", "detail"]


class SourceText:
    """The text of one file as read, shared by the layouts of its elements.

    Offsets are byte offsets (expat's): for an ASCII file they are text offsets too.

    Example:
        >>> SourceText(b"<a><b/></a>").slice(3, 7)
        '<b/>'

    """

    __slots__ = ("details", "document", "filename", "raw", "root_begin", "text", "values")

    def __init__(self, raw: bytes, filename: str | None = None) -> None:
        #: The file the text was read from, as the reader was given it (``"<string>"`` for
        #: text), or ``None``: where errors about its elements point.
        self.filename = filename
        #: The bytes read, when they are not ASCII (offsets are byte offsets), else ``b""``.
        self.raw = b"" if raw.isascii() else raw
        #: The text, when the bytes are ASCII (byte offsets are then text offsets).
        self.text = raw.decode("ascii") if not self.raw else ""
        #: The text of the file around its root element, and where the root begins.
        self.document: DocumentText | None = None
        self.root_begin = -1
        #: The :class:`LayoutDetail` of each element the writer asked for, by its offset.
        self.details: dict[int, LayoutDetail] = {}
        #: Per typed class, each ``(name, text)`` attribute the reader read, as the
        #: field and value it gave the node (shared with the reader while it reads).
        self.values: dict[type, dict[tuple[str, str], tuple[str, Any]]] = {}

    def __getstate__(self) -> dict[str, Any]:
        """Pickle without the details (they may hold getters): they are worked out again."""
        state = {name: getattr(self, name) for name in self.__slots__}
        state["details"] = {}
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.filename = None  # pickled before files were recorded
        for name, value in state.items():
            setattr(self, name, value)

    def slice(self, begin: int, after: int) -> str:
        """The text between two byte offsets."""
        if self.raw:
            return self.raw[begin:after].decode("utf-8", "surrogatepass")
        return self.text[begin:after]

    def line(self, offset: int) -> int:
        r"""The 1-based line the byte ``offset`` stands on, as MuJoCo counts lines.

        Worked out when asked for (for an error), never while reading.

        Example:
            >>> SourceText(b"<a>\n  <b/>\n</a>").line(6)
            2

        """
        if self.raw:
            return self.raw.count(b"\n", 0, offset) + 1
        return self.text.count("\n", 0, offset) + 1

    def end_tag_begin(self, begin: int, after: int) -> int:
        """Where the end tag of the element between two offsets begins."""
        if self.raw:
            return self.raw.rindex(b"</", begin, after)
        return self.text.rindex("</", begin, after)


class DocumentText:
    r"""The text of a file around its root element: XML declaration, comments, line breaks.

    Example:
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


class Layout(NamedTuple):
    """Where one element was read, and what it was read with.

    Made by the reader, one per element (a tuple: cheap to make, never changed).
    The pieces the writer edits are worked out by :func:`detail` when first
    asked for, and kept with the file's text.

    Example:
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
    #: The attribute names and texts as read, alternating, in source order (the
    #: reader's own list, never changed).
    attributes: list[str]
    #: The children the element was read with: while the element still holds this
    #: very tuple, nothing below it changed.
    children: tuple[Any, ...]
    #: The element's ``text`` when it was read.
    text: str | None
    #: Where each comment child begins and ends, by child index; ``None`` when none.
    comments: dict[int, tuple[int, int]] | None = None

    def whole(self) -> str:
        """The element's whole source text, from its start tag to its end tag.

        Example:
            >>> Layout(SourceText(b"<a></a>"), "a", 0, 3, 7, [], (), None).whole()
            '<a></a>'

        """
        return self.origin.slice(self.begin, self.after)

    def document(self) -> DocumentText | None:
        """For the root element of its file, the text of the file around it."""
        origin = self.origin
        return origin.document if origin.root_begin == self.begin else None

    def __repr__(self) -> str:
        return f"Layout({self.whole()[:40]!r}, ...)"


def detail(layout: Layout) -> LayoutDetail:
    r"""The pieces of the element's text, cut once and kept with the file's text.

    Example:
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

    Example:
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
        "gaps",
        "getter",
        "names",
        "sources",
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
