"""How an element was written in its file, so that writing it back changes nothing.

A loaded element carries a :class:`Layout`: the exact text of its start tag,
of the gaps between its children and of its end tag. The writer copies that
text for what nobody changed and writes only what a transform changed or
added in the canonical form. A layout is never part of a node's value: ``==``,
``hash`` and the dict form ignore it.

A transform that rebuilds an element keeps its layout (``attrs.evolve`` copies
it), so the writer tells what changed by comparing: the attribute values the
reader stored (:attr:`Layout.values`) with the element's own, and each child
with the child that stood there (:attr:`Layout.sources`).
"""

from __future__ import annotations

from collections.abc import Callable, Set
from typing import Any

__all__ = ["DocumentText", "Layout", "SourceText"]


class SourceText:
    """The text of one file as read, shared by the layouts of its elements.

    An element nobody changed, with every element below it, is written back as
    one slice of it (:meth:`Layout.whole`).

    Example:
        >>> SourceText(b"<a><b/></a>").slice(3, 7)
        '<b/>'

    """

    __slots__ = ("raw", "text")

    def __init__(self, raw: bytes) -> None:
        #: The bytes read, when they are not ASCII (offsets are byte offsets), else ``b""``.
        self.raw = b"" if raw.isascii() else raw
        #: The text, when the bytes are ASCII (byte offsets are then text offsets).
        self.text = raw.decode("ascii") if not self.raw else ""

    def slice(self, begin: int, after: int) -> str:
        """The text between two byte offsets."""
        if self.raw:
            return self.raw[begin:after].decode("utf-8", "surrogatepass")
        return self.text[begin:after]


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


class Layout:
    """The source text of one element, as the reader found it.

    Mutable only while the reader builds it; shared, never changed, afterwards.

    Example:
        >>> layout = Layout("geom", '<geom size="1.0"/>', ("",), "", ("size",), ((1.0,),), (), None)
        >>> layout.start
        '<geom size="1.0"/>'

    """

    __slots__ = (
        "after",
        "begin",
        "children",
        "comments",
        "document",
        "end",
        "gaps",
        "getter",
        "names",
        "origin",
        "sources",
        "start",
        "stored",
        "tag",
        "text",
        "values",
    )

    def __init__(
        self,
        tag: str,
        start: str,
        gaps: tuple[str, ...],
        end: str,
        names: tuple[str, ...],
        values: tuple[Any, ...],
        sources: tuple[Any, ...],
        text: str | None,
        comments: dict[int, str] | None = None,
    ) -> None:
        #: The element's tag when it was read.
        self.tag = tag
        #: The start tag exactly as written, from ``<`` to ``>`` (``/>`` for an empty element).
        self.start = start
        #: The text between the start tag, each child and the end tag: one more than the
        #: children. White space, and the raw text of an element with character data.
        self.gaps = gaps
        #: The end tag exactly as written, or ``""`` for an empty-element tag.
        self.end = end
        #: The MJCF attribute names of the start tag, in order.
        self.names = names
        #: The values the reader stored for those attributes: a value that is still the
        #: same object (or an equal one) was not changed, and its source text is written back.
        self.values = values
        #: What stood in each child slot: a child element's own :class:`Layout`, or the
        #: comment node itself. A child carrying the same token is the same child.
        self.sources = sources
        #: The element's ``text`` when it was read.
        self.text = text
        #: The exact text of comment children whose text differs from ``<!--text-->``
        #: (a carriage return), by child index; ``None`` when there is none.
        self.comments = comments
        #: For the root element: the text of the file around it.
        self.document: DocumentText | None = None
        #: For a typed element whose attributes all have fields: reads the element's
        #: values for ``names`` at once (``None`` otherwise).
        self.getter: Callable[[Any], tuple[Any, ...]] | None = None
        #: The fields the element stored when it was read: with ``getter``, an element
        #: that stores the same fields, with ``values`` for its attributes, is unchanged
        #: (the writer's fast check).
        self.stored: Set[str] = frozenset()
        #: The children the element was read with: while the element still holds this
        #: very tuple, nothing below it changed.
        self.children: tuple[Any, ...] = ()
        #: The file's text, and where the element begins and ends in it (byte offsets).
        self.origin: SourceText | None = None
        self.begin = self.after = 0

    def whole(self) -> str | None:
        """The element's whole source text, from its start tag to its end tag, if known.

        Example:
            >>> layout = Layout("a", "<a>", ("",), "</a>", (), (), (), None)
            >>> layout.origin, layout.begin, layout.after = SourceText(b"<a></a>"), 0, 7
            >>> layout.whole()
            '<a></a>'

        """
        origin = self.origin
        return None if origin is None else origin.slice(self.begin, self.after)

    def __repr__(self) -> str:
        return f"Layout({self.start!r}, ...)"

    def __getstate__(self) -> dict[str, Any]:
        """Pickle without ``getter`` (it may be a lambda): the writer then compares values."""
        state = {name: getattr(self, name) for name in self.__slots__}
        state["getter"] = None
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        for name, value in state.items():
            setattr(self, name, value)
