"""Turning one parsed element (tag, attributes, children) into a node.

Both readers, the text reader and :func:`mjcf_model.serializers.from_etree`, hand every
element to :func:`build_element`, so the two cannot disagree.

>>> node = build_element("body/geom", "geom", [("name", "g"), ("size", "0.1")], [], None)
>>> node.name, node.size
('g', (0.1,))
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from mjcf_model.caching import BoundedCache
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    GenericElement,
    Node,
    TypedElement,
    attribute_text,
    build_node,
    field_table,
    get_attribute,
)
from mjcf_model.nodes.node_info import NodeInfo, tuple_getter
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.serializers.layout import Layout, LayoutDetail, detail, layout_of
from mjcf_model.values import Unparsed

__all__ = [
    "ReadMemo",
    "build_element",
    "element_step",
    "element_text",
    "read_typed",
    "written_text",
]


def element_text(chunks: Sequence[str | None], has_children: bool) -> str | None:
    r"""The text an element keeps from its character data chunks.

    An element with only text keeps it exactly (``<text>`` content). Where text
    stands between child elements (mixed content, which MuJoCo ignores), each
    chunk is stripped and the non-blank ones are joined by a space, so that
    re-indenting on write does not change the text. White space alone is ``None``.

    Examples:
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

    Examples:
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
        key: The element's schema key (see :func:`mjcf_model.schema.namespaces.child_key`).
        tag: The XML tag.
        attributes: ``(name, text)`` pairs in source order.
        children: The already built child nodes.
        text: Character data, or ``None`` when there is none but white space.
        locate: Adds file, line and path to an error about this element.
        layout: Where the element was read: the node keeps it.
        memo: One dict per document: each attribute text is converted once.

    Examples:
        >>> build_element("body/geom", "geom", [("size", "1 x")], [], None).size
        Unparsed('1 x')

    """
    cls = CLASS_BY_KEY.get(key) if key is not None else None
    if cls is None or cls.tag != tag:
        return GenericElement(
            tag=tag, attributes=attributes, children=children, text=text, layout=layout
        )
    table = field_table(cls)
    fields: dict[str, Any] = {}
    extra: list[tuple[str, str]] = []
    for name, value in attributes:
        field = table.get(name)
        if field is None:
            extra.append((name, value))
        else:
            fields[field] = value
    fields["attribute_order"] = tuple([name for name, _ in attributes])
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
        return node
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
    return build_node(cls, fields)


#: Per typed class, each ``(name, text)`` attribute read in one document, as its field
#: and converted, validated value (see :func:`read_typed`).
ReadMemo = dict[type, dict[tuple[str, str], tuple[str, Any]]]

#: Attribute text longer than this is converted after the whole file is parsed (see
#: :func:`read_typed`'s ``deferred``).
DEFERRED_TEXT = 1 << 20

#: An attribute whose value is converted later: its field, name, text and reader.
Deferred = tuple[str, str, str, Callable[[str], Any]]
_new = object.__new__
_set_dict = object.__setattr__


def read_typed(
    cls: type[TypedElement],
    attributes: Sequence[str],
    children: tuple[Node, ...],
    layout: Layout,
    memo: ReadMemo,
    names: dict[tuple[str, ...], tuple[str, ...]],
    deferred: list[Deferred] | None = None,
) -> TypedElement | None:
    """The typed node of an element read from text, or ``None`` if :func:`build_element` must.

    The text reader's fast path for an element without character data: each
    ``(name, text)`` attribute is looked up in the document's ``memo`` (read
    once, then shared), and the node is given its fields at once. It returns
    ``None`` for an attribute without a field or a value its field cannot read,
    which :func:`build_element` keeps and explains. The result is the node
    :func:`build_element` builds (``tests/serializers/test_parsed_elements.py`` checks it).

    Args:
        cls: The element's typed class.
        attributes: Attribute names and texts, alternating, in source order.
        children: The already built child nodes.
        layout: Where the element was read.
        memo: One per document.
        names: One per document: each tuple of attribute names, shared.
        deferred: Where to put the attributes of over :data:`DEFERRED_TEXT` characters
            instead of converting them: the node holds their text until the caller
            converts them (a 50 MB number list becomes floats once expat has let go
            of its own copies of the text, which halves the peak memory of reading).

    Examples:
        >>> from mjcf_model import Geom
        >>> from mjcf_model.serializers.layout import SourceText
        >>> origin = SourceText(b'<geom size="1"/>')
        >>> layout = Layout(origin, "geom", 0, 16, 16, ["size", "1"], (), None)
        >>> read_typed(Geom, ["size", "1"], (), layout, {}, {}) == Geom(size=[1.0])
        True

    """
    known = memo.get(cls)
    if known is None:
        known = memo[cls] = {}
    info = cls.__node_info__
    plain, readers = info.plain_names, info.readers
    data: dict[str, Any] = {}
    texts = iter(attributes)
    for name, text in zip(texts, texts):  # noqa: B905 (expat gives names and texts in pairs)
        field = plain.get(name)
        if field is not None:
            data[field] = text  # expat gives only text XML can carry: nothing to check
            continue
        pair = (name, text)
        found = known.get(pair)
        if found is None:
            reading = readers.get(name)
            if reading is None:
                return None  # an attribute without a field
            if deferred is not None and len(text) > DEFERRED_TEXT:
                deferred.append((reading[0], name, text, reading[1]))
                data[reading[0]] = text
                continue
            try:
                value = reading[1](text)
            except MjcfValueError:
                return None  # kept verbatim, and explained, by build_element
            if value is None:
                return None
            found = known[pair] = (reading[0], value)
        data[found[0]] = found[1]
    order = tuple(attributes[::2])
    data["attribute_order"] = names.setdefault(order, order)
    if children:
        data["children"] = children
    data["layout"] = layout
    node = _new(cls)
    _set_dict(node, "__dict__", data)
    return node


#: Fields set on a node after it is read (the root's folder), left out of the stored fields.
LATER_FIELDS = frozenset({"base_dir"})


def recorded_values(detail: LayoutDetail, cls: type[AnyElement], layout: Layout) -> tuple[Any, ...]:
    """The values an element of class ``cls`` held for its attributes when it was read.

    Looked up in what the reader read from the file (the same objects the nodes
    got), or worked out again from the texts as the reader works them out; kept
    in ``detail`` with the writer's fast check (:attr:`LayoutDetail.getter` and
    :attr:`LayoutDetail.stored`, for a typed element whose attributes all have fields).

    Examples:
        >>> from mjcf_model import Geom
        >>> from mjcf_model.serializers.layout import SourceText, detail
        >>> text = b'<geom size="1" condim="x" colour="red"/>'
        >>> flat = ["size", "1", "condim", "x", "colour", "red"]
        >>> layout = Layout(SourceText(text), "geom", 0, len(text), len(text), flat, (), None)
        >>> recorded_values(detail(layout), Geom, layout)
        ((1.0,), Unparsed('x'), 'red')

    """
    values = detail.values
    if values is not None:
        return values
    if not issubclass(cls, TypedElement):
        values = detail.values = detail.texts  # a generic element holds the very strings
        return values
    info = cls.__node_info__
    table, plain = info.table, info.plain_names
    known = layout.origin.values.get(cls, {})  # the very values the reader gave the nodes
    found: list[Any] = []
    for name, text in zip(detail.names, detail.texts, strict=True):
        field = table.get(name)
        if field is None or name in plain:
            found.append(text)  # kept in ``extra``, or a name held as it is
            continue
        read = known.get((name, text))
        if read is not None:
            found.append(read[1])
            continue
        try:
            found.append(info.readers[name][1](text))
        except MjcfValueError:
            found.append(Unparsed(text))  # equal to the one the node keeps
    values = detail.values = tuple(found)
    key = (cls, detail.names, bool(layout.children), layout.text is not None)
    check = _FAST_CHECKS.get(key)
    if check is None:
        check = _FAST_CHECKS.remember(key, _fast_check(info, *key[1:]))
    if check is not None and None not in values:
        detail.getter, detail.stored, detail.fields = check
    return values


def written_text(node: Node, name: str) -> str | None:
    """The text the writer writes for attribute ``name``; ``None`` when not written or a comment.

    For an element read from a file, an attribute still holding the value it was read
    with is written as it was spelled there (``group="01"``); any other is formatted, as
    :func:`~mjcf_model.nodes.base.attribute_text` formats it.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><worldbody><geom group="01" size="0.10"/></worldbody></mujoco>')
        >>> (geom,) = model.worldbody.geoms
        >>> written_text(geom, "group"), written_text(geom, "size"), written_text(geom, "pos")
        ('01', '0.10', None)
        >>> from mjcf_model import with_attributes
        >>> written_text(with_attributes(geom, group=2), "group")
        '2'

    """
    text = attribute_text(node, name)
    if text is None:
        return None
    assert isinstance(node, Element)
    layout = layout_of(node)
    if layout is None:
        return text
    cut = detail(layout)
    if name not in cut.names:
        return text
    index = cut.names.index(name)
    recorded = recorded_values(cut, type(node), layout)[index]
    value = get_attribute(node, name)
    return cut.texts[index] if value is recorded or value == recorded else text


def holds_what_was_read(element: AnyElement, layout: Layout, cut: LayoutDetail) -> bool:
    """Whether ``element`` stores exactly the fields, and values, it was read with.

    The writer's fast check for an unchanged start tag (children and text aside).
    """
    values = recorded_values(cut, type(element), layout)
    getter = cut.getter
    stored = element.__dict__.keys()
    return (
        getter is not None
        and (stored == cut.stored or stored - LATER_FIELDS == cut.stored)
        and getter(element) == values
    )


def reduced_from_text(element: AnyElement) -> tuple[Any, ...] | None:
    """How to pickle a typed element read from text: its class, layout, children and changes.

    Its values are read again from its layout's attributes when unpickled (they
    repeat its text, which the layout carries), and the fields changed since reading
    are set over them, so a pickled subtree weighs little more than its text. ``None``
    for an element with character data or an attribute without a field, or not read
    from text: pickled field by field.
    """
    layout = layout_of(element)
    if (
        layout is None
        or not isinstance(element, TypedElement)
        or element.text is not None
        or element.tag != layout.tag
        or layout.text is not None
    ):
        return None
    cut = detail(layout)
    values = recorded_values(cut, type(element), layout)
    if cut.getter is None:
        return None
    table = type(element).__node_info__.table
    read = dict(zip([table[name] for name in cut.names], values, strict=True))
    read["attribute_order"] = cut.names
    held = element.__dict__
    changed = {
        name: value
        for name, value in held.items()
        if name not in _NOT_READ and (name not in read or not _same(read[name], value))
    }
    removed = tuple(name for name in read if name not in held)
    kept = layout.without_old_children(element.children)
    return (reread, (type(element), kept, element.children, changed, removed))


#: The fields :func:`reduced_from_text` passes apart from the values read.
_NOT_READ = frozenset({"layout", "children"})


def _same(read: Any, held: Any) -> bool:
    return read is held or read == held


def reread(
    cls: type[TypedElement],
    layout: Layout,
    children: tuple[Node, ...],
    changed: dict[str, Any],
    removed: tuple[str, ...],
) -> TypedElement:
    """An element pickled by :func:`reduced_from_text`, read again from its layout.

    Raises:
        MjcfValueError: the text no longer reads as the class reads it (a pickle from
            another version of the library).

    """
    origin = layout.origin
    if origin.reducer is None:  # not pickled with the text: this reader reads it
        origin.reducer = reduced_from_text
    node = read_typed(cls, layout.attributes, children, layout, origin.values, {})
    if node is None:
        raise MjcfValueError(f"a pickled <{layout.tag}> no longer reads as {cls.__name__}")
    held = node.__dict__
    held.update(changed)
    for name in removed:
        del held[name]
    return node


def _fast_check(
    info: NodeInfo, names: tuple[str, ...], children: bool, text: bool
) -> tuple[Callable[[Any], tuple[Any, ...]], frozenset[str], tuple[str, ...]] | None:
    """The getter of the fields of ``names``, the fields an element read so stores, and those.

    ``None`` when an attribute has no field (the element keeps it in ``extra``).
    """
    fields = tuple([info.table.get(name) or "" for name in names])
    if "" in fields:
        return None
    stored = {*fields, "attribute_order", "layout"}
    if children:
        stored.add("children")
    if text:
        stored.add("text")
    return tuple_getter(fields), frozenset(stored), fields


#: Per class, attribute names and kind of content, what :func:`_fast_check` made.
#: (Hostile text could make any number of attribute sets, hence the bound.)
_FAST_CHECKS: BoundedCache[
    tuple[type, tuple[str, ...], bool, bool],
    tuple[Callable[[Any], tuple[Any, ...]], frozenset[str], tuple[str, ...]] | None,
] = BoundedCache(4096)
