"""Writing MJCF: nodes into text, files and ElementTree.

The mirror of :mod:`serializers.reader`. A loaded model is written as it was
read: each element that carries a :class:`~mjcf_model.layout.Layout` is written
as its source text, with only what changed edited in place, and an element
added in code is written in the canonical form, indented to fit. The canonical
form (``canonical=True``, and every model built in code) writes each element on
its own line, indented by ``indent``. Attribute values are formatted by
:func:`mjcf_model.values.format_value`, the one place numbers become text, and
come out in the order they had in the source.

>>> from mjcf_model import Geom, Mujoco, Worldbody
>>> print(dumps(Mujoco(children=[Worldbody(children=[Geom(size=[0.1])])])), end="")
<mujoco>
  <worldbody>
    <geom size="0.1"/>
  </worldbody>
</mujoco>
"""

from __future__ import annotations

import contextlib
import os
import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from pathlib import Path
from typing import IO, Any

from mjcf_model.base import AnyElement, Comment, Element, GenericElement, Node, attribute_items
from mjcf_model.compiling import inlined
from mjcf_model.errors import MjcfValueError
from mjcf_model.layout import Layout
from mjcf_model.nodes.root import Mujoco
from mjcf_model.provenance import Folders, file_references, relocated
from mjcf_model.traversal import keyed_walk
from mjcf_model.values import Value, format_value

__all__ = ["attribute_texts", "dump", "dumps", "to_etree"]

_ATTRIBUTE_ESCAPES = str.maketrans(
    {
        "&": "&amp;",
        "<": "&lt;",
        ">": "&gt;",
        '"': "&quot;",
        "\n": "&#10;",
        "\r": "&#13;",
        "\t": "&#9;",
    }
)
#: A carriage return in text is written as a reference: XML reads a raw one as a line feed.
_TEXT_ESCAPES = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;", "\r": "&#13;"})


def attribute_texts(element: AnyElement) -> list[tuple[str, str]]:
    """The element's attributes as ``(name, text)`` pairs, as they will be written.

    Example:
        >>> from mjcf_model import Joint
        >>> attribute_texts(Joint(name="j", range=[-1, 1.5]))
        [('name', 'j'), ('range', '-1 1.5')]

    """
    if isinstance(element, GenericElement):
        return list(element.attributes.items())
    return [(name, format_value(value)) for name, value in attribute_items(element)]


def _element(node: Node) -> AnyElement:
    if not isinstance(node, AnyElement):
        raise MjcfValueError(f"cannot write {type(node).__name__}: not an element or a comment")
    return node


#: Indentation stops growing below this depth (MuJoCo reads at most 499 levels from
#: one file), so deeper trees, which only includes can make, are not written with
#: indentation quadratic in their depth.
MAX_INDENTED_DEPTH = 500


def _write(root: Node, indent: str, out: list[str], margin: str = "", newline: str = "\n") -> None:
    """Append the canonical text of ``root`` to ``out``, each line after ``margin``.

    An explicit stack, so any depth is written.
    """
    # Each entry is a node to write at a depth, or the closing tag of an element.
    stack: list[tuple[Node | str, int]] = [(root, 0)]
    pads: dict[int, str] = {}
    while stack:
        node, depth = stack.pop()
        pad = pads.get(depth)
        if pad is None:
            pad = pads[depth] = margin + indent * min(depth, MAX_INDENTED_DEPTH)
        if isinstance(node, str):
            out.append(f"{pad}</{node}>{newline}")
            continue
        if isinstance(node, Comment):
            out.append(f"{pad}<!--{node.text}-->{newline}")
            continue
        element = _element(node)
        tag = element.tag
        attributes = "".join(
            f' {name}="{text.translate(_ATTRIBUTE_ESCAPES)}"'
            for name, text in attribute_texts(element)
        )
        text = None if element.text is None else element.text.translate(_TEXT_ESCAPES)
        if not element.children:
            if text is None:
                out.append(f"{pad}<{tag}{attributes}/>{newline}")
            else:
                out.append(f"{pad}<{tag}{attributes}>{text}</{tag}>{newline}")
            continue
        out.append(f"{pad}<{tag}{attributes}>{text or ''}{newline}")
        stack.append((tag, depth))
        stack.extend((child, depth + 1) for child in reversed(element.children))


def dumps(node: Node, *, indent: str = "  ", canonical: bool = False) -> str:
    r"""Write a node (usually a whole :class:`~mjcf_model.Mujoco`) as MJCF text.

    A loaded node is written as it was read (line breaks, indentation, quotes,
    number spellings, comments, the XML declaration), with only what was
    changed since rewritten; a node built in code is written in the canonical form.

    Args:
        node: The node to write.
        indent: The indentation of one nesting level in the canonical form.
        canonical: Write the canonical form even for a loaded node, as a formatter would.

    Example:
        >>> from mjcf_model import Site
        >>> dumps(Site(name="tip", pos=(0, 0, 0.1)))
        '<site name="tip" pos="0 0 0.1"/>\n'
        >>> from serializers import loads
        >>> model = loads("<mujoco>\n\n  <option timestep='2e-3'/>\n</mujoco>\n")
        >>> dumps(model)
        "<mujoco>\n\n  <option timestep='2e-3'/>\n</mujoco>\n"
        >>> dumps(model, canonical=True)
        '<mujoco>\n  <option timestep="0.002"/>\n</mujoco>\n'

    """
    out: list[str] = []
    if canonical or not isinstance(node, Element) or node.layout is None:
        _write(node, indent, out)
    else:
        _write_kept(node, out)  # type: ignore[arg-type]
    return "".join(out)


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
        if not any("\n" in gap for gap in root.gaps):
            self.newline = self.unit = ""
            return
        document = root.document
        margin = _indent_after(document.before) if document is not None else ""
        for gap in root.gaps[:-1]:
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


def _write_kept(root: AnyElement, out: list[str]) -> None:
    """Append the text of ``root`` (it has a layout), the source text of what is unchanged.

    An explicit stack of pieces (text, or a node still to write), so any depth is written.
    """
    layout = root.layout
    assert layout is not None
    style = _Style(layout)
    children = root.children
    before, after = "", style.newline
    document = layout.document
    if document is not None:
        lead, trail = document.before_comments, document.after_comments
        inner = len(children) - len(trail)
        if (
            inner >= len(lead)
            and all(a is b for a, b in zip(children, lead, strict=False))
            and all(a is b for a, b in zip(children[inner:], trail, strict=True))
        ):
            before, after = document.before, document.after
            children = children[len(lead) : inner]
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
            element = _element(item)
            kept = element.layout
            if kept is not None and element.tag == kept.tag:
                _open(element, kept, element.children, out, stack, style)
            else:
                margin = _current_indent(out)
                block: list[str] = []
                _write(element, style.unit, block, margin, style.newline)
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
    """Write ``element``'s start tag to ``out``; push its gaps, children and end tag."""
    sources = layout.sources
    count = len(sources)
    if (element.text is layout.text or element.text == layout.text) and len(children) == count:
        for child, source in zip(children, sources, strict=True):
            if getattr(child, "layout", child) is not source:
                break
        else:
            out.append(_start_tag(element, layout))
            gaps = layout.gaps
            comments = layout.comments or {}
            stack.append(layout.end)
            stack.append(gaps[count])
            for index in range(count - 1, -1, -1):
                child = children[index]
                if isinstance(child, Comment):
                    stack.append(comments.get(index) or f"<!--{child.text}-->")
                else:
                    stack.append(child)
                stack.append(gaps[index])
            return
    pieces = _changed_content(element, layout, children, _current_indent(out), style)
    start, end = _start_tag(element, layout), layout.end
    if not end and len(pieces) > 1:  # an empty-element tag now holds something
        start, end = start[:-2].rstrip() + ">", f"</{element.tag}>"
    out.append(start)
    stack.append(end)
    stack.extend(reversed(pieces))


def _changed_content(
    element: AnyElement, layout: Layout, children: tuple[Node, ...], indent: str, style: _Style
) -> list[Any]:
    """The gaps and children of an element whose children or text changed, in order.

    Kept children keep the gap before them (of the gaps left where children were
    removed, the one with the most line breaks: no blank line is lost); an added
    child gets a line of its own, indented as its siblings.
    """
    gaps = list(layout.gaps)
    text = element.text
    if not (text is layout.text or text == layout.text):
        gaps = [gap[len(gap.rstrip()) :] for gap in gaps]  # the old text goes
        if text is not None:
            gaps[0] = text.translate(_TEXT_ESCAPES) + gaps[0]
    sources = layout.sources
    count = len(sources)
    slots = {id(source): index for index, source in enumerate(sources)}
    comments = layout.comments or {}
    added = _added_gap(gaps, count, indent, style)
    pieces: list[Any] = []
    last = -1
    for child in children:
        token = getattr(child, "layout", child)
        index = slots.get(id(token), -1) if token is not None else -1
        if index > last:
            if last < 0 or index == last + 1:
                gap = gaps[0] if last < 0 else gaps[index]
            else:
                gap = max(reversed(gaps[last + 1 : index + 1]), key=lambda g: g.count("\n"))
            last = index
            kept = comments.get(index) if isinstance(child, Comment) else None
            pieces += (gap, kept or child)
        else:
            pieces += (added, child)
    if count:
        pieces.append(gaps[count])
    elif children:
        pieces.append(gaps[0] if "\n" in gaps[0] else style.newline + indent)
    else:
        pieces.append(gaps[0])
    return pieces


def _added_gap(gaps: list[str], count: int, indent: str, style: _Style) -> str:
    """The gap before a child added among ``count`` children: a line like its siblings'."""
    for gap in gaps[:count]:
        line = _line_start(gap)
        if line is not None:
            return line
    if count:  # siblings on one line: one more there, separated as they are
        return gaps[1] if count > 1 else ""
    return style.newline + indent + style.unit


def _start_tag(element: AnyElement, layout: Layout) -> str:
    """The recorded start tag, with the attributes changed since edited in place."""
    getter = layout.getter
    if (
        getter is not None
        and len(element.__dict__) == layout.size
        and getter(element) == layout.values
    ):
        return layout.start  # the fields stored and their values are the ones read
    items = attribute_items(element)
    names, values = layout.names, layout.values
    if len(items) == len(names):
        for (name, value), recorded_name, recorded in zip(items, names, values, strict=True):
            if name != recorded_name or (value is not recorded and value != recorded):
                break
        else:
            return layout.start
    return _edited_start(layout, items)


def _attribute_spans(start: str, position: int) -> Iterator[tuple[int, str, int, int]]:
    """Each attribute of a start tag from ``position`` on, as offsets into ``start``.

    Yields where the white space before the attribute begins, its name, and
    where its value begins and ends (the closing quote's offset).
    """
    while True:
        begin = position
        while position < len(start) and start[position] in _WHITE_SPACE:
            position += 1
        equals = start.find("=", position)
        if position == begin or equals < 0:
            return
        name = start[position:equals].rstrip(_WHITE_SPACE)
        quote = equals + 1
        while start[quote] in _WHITE_SPACE:
            quote += 1
        close = start.find(start[quote], quote + 1)
        yield begin, name, quote + 1, close
        position = close + 1


def _edited_start(layout: Layout, items: list[tuple[str, Value]]) -> str:
    """The recorded start tag with ``items`` as its attributes.

    A changed value is replaced inside its quotes (the quote kept), a removed
    attribute goes with the white space before it, and an added one is written
    after the last attribute, as in the canonical form.
    """
    start = layout.start
    current = dict(items)
    recorded = dict(zip(layout.names, layout.values, strict=True))
    position = 1 + len(layout.tag)
    pieces = [start[:position]]
    for begin, name, value_start, value_end in _attribute_spans(start, position):
        position = value_end + 1
        if name not in current:
            continue  # removed, with the white space before it
        value = current.pop(name)
        old = recorded.get(name, _NOT_READ)
        if value is old or value == old:
            pieces.append(start[begin:position])
            continue
        text = format_value(value).translate(_ATTRIBUTE_ESCAPES)
        if start[value_end] == "'":
            text = text.replace("'", "&apos;")
        pieces += (start[begin:value_start], text, start[value_end])
    for name, value in current.items():
        pieces.append(f' {name}="{format_value(value).translate(_ATTRIBUTE_ESCAPES)}"')
    pieces.append(start[position:])
    return "".join(pieces)


def dump(
    node: Node,
    target: str | os.PathLike[str] | IO[str],
    *,
    indent: str = "  ",
    canonical: bool = False,
) -> None:
    r"""Write a node to a file path or an open text file.

    Writing a loaded model to a path in another folder (or to an open file that
    names its path) relocates it: relative
    file paths (meshes, textures, includes...) are rewritten to name the same
    files from the new folder (:func:`mjcf_model.provenance.relocated`). Written
    back to its own folder, the text is unchanged. A model built in code has no
    folder of its own: its paths are written as they are.

    Writing to a path is atomic: the text goes to a temporary file beside the
    target, which then replaces it. If anything fails, the old file is untouched
    and no partial file is left. The text is written as :func:`dumps` gives it
    (line breaks are not translated), encoded as UTF-8.

    Args:
        node: The node to write.
        target: A path, or a file object opened for writing text.
        indent: The indentation of one nesting level in the canonical form.
        canonical: Write the canonical form even for a loaded node (see :func:`dumps`).

    Example:
        >>> import tempfile, pathlib
        >>> from mjcf_model import Mujoco
        >>> path = pathlib.Path(tempfile.mkdtemp()) / "out.xml"
        >>> dump(Mujoco(model="m"), path)
        >>> path.read_text()
        '<mujoco model="m"/>\n'

    """
    if not isinstance(target, (str, os.PathLike)):
        name = getattr(target, "name", None)  # an open file names its path, as load reads it
        if isinstance(name, str) and not name.startswith("<"):
            node = _relocated_for(node, Path(name).parent)
        target.write(dumps(node, indent=indent, canonical=canonical))
        return
    path = Path(target)
    text = dumps(_relocated_for(node, path.parent), indent=indent, canonical=canonical)
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(handle, "w", encoding="utf-8", newline="") as stream:
            stream.write(text)
            stream.flush()
            os.fsync(stream.fileno())
        if path.exists():
            with contextlib.suppress(OSError):
                os.chmod(temporary, path.stat().st_mode & 0o7777)
        os.replace(temporary, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        raise


def _relocated_for(node: Node, folder: Path) -> Node:
    """A loaded model with its paths rewritten to resolve from ``folder``; other nodes as given."""
    if isinstance(node, Mujoco) and node.base_dir is not None:
        return _relocated(node, folder)
    return node


def _relocated(model: Mujoco, folder: Path) -> Mujoco:
    """``model`` with its paths rewritten to resolve from ``folder``.

    A kept ``<include>`` is not rewritten, and its file may set the compiler's
    folders: they are read from the whole model. A path in an included file that
    MuJoCo found under the main model's folder is looked for under the new folder
    once the model moves: that raises.
    """
    if not any(key == "include" for _, key, _ in keyed_walk(model)):
        return relocated(model, folder)
    whole = inlined(model)
    moved = relocated(model, folder, source=Folders.of(whole))
    before = [r.path for r in file_references(whole)]
    after = list(file_references(inlined(moved)))
    for reference, path in zip(after, before, strict=False):
        if reference.path != path:
            raise MjcfValueError(
                f"an included file names {reference.text!r}, found under the model's folder "
                f"({str(path)!r}); written elsewhere the model would look for "
                f"{str(reference.path)!r}: load it with inline_includes=True, or export it"
            )
    if len(after) != len(before):
        raise MjcfValueError(
            "written elsewhere, the model's included files would name other files: load it "
            "with inline_includes=True, or export it"
        )
    return moved


def to_etree(node: Node) -> ET.Element:
    """Convert a node and its subtree to ElementTree.

    Comments become ``ET.Comment`` elements; attribute order is kept.

    Example:
        >>> from mjcf_model import Body, Geom
        >>> ET.tostring(to_etree(Body(name="b", children=[Geom(size=[1])])), encoding="unicode")
        '<body name="b"><geom size="1" /></body>'

    """
    root = _etree_element(node)
    stack = [(node, root)]  # an explicit stack, so any depth is converted
    while stack:
        parent, element = stack.pop()
        if not isinstance(parent, AnyElement):
            continue
        for child in parent.children:
            converted = _etree_element(child)
            element.append(converted)
            stack.append((child, converted))
    return root


def _etree_element(node: Node) -> ET.Element:
    """One node as an ElementTree element, without its children."""
    if isinstance(node, Comment):
        comment: ET.Element = ET.Comment(node.text)  # type: ignore[assignment]
        return comment
    if not isinstance(node, AnyElement):
        raise MjcfValueError(f"cannot convert {type(node).__name__}: not an element or a comment")
    element = ET.Element(node.tag, dict(attribute_texts(node)))
    element.text = node.text
    return element
