r"""The tidy form: a loaded file's layout made regular, and nothing else changed.

What ``mjcf-model fmt`` writes (:mod:`mjcf_model.tools.formatting`), as a code
formatter rewrites code: each element on a line of its own, indented by its depth;
a start tag longer than the width wrapped one attribute a line; and, of what the
author chose, everything kept:

* attribute values as written (``8.2904e-7`` stays so; white space inside a list of
  numbers becomes one space), unless ``normalize_numbers`` asks for the shortest
  form of every number (:func:`mjcf_model.values.format_float`);
* the attributes' order, and every comment where it stands (a comment that
  followed an element on its line stays on that line);
* one blank line between two elements (or comments) where the file had one or
  more; blank lines just after a start tag or before an end tag go;
* what stands before and after the root element (the XML declaration, comments).

Elements added in code, without a layout, are written as the canonical form writes
them. The tidy form of a tidy text is that text (the formatter is idempotent).

>>> from mjcf_model import loads
>>> text = '<mujoco><option timestep="2e-3"/>\n\n\n<worldbody/><!-- the world --></mujoco>'
>>> print(tidy_text(loads(text)), end="")
<mujoco>
  <option timestep="2e-3"/>
<BLANKLINE>
  <worldbody/> <!-- the world -->
</mujoco>
>>> print(tidy_text(loads(text), normalize_numbers=True).splitlines()[1])
  <option timestep="0.002"/>
"""

from __future__ import annotations

from typing import Any

from mjcf_model.nodes.base import AnyElement, Comment, Node, attribute_items
from mjcf_model.serializers.canonical import ATTRIBUTE_ESCAPES, TEXT_ESCAPES, checked_element
from mjcf_model.serializers.layout import Layout, detail, layout_of, read_slots
from mjcf_model.serializers.parsed_elements import recorded_values
from mjcf_model.values import Unparsed, format_value

__all__ = ["DEFAULT_WIDTH", "tidy_text"]

#: The longest line a start tag may take before it is wrapped, one attribute a line.
DEFAULT_WIDTH = 100


def tidy_text(
    root: Node,
    *,
    indent: str = "  ",
    width: int = DEFAULT_WIDTH,
    normalize_numbers: bool = False,
) -> str:
    """The tidy text of ``root`` (see the module's description).

    Args:
        root: The element to write, usually a model loaded from a file.
        indent: One level of indentation.
        width: Wrap a start tag whose line would be longer than this.
        normalize_numbers: Write every number in its shortest form instead of as read.

    Examples:
        >>> from mjcf_model import Geom
        >>> print(tidy_text(Geom(name="g", size=(1, 2, 3)), width=20), end="")
        <geom
          name="g"
          size="1 2 3"/>

    """
    writer = _Tidy(indent, width, normalize_numbers)
    element = checked_element(root)
    layout = layout_of(element)
    document = layout.document() if layout is not None else None
    children = element.children
    before = after = ""
    inner = document.inner_children(children) if document is not None else None
    if document is not None and inner is not None:
        children = inner
        before, after = _outside(document.before), _outside(document.after)
        if before and document.before[len(document.before.rstrip()) :].count("\n") > 1:
            before += "\n"  # the blank line before the root
        lead = document.after[: len(document.after) - len(document.after.lstrip())]
        if after and lead.count("\n") > 1:
            after = "\n" + after
    writer.out.append(before)
    writer.element(element, children, 0)
    writer.out.append(after)
    return "".join(writer.out)


def _outside(text: str) -> str:
    """What stands before or after the root, its lines' ends trimmed and blank lines merged."""
    lines = [line.rstrip() for line in text.strip().splitlines()]
    kept = [line for index, line in enumerate(lines) if line or lines[index - 1]]
    return "".join(line + "\n" for line in kept)


class _Tidy:
    """The tidy writer's settings and output (an explicit stack: any depth is written)."""

    def __init__(self, indent: str, width: int, normalize_numbers: bool) -> None:
        self.indent = indent
        self.width = width
        self.normalize_numbers = normalize_numbers
        self.out: list[str] = []

    def element(self, root: AnyElement, children: tuple[Node, ...], depth: int) -> None:
        """Write ``root``, whose children to write are ``children``, at ``depth``."""
        # Each entry: an element or comment with its depth and the gap read before
        # it, or the text that closes an element.
        stack: list[tuple[Node, int, str, tuple[Node, ...] | None] | str] = [
            (root, depth, "\n", children)
        ]
        first = True
        while stack:
            entry = stack.pop()
            if isinstance(entry, str):
                self.out.append(entry)
                continue
            node, level, gap, own = entry
            pad = self.indent * level
            if isinstance(node, Comment):
                if "\n" not in gap and not first:  # it followed an element on its line
                    self.out[-1] = self.out[-1].rstrip("\n") + f" <!--{node.text}-->\n"
                else:
                    self.out.append(_blank(gap, first) + f"{pad}<!--{node.text}-->\n")
                first = False
                continue
            element = checked_element(node)
            kids = element.children if own is None else own
            start = self._start_tag(element, pad, closed=not kids and element.text is None)
            self.out.append(_blank(gap, first) + start)
            first = False
            if not kids:
                if element.text is not None:
                    self.out.append(f"{element.text.translate(TEXT_ESCAPES)}</{element.tag}>\n")
                else:
                    self.out.append("\n")
                continue
            self.out.append((element.text or "").translate(TEXT_ESCAPES) + "\n")
            stack.append(f"{pad}</{element.tag}>\n")
            gaps = _gaps_before(element, kids)
            for index in range(len(kids) - 1, -1, -1):
                gap_before = gaps[index] if index else "\n"  # none after the start tag
                stack.append((kids[index], level + 1, gap_before, None))

    def _start_tag(self, element: AnyElement, pad: str, *, closed: bool) -> str:
        """The start tag at ``pad``, wrapped when too long (``closed``: ``/>``)."""
        pairs = [f'{name}="{text}"' for name, text in self._attribute_texts(element)]
        end = "/>" if closed else ">"
        line = f"{pad}<{element.tag}" + "".join(" " + pair for pair in pairs) + end
        if len(pairs) < 2 or len(line) <= self.width:
            return line
        inner = pad + self.indent
        return f"{pad}<{element.tag}\n" + "\n".join(inner + pair for pair in pairs) + end

    def _attribute_texts(self, element: AnyElement) -> list[tuple[str, str]]:
        """Each attribute and its escaped text: as read, where its value is unchanged."""
        items = attribute_items(element)
        read = _read_texts(element)
        texts = []
        for name, value in items:
            found = read.get(name)
            if found is not None and (found[0] is value or found[0] == value):
                text = found[1]
                if not isinstance(value, (str, Unparsed)):  # numbers: their spelling
                    numbers = format_value(value) if self.normalize_numbers else None
                    text = numbers or " ".join(text.split())
            else:
                text = format_value(value)
            texts.append((name, text.translate(ATTRIBUTE_ESCAPES)))
        return texts


def _read_texts(element: AnyElement) -> dict[str, tuple[Any, str]]:
    """Each attribute the element was read with: the value it was read as and its text."""
    layout = layout_of(element)
    if layout is None or layout.tag != element.tag:
        return {}
    cut = detail(layout)
    values = recorded_values(cut, type(element), layout)
    return {
        name: (value, text) for name, value, text in zip(cut.names, values, cut.texts, strict=True)
    }


def _gaps_before(element: AnyElement, children: tuple[Node, ...]) -> list[str]:
    """The white space read before each child (a line break for a child added since)."""
    layout: Layout | None = layout_of(element)
    if layout is None or layout.tag != element.tag:
        return ["\n"] * len(children)
    cut = detail(layout)
    return ["\n" if index < 0 else cut.gaps[index] for index in read_slots(cut, children)]


def _blank(gap: str, first: bool) -> str:
    """A blank line where the gap read held one (never before the first line written)."""
    return "\n" if not first and gap.count("\n") > 1 else ""
