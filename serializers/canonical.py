r"""The canonical form: escapes, attribute texts, and each element on its own line.

Shared by :mod:`mjcf_model.serializers.dumping` (``canonical=True``, and every model built
in code) and :mod:`mjcf_model.serializers.kept_format` (elements added to a loaded model).

>>> from mjcf_model import Geom
>>> out: list[str] = []
>>> write_canonical(Geom(name="a<b", size=(0.1,)), "  ", out)
>>> out
['<geom name="a&lt;b" size="0.1"/>\n']
"""

from __future__ import annotations

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, Comment, GenericElement, Node, attribute_items
from mjcf_model.values import format_value

__all__ = [
    "ATTRIBUTE_ESCAPES",
    "TEXT_ESCAPES",
    "attribute_texts",
    "checked_element",
    "write_canonical",
]

#: What an attribute value escapes: a raw tab or line break would be read back as a space.
ATTRIBUTE_ESCAPES = str.maketrans(
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
TEXT_ESCAPES = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;", "\r": "&#13;"})


def attribute_texts(element: AnyElement) -> list[tuple[str, str]]:
    """The element's attributes as ``(name, text)`` pairs, as they will be written.

    Examples:
        >>> from mjcf_model import Joint
        >>> attribute_texts(Joint(name="j", range=[-1, 1.5]))
        [('name', 'j'), ('range', '-1 1.5')]

    """
    if isinstance(element, GenericElement):
        return list(element.attributes.items())
    return [(name, format_value(value)) for name, value in attribute_items(element)]


def checked_element(node: Node) -> AnyElement:
    """``node``, checked to be an element; anything else cannot be written and raises."""
    if not isinstance(node, AnyElement):
        raise MjcfValueError(f"cannot write {type(node).__name__}: not an element or a comment")
    return node


#: Indentation stops growing below this depth (MuJoCo reads at most 499 levels from
#: one file), so deeper trees, which only includes can make, are not written with
#: indentation quadratic in their depth.
MAX_INDENTED_DEPTH = 500


def write_canonical(
    root: Node, indent: str, out: list[str], margin: str = "", newline: str = "\n"
) -> None:
    """Append the canonical text of ``root`` to ``out``, each line after ``margin``.

    An explicit stack, so any depth is written.
    """
    # Each entry is a node to write at a depth, or the closing tag of an element.
    stack: list[tuple[Node | str, int]] = [(root, 0)]
    pads: dict[int, str] = {}
    # Copies share their value objects (1,000 attached cans hold ~60): each is
    # formatted and escaped once per write. The value is kept with its text, so
    # an id is never mistaken for a freed object's.
    written: dict[int, tuple[object, str]] = {}

    def escaped(value: object) -> str:
        found = written.get(id(value))
        if found is not None and found[0] is value:
            return found[1]
        text = format_value(value).translate(ATTRIBUTE_ESCAPES)  # type: ignore[arg-type]
        written[id(value)] = (value, text)
        return text

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
        element = checked_element(node)
        tag = element.tag
        pairs = (
            element.attributes.items()
            if isinstance(element, GenericElement)
            else attribute_items(element)
        )
        attributes = "".join([f' {name}="{escaped(value)}"' for name, value in pairs])
        text = None if element.text is None else element.text.translate(TEXT_ESCAPES)
        if not element.children:
            if text is None:
                out.append(f"{pad}<{tag}{attributes}/>{newline}")
            else:
                out.append(f"{pad}<{tag}{attributes}>{text}</{tag}>{newline}")
            continue
        out.append(f"{pad}<{tag}{attributes}>{text or ''}{newline}")
        stack.append((tag, depth))
        stack.extend((child, depth + 1) for child in reversed(element.children))
