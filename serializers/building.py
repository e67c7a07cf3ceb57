"""Turning one parsed element (tag, attributes, children) into a node.

Both readers, the text reader and :func:`serializers.from_etree`, hand every
element to :func:`build_element`, so the two cannot disagree.

>>> node = build_element("body/geom", "geom", [("name", "g"), ("size", "0.1")], [], None)
>>> node.name, node.size
('g', (0.1,))
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from mjcf_model.base import (
    AnyElement,
    GenericElement,
    Node,
    TypedElement,
    build_node,
    field_table,
)
from mjcf_model.declaring import NodeInfo, tuple_getter
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.layout import Layout
from mjcf_model.registry import CLASS_BY_KEY
from mjcf_model.values import Unparsed

__all__ = ["ReadMemo", "build_element", "element_step", "element_text", "read_typed"]


def element_text(chunks: Sequence[str | None], has_children: bool) -> str | None:
    r"""The text an element keeps from its character data chunks.

    An element with only text keeps it exactly (``<text>`` content). Where text
    stands between child elements (mixed content, which MuJoCo ignores), each
    chunk is stripped and the non-blank ones are joined by a space, so that
    re-indenting on write does not change the text. White space alone is ``None``.

    Example:
        >>> element_text(["  a b "], False), element_text(["\n  ", " > ", "\n"], True)
        ('  a b ', '>')

    """
    if has_children:
        joined = " ".join(c.strip() for c in chunks if c and c.strip())
        return joined or None
    text = "".join(c for c in chunks if c)
    return text if text.strip() else None


def element_step(tag: str, attributes: Sequence[tuple[str, str]], index: int) -> str:
    """One step of an element path: ``body[@name='arm']`` or ``geom[3]`` (1-based).

    Example:
        >>> element_step("body", [("name", "arm")], 1), element_step("geom", [], 3)
        ("body[@name='arm']", 'geom[3]')

    """
    for key, value in attributes:
        if key == "name":
            return f"{tag}[@name={value!r}]"
    return tag if index == 1 else f"{tag}[{index}]"


#: Adds the file, line and element path to an error about the element being built.
Locate = Callable[[MjcfError], MjcfError]


def build_element(
    key: str | None,
    tag: str,
    attributes: Sequence[tuple[str, str]],
    children: Sequence[Node],
    text: str | None,
    locate: Locate | None = None,
    layout: Layout | None = None,
    memo: dict[tuple[Any, str], Any] | None = None,
) -> AnyElement:
    """Build the node for one element from its parsed parts.

    An attribute text its typed field cannot read is kept verbatim as an
    :class:`~mjcf_model.values.Unparsed` value (MuJoCo is the judge of what it
    reads: ``size="0x10"`` is 16 to it); using that value raises the error,
    located by ``locate``.

    Args:
        key: The element's schema key (see :func:`mjcf_model.namespaces.child_key`).
        tag: The XML tag.
        attributes: ``(name, text)`` pairs in source order.
        children: The already built child nodes.
        text: Character data, or ``None`` when there is none but white space.
        locate: Adds file, line and path to an error about this element.
        layout: The element's source text: the node keeps it, and its ``values``
            are set to the values the node holds for its ``names``.
        memo: One dict per document: each attribute text is converted once.

    Example:
        >>> build_element("body/geom", "geom", [("size", "1 x")], [], None).size
        Unparsed('1 x')

    """
    cls = CLASS_BY_KEY.get(key) if key is not None else None
    if cls is None or cls.tag != tag:
        generic = GenericElement(
            tag=tag, attributes=attributes, children=children, text=text, layout=layout
        )
        if layout is not None:  # the map holds the very strings given
            layout.values = tuple(generic.attributes.values())
        return generic
    table = field_table(cls)
    fields: dict[str, Any] = {}
    extra: list[tuple[str, str]] = []
    for name, value in attributes:
        field = table.get(name)
        if field is None:
            extra.append((name, value))
        else:
            fields[field] = value
    fields["attribute_order"] = (
        layout.names if layout is not None else tuple([name for name, _ in attributes])
    )
    if extra:
        fields["extra"] = extra
    if children:
        fields["children"] = children
    if text is not None:
        fields["text"] = text
    if layout is not None:
        fields["layout"] = layout
    try:
        node = build_node(cls, fields, memo=memo)
    except MjcfValueError:
        pass
    else:
        if layout is None or not attributes:
            return node
        return _with_values(node, table, attributes, layout, not extra)
    for name, value in attributes:  # only on the error path: find the values it cannot read
        field = table.get(name)
        if field is None:
            continue
        try:
            build_node(cls, {field: value})
        except MjcfValueError as error:
            problem: MjcfError = MjcfValueError(f"attribute {name!r}: {error.detail}")
            if locate is not None:
                problem = locate(problem)
            assert isinstance(problem, MjcfValueError)
            fields[field] = Unparsed(value, problem)
    node = build_node(cls, fields)
    return node if layout is None else _with_values(node, table, attributes, layout, not extra)


#: Per typed class, each ``(name, text)`` attribute read in one document, as its field
#: and converted, validated value (see :func:`read_typed`).
ReadMemo = dict[type, dict[tuple[str, str], tuple[str, Any]]]
_new = object.__new__
_set_dict = object.__setattr__


def read_typed(
    cls: type[TypedElement],
    attributes: list[str],
    children: Sequence[Node],
    layout: Layout,
    memo: ReadMemo,
) -> TypedElement | None:
    """The typed node of an element read from text, or ``None`` if :func:`build_element` must.

    The text reader's fast path for an element without character data: each
    ``(name, text)`` attribute is looked up in the document's ``memo`` (read
    once, then shared), and the node is given its fields at once. It returns
    ``None`` for an attribute without a field or a value its field cannot read,
    which :func:`build_element` keeps and explains. The result is the node
    :func:`build_element` builds (``tests/test_reading_paths.py`` checks it).

    Args:
        cls: The element's typed class.
        attributes: Attribute names and texts, alternating, in source order.
        children: The already built child nodes.
        layout: The element's source text (its ``names`` are the attribute names).
        memo: One per document.

    Example:
        >>> from mjcf_model import Geom
        >>> layout = Layout("geom", '<geom size="1"/>', ("",), "", ("size",), (), (), None)
        >>> read_typed(Geom, ["size", "1"], [], layout, {}) == Geom(size=[1.0])
        True

    """
    known = memo.get(cls)
    if known is None:
        known = memo[cls] = {}
    data: dict[str, Any] = {}
    texts = iter(attributes)
    for pair in zip(texts, texts, strict=True):
        found = known.get(pair)
        if found is None:
            found = _read_value(cls.__node_info__, pair)
            if found is None:
                return None
            known[pair] = found
        data[found[0]] = found[1]
    data["attribute_order"] = layout.names
    if children:
        data["children"] = tuple(children)
    data["layout"] = layout
    node = _new(cls)
    _set_dict(node, "__dict__", data)
    if attributes:
        _record_values(node, cls.__node_info__.table, layout)
    return node


def _read_value(info: NodeInfo, pair: tuple[str, str]) -> tuple[str, Any] | None:
    """The field and the value one attribute text gives, or ``None`` if it gives none."""
    name, text = pair
    field = info.table.get(name)
    if field is None:
        return None
    converter = info.converters.get(field)
    try:
        value = text if converter is None else converter(text)
        checks = info.validators.get(field)
        if checks is not None:
            checks[0](None, checks[1], value)
    except MjcfValueError:
        return None
    return None if value is None else (field, value)


#: Fields set on a node after it is read (the root's folder), left out of ``Layout.stored``.
LATER_FIELDS = frozenset({"base_dir"})
#: Per class, attribute names (all typed fields) and kind of content: a getter of their
#: values as a tuple, and the fields such an element stores.
_VALUE_GETTERS: dict[
    tuple[type, tuple[str, ...], bool, bool],
    tuple[Callable[[Any], tuple[Any, ...]], frozenset[str]],
] = {}
#: Past this many, the getters are forgotten (hostile text could make any number).
_MAX_VALUE_GETTERS = 4096


def _with_values(
    node: TypedElement,
    table: dict[str, str],
    attributes: Sequence[tuple[str, str]],
    layout: Layout,
    all_typed: bool,
) -> TypedElement:
    """``node``, its layout given the values it holds for each of ``attributes``.

    An attribute without a field (``all_typed`` false) holds the given text.
    """
    if not all_typed:
        layout.values = tuple(
            [
                value if field is None else getattr(node, field)
                for field, value in [(table.get(name), value) for name, value in attributes]
            ]
        )
        return node
    _record_values(node, table, layout)
    return node


def _record_values(node: TypedElement, table: dict[str, str], layout: Layout) -> None:
    """Give ``layout`` the values ``node`` holds for its attributes, and what it stores.

    Every attribute of the layout has a field (``table`` maps it). The getter and
    the set of stored fields are made once per class, attribute names and kind of
    content, and shared.
    """
    data = node.__dict__
    key = (type(node), layout.names, "children" in data, "text" in data)
    known = _VALUE_GETTERS.get(key)
    if known is None:
        if len(_VALUE_GETTERS) >= _MAX_VALUE_GETTERS:
            _VALUE_GETTERS.clear()
        known = _VALUE_GETTERS[key] = (
            tuple_getter(tuple(table[n] for n in layout.names)),
            frozenset(data.keys() - LATER_FIELDS),
        )
    getter, stored = known
    layout.values = getter(node)
    if stored != data.keys():  # a value read as None (not stored): not the usual fields
        stored = frozenset(data.keys() - LATER_FIELDS)
    layout.getter, layout.stored = getter, stored
