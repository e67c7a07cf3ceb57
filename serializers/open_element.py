"""An element the text reader has begun and not yet closed.

:class:`OpenElement` holds what :class:`serializers.expat_reading.Reader` gathers
between an element's start tag and its end tag: its attributes, its children and
the source text around them.

>>> item = OpenElement("geom", ["size", "0.1"], "geom", None, None, 1, 0, "<geom>", 6, "")
>>> item.children, item.start
([], '<geom>')
"""

from __future__ import annotations

from typing import Any

from mjcf_model.base import Node

__all__ = ["OpenElement"]


class OpenElement:
    """An element whose start tag was read and whose end tag was not yet."""

    __slots__ = (
        "attributes",
        "begin",
        "children",
        "comments",
        "context",
        "cursor",
        "gap",
        "gaps",
        "key",
        "line",
        "sources",
        "start",
        "tag",
        "text",
        "typed",
    )

    def __init__(
        self,
        tag: str,
        attributes: list[str],
        key: str | None,
        typed: type | None,
        context: str | None,
        line: int,
        begin: int,
        start: str,
        cursor: int,
        gap: str,
    ) -> None:
        self.tag = tag
        #: The attribute names and values in source order, alternating (as expat gives them).
        self.attributes = attributes
        self.key = key
        #: The typed class the key maps to, when its tag is the element's (else ``None``).
        self.typed = typed
        self.context = context
        self.line = line
        #: The byte offset of the start tag's ``<``.
        self.begin = begin
        #: The start tag's source text.
        self.start = start
        #: The byte offset where the text not yet given to a gap or a child begins.
        self.cursor = cursor
        #: The source text between the previous sibling (or the parent's start tag) and this.
        self.gap = gap
        #: The character data read, or ``None`` before any.
        self.text: list[str] | None = None
        #: What the children need, made at the first child (most elements have none):
        #: the children, the source text before each child, and each child's layout or
        #: the comment node (:attr:`Layout.sources`).
        self.children: list[Node] = _NO_CHILDREN
        self.gaps: list[str] = _NO_CHILDREN
        self.sources: list[Any] = _NO_CHILDREN
        #: The exact text of comment children that ``<!--text-->`` would not give back.
        self.comments: dict[int, str] | None = None

    def add_child(self, gap: str, child: Node, source: Any) -> None:
        """Note a child and the source text before it."""
        if self.children is _NO_CHILDREN:
            self.children, self.gaps, self.sources = [], [], []
        self.gaps.append(gap)
        self.children.append(child)
        self.sources.append(source)

    def pairs(self) -> list[tuple[str, str]]:
        """The attributes as ``(name, value)`` pairs."""
        flat = self.attributes
        return list(zip(flat[::2], flat[1::2], strict=True))

    def index_of(self, tag: str) -> int:
        """The 1-based position a ``tag`` child added now takes among the children of its tag."""
        return 1 + sum(1 for child in self.children if getattr(child, "tag", None) == tag)


#: What an element without children holds as its children (never appended to).
_NO_CHILDREN: list[Any] = []
