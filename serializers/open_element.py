"""An element the text reader has begun and not yet closed.

:class:`OpenElement` holds what :class:`mjcf_model.serializers.parsing.Reader` gathers
between an element's start tag and its end tag: its attributes, its children and
where its start tag stands in the text.

>>> item = OpenElement("geom", ["size", "0.1"], "geom", None, None, 1, 0, 16)
>>> item.children, item.pairs()
([], [('size', '0.1')])
"""

from __future__ import annotations

from typing import Any

from mjcf_model.caching import BoundedCache
from mjcf_model.nodes.base import Node
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema.namespaces import child_key, children_context

__all__ = ["STEPS", "OpenElement", "step_of"]


class OpenElement:
    """An element whose start tag was read and whose end tag was not yet."""

    __slots__ = (
        "attributes",
        "begin",
        "children",
        "comments",
        "context",
        "key",
        "line",
        "place",
        "stop",
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
        stop: int,
        place: int = -1,
    ) -> None:
        self.tag = tag
        #: The attribute names and values in source order, alternating (as expat gives them).
        self.attributes = attributes
        self.key = key
        #: The typed class the key maps to, when its tag is the element's (else ``None``).
        self.typed = typed
        self.context = context
        self.line = line
        #: The byte offset of the start tag's ``<``, and of what follows its ``>``.
        self.begin = begin
        self.stop = stop
        #: The element's place in the reader's document order (``-1``: the root's).
        self.place = place
        #: The character data read, or ``None`` before any.
        self.text: list[str] | None = None
        #: The children read so far (most elements have none: a shared empty list).
        self.children: list[Node] = _NO_CHILDREN
        #: Where each comment child begins and ends, by child index; ``None`` when none.
        self.comments: dict[int, tuple[int, int]] | None = None

    def add_child(self, child: Node) -> None:
        """Note a child."""
        if self.children is _NO_CHILDREN:
            self.children = [child]
        else:
            self.children.append(child)

    def pairs(self) -> list[tuple[str, str]]:
        """The attributes as ``(name, value)`` pairs."""
        flat = self.attributes
        return list(zip(flat[::2], flat[1::2], strict=True))

    def index_of(self, tag: str) -> int:
        """The 1-based position a ``tag`` child added now takes among the children of its tag."""
        return 1 + sum(1 for child in self.children if getattr(child, "tag", None) == tag)


#: What an element without children holds as its children (never appended to).
_NO_CHILDREN: list[Any] = []


def step_of(context: str | None, tag: str) -> tuple[str | None, str | None, Any]:
    """A ``tag`` element in ``context``: its schema key, its children's context, its class.

    The class is ``None`` unless the element is typed. Remembered in :data:`STEPS`.
    """
    key = child_key(context, tag)
    cls = CLASS_BY_KEY.get(key) if key is not None else None
    step = (
        key,
        children_context(key, context),
        cls if cls is not None and cls.tag == tag else None,
    )
    return STEPS.remember((context, tag), step)


#: Per parent context and tag, what :func:`step_of` found (hostile text could make any
#: number of tags, hence the bound).
STEPS: BoundedCache[tuple[str | None, str], tuple[str | None, str | None, Any]] = BoundedCache(4096)
