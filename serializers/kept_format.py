r"""The format-keeping writer: a loaded model written as it was read.

Each element that carries a :class:`~mjcf_model.serializers.layout.Layout` is written as its
source text, with only what changed edited in place (a changed value inside its
quotes, a removed attribute or child with the white space before it); an element
added in code is written in the canonical form (:mod:`mjcf_model.serializers.canonical`),
indented as its siblings.

>>> from mjcf_model import loads
>>> out: list[str] = []
>>> write_kept(loads("<mujoco>\n\t<option timestep='2e-3'/>\n</mujoco>"), out)
>>> "".join(out)
"<mujoco>\n\t<option timestep='2e-3'/>\n</mujoco>"
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from mjcf_model.nodes.base import AnyElement, Comment, Node, attribute_items
from mjcf_model.serializers.canonical import (
    ATTRIBUTE_ESCAPES,
    TEXT_ESCAPES,
    checked_element,
    write_canonical,
)
from mjcf_model.serializers.layout import (
    Layout,
    LayoutDetail,
    detail,
    layout_of,
    place_key,
    read_slots,
)
from mjcf_model.serializers.parsed_elements import holds_what_was_read, recorded_values
from mjcf_model.values import Value, format_value

__all__ = ["write_kept"]


_WHITE_SPACE = " \t\r\n"
#: The recorded value of an attribute the reader did not find (equal to no value).
_NOT_READ = object()
#: How far back the writer looks for the line an element starts on (bounded: linear).
_INDENT_LOOKBACK = 64


class _Style:
    """The line break and indentation unit of a file, for the elements added to it.

    Read from the root's gaps: the first one that breaks the line gives both; a
    root written on one line gives none (added elements stay on the line).
    """

    __slots__ = ("newline", "unit")

    def __init__(self, root: Layout) -> None:
        #: The file's line break.
        self.newline = "\n"
        #: One level of indentation.
        self.unit = "  "
        gaps = detail(root).gaps
        if not any("\n" in gap for gap in gaps):
            self.newline = self.unit = ""
            return
        document = root.document()
        margin = _indent_after(document.before) if document is not None else ""
        for gap in gaps[:-1]:
            line = _line_start(gap)
            if line is not None:
                self.newline = "\r\n" if line.startswith("\r") else "\n"
                indent = line.lstrip("\r\n")
                if indent.startswith(margin):
                    self.unit = indent[len(margin) :]
                break


def _line_start(gap: str) -> str | None:
    """The last line break of ``gap`` and the white space after it, or ``None``."""
    index = gap.rfind("\n")
    if index < 0:
        return None
    return ("\r\n" if index and gap[index - 1] == "\r" else "\n") + _indent_after(gap)


def _indent_after(text: str) -> str:
    """The white space that starts the last line of ``text``."""
    rest = text[text.rfind("\n") + 1 :]
    return rest[: len(rest) - len(rest.lstrip(" \t"))]


def _current_indent(out: list[str]) -> str:
    """The indentation of the line being written (looked for a bounded way back)."""
    for piece in out[: -_INDENT_LOOKBACK - 1 : -1]:
        if "\n" in piece:
            return _indent_after(piece)
    return ""


def write_kept(root: AnyElement, out: list[str]) -> None:
    """Append the text of ``root`` (it has a layout), the source text of what is unchanged.

    An explicit stack of pieces (text, or a node still to write), so any depth is written.
    """
    layout = layout_of(root)
    assert layout is not None
    style = _Style(layout)
    children = root.children
    before, after = "", style.newline
    document = layout.document()
    inner = document.inner_children(children) if document is not None else None
    if document is not None and inner is not None:
        before, after = document.before, document.after
        children = inner
    out.append(before)
    stack: list[Any] = [after]
    if root.tag == layout.tag:
        _open(root, layout, children, out, stack, style)
    else:
        stack.append(root)
    while stack:
        item = stack.pop()
        if type(item) is str:
            out.append(item)
        elif isinstance(item, Comment):
            out.append(f"<!--{item.text}-->")
        else:
            element = checked_element(item)
            kept = layout_of(element)
            if kept is not None and element.tag == kept.tag:
                _open(element, kept, element.children, out, stack, style)
            else:
                margin = _current_indent(out)
                block: list[str] = []
                write_canonical(element, style.unit, block, margin, style.newline)
                text = "".join(block)
                out.append(text[len(margin) : len(text) - len(style.newline)])


def _open(
    element: AnyElement,
    layout: Layout,
    children: tuple[Node, ...],
    out: list[str],
    stack: list[Any],
    style: _Style,
) -> None:
    """Write ``element``'s start tag to ``out``; push its gaps, children and end tag.

    An element that holds the children it was read with, with its own start tag
    and text unchanged, is written as its source text at once.
    """
    cut = detail(layout)
    start = _start_tag(element, layout, cut)
    same_text = element.text is layout.text or element.text == layout.text
    if children is layout.children and same_text and start is cut.start:
        out.append(layout.whole())
        return
    sources = cut.sources
    count = len(sources)
    if same_text and len(children) == count:
        for child, source in zip(children, sources, strict=True):
            token = getattr(child, "layout", child)
            if token is not source and place_key(token) != place_key(source):
                break
        else:
            out.append(start)
            gaps = cut.gaps
            comments = cut.comments
            stack.append(cut.end)
            stack.append(gaps[count])
            for index in range(count - 1, -1, -1):
                child = children[index]
                if isinstance(child, Comment):
                    stack.append(comments.get(index) or f"<!--{child.text}-->")
                else:
                    stack.append(child)
                stack.append(gaps[index])
            return
    pieces = _changed_content(element, layout, cut, children, _current_indent(out), style)
    end = cut.end
    if not end and len(pieces) > 1:  # an empty-element tag now holds something
        start, end = start[:-2].rstrip() + ">", f"</{element.tag}>"
    out.append(start)
    stack.append(end)
    stack.extend(reversed(pieces))


def _changed_content(
    element: AnyElement,
    layout: Layout,
    cut: LayoutDetail,
    children: tuple[Node, ...],
    indent: str,
    style: _Style,
) -> list[Any]:
    """The gaps and children of an element whose children or text changed, in order.

    Kept children keep the gap before them (of the gaps left where children were
    removed, the one with the most line breaks: no blank line is lost); an added
    child gets a line of its own, indented as its siblings. Stray text (mixed
    content) stays in its gaps while all of them are written; when the text
    changed, or a gap holding some is left out with a removed or replaced child
    (an ``<include>`` inlined), the element's whole text is written first instead.
    """
    gaps = cut.gaps
    sources = cut.sources
    count = len(sources)
    comments = cut.comments
    added = _added_gap(gaps, count, indent, style)
    pieces: list[Any] = []  # a gap, then each child and the gap after it
    written: set[int] = set()  # the gaps written, by index
    last = -1
    for child, index in zip(children, read_slots(cut, children), strict=True):
        if index > last:
            if last < 0 or index == last + 1:
                at = 0 if last < 0 else index
            else:
                at = max(range(index, last, -1), key=lambda i: gaps[i].count("\n"))
            written.add(at)
            last = index
            kept = comments.get(index) if isinstance(child, Comment) else None
            pieces += (gaps[at], kept or child)
        else:
            pieces += (added, child)
    if count:
        written.add(count)
        pieces.append(gaps[count])
    elif children:
        pieces.append(gaps[0] if "\n" in gaps[0] else style.newline + indent)
    else:
        written.add(0)
        pieces.append(gaps[0])
    text = element.text
    same_text = text is layout.text or text == layout.text
    if same_text and all(i in written or not gap.strip() for i, gap in enumerate(gaps)):
        return pieces
    for at in range(0, len(pieces), 2):  # the old text goes from every gap
        pieces[at] = _blank(pieces[at])
    if text is not None:
        pieces[0] = text.translate(TEXT_ESCAPES) + (pieces[0] if children else "")
    return pieces


def _blank(gap: str) -> str:
    """The white space that ends ``gap``: what is left of it without its text."""
    return gap[len(gap.rstrip()) :]


def _added_gap(gaps: Sequence[str], count: int, indent: str, style: _Style) -> str:
    """The gap before a child added among ``count`` children: a line like its siblings'."""
    for gap in gaps[:count]:
        line = _line_start(gap)
        if line is not None:
            return line
    if count:  # siblings on one line: one more there, separated as they are
        return _blank(gaps[1]) if count > 1 else ""
    return style.newline + indent + style.unit


def _start_tag(element: AnyElement, layout: Layout, cut: LayoutDetail) -> str:
    """The recorded start tag, with the attributes changed since edited in place."""
    if holds_what_was_read(element, layout, cut):
        return cut.start  # the fields stored and their values are the ones read
    if cut.getter is not None:
        spliced = _spliced_start(element, cut)
        if spliced is not None:
            return spliced
    values = recorded_values(cut, type(element), layout)
    items = attribute_items(element)
    names = cut.names
    if len(items) == len(names):
        for (name, value), recorded_name, recorded in zip(items, names, values, strict=True):
            if name != recorded_name or (value is not recorded and value != recorded):
                break
        else:
            return cut.start
    return _edited_start(cut, items)


def _value_spans(cut: LayoutDetail) -> list[tuple[int, int, int]]:
    """Where each attribute of the recorded start tag stands, worked out once.

    For each attribute (in ``cut.names`` order): where the white space before it begins,
    and where its value begins and ends (the closing quote's offset). The reader found
    the attributes, so each ``=`` after a value's closing quote is the next attribute's
    (a name holds no ``=``, and a value no quote of its own kind).
    """
    spans = cut.spans
    if spans is None:
        start = cut.start
        position = 1 + len(cut.tag)
        spans = []
        for _ in cut.names:
            quote = start.find("=", position) + 1
            while start[quote] in _WHITE_SPACE:
                quote += 1
            close = start.find(start[quote], quote + 1)
            spans.append((position, quote + 1, close))
            position = close + 1
        cut.spans = spans
    return spans


def _spliced_start(element: AnyElement, cut: LayoutDetail) -> str | None:
    """The recorded start tag with only the attributes changed since reading spliced in.

    For a typed element read with a field for each attribute (``cut.getter`` is set): each
    value is compared with the one read (the same object, or an equal one), a changed one
    replaces the text inside its quotes, a removed one goes with the white space before it,
    and an attribute set since reading goes after the last one, in field order, as
    :func:`_edited_start` writes them. ``None`` where :func:`_edited_start` must write the
    tag: the attribute order or ``extra`` changed.
    """
    held = element.__dict__
    names = cut.names
    if held.get("attribute_order", ()) != names:
        return None
    stored = cut.stored
    rank = type(element).__node_info__.rank
    new = held.keys() - stored  # usually none: the same fields, some of other values
    if "extra" in new:
        return None
    added = [key for key in new if key in rank]
    values = cut.values
    assert values is not None
    start = cut.start
    spans = _value_spans(cut)
    pieces: list[str] = []
    position = 0
    for index, field in enumerate(cut.fields):
        value = held.get(field)
        old = values[index]
        if value is old or value == old:
            continue
        begin, first, close = spans[index]
        if value is None:
            pieces.append(start[position:begin])  # removed, with the white space before it
        else:
            text = format_value(value).translate(ATTRIBUTE_ESCAPES)
            if start[close] == "'":
                text = text.replace("'", "&apos;")
            pieces += (start[position:first], text)
            position = close
            continue
        position = close + 1
    if added:
        at = spans[-1][2] + 1 if spans else 1 + len(cut.tag)
        pieces.append(start[position:at])
        position = at
        names_of = type(element).__node_info__.names
        for key in sorted(added, key=rank.__getitem__):
            text = format_value(held[key]).translate(ATTRIBUTE_ESCAPES)
            pieces.append(f' {names_of[rank[key]]}="{text}"')
    pieces.append(start[position:])
    return "".join(pieces)


def _edited_start(cut: LayoutDetail, items: list[tuple[str, Value]]) -> str:
    """The recorded start tag with ``items`` as its attributes.

    A changed value is replaced inside its quotes (the quote kept), a removed
    attribute goes with the white space before it, and an added one is written
    after the last attribute, as in the canonical form.
    """
    start = cut.start
    current = dict(items)
    assert cut.values is not None
    recorded = dict(zip(cut.names, cut.values, strict=True))
    position = 1 + len(cut.tag)
    pieces = [start[:position]]
    for name, (begin, value_start, value_end) in zip(cut.names, _value_spans(cut), strict=True):
        position = value_end + 1
        if name not in current:
            continue  # removed, with the white space before it
        value = current.pop(name)
        old = recorded.get(name, _NOT_READ)
        if value is old or value == old:
            pieces.append(start[begin:position])
            continue
        text = format_value(value).translate(ATTRIBUTE_ESCAPES)
        if start[value_end] == "'":
            text = text.replace("'", "&apos;")
        pieces += (start[begin:value_start], text, start[value_end])
    for name, value in current.items():
        pieces.append(f' {name}="{format_value(value).translate(ATTRIBUTE_ESCAPES)}"')
    pieces.append(start[position:])
    return "".join(pieces)
