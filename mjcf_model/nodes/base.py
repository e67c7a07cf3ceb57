"""The node base classes: comments, typed elements and the generic element.

Every node is a frozen attrs instance. An element keeps its children in one
ordered ``children`` tuple (MuJoCo numbers objects in document order), the
attributes its class does not model in :class:`AttributeMap` ``extra``, and the
order its attributes had in the source in ``attribute_order`` (not part of
equality: two elements that differ only in attribute order are equal).

>>> from mjcf_model import Geom
>>> g = Geom(name="ball", type="sphere", size=[0.1])
>>> g.size
(0.1,)
>>> attribute_items(g)
[('name', 'ball'), ('type', 'sphere'), ('size', (0.1,))]
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING, Any, ClassVar, SupportsIndex, TypeVar, cast

import attrs

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.attribute_map import EMPTY_ATTRIBUTES, AttributeMap, to_attribute_map
from mjcf_model.nodes.building import build_node
from mjcf_model.nodes.comparing import Subtree, forest_hash, forests_equal
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.file_layout import FileLayout
from mjcf_model.nodes.node_info import NodeInfo, xml_name
from mjcf_model.values import Value, check_name, check_text, format_value

__all__ = [
    "AnyElement",
    "AttributeMap",
    "Comment",
    "Element",
    "GenericElement",
    "Node",
    "TypedElement",
    "attribute_items",
    "attribute_text",
    "build_node",
    "field_table",
    "full_repr",
    "get_attribute",
    "to_attribute_map",
    "to_children",
    "with_attributes",
    "xml_name",
]

_T = TypeVar("_T")


def to_children(value: Iterable[Node] | None) -> tuple[Node, ...]:
    """Converter: any iterable of nodes becomes a tuple, checking each item is a node.

    Examples:
        >>> to_children([Comment(text=" hi ")])
        (Comment(text=' hi '),)

    """
    if value is None:
        return ()
    items = value if isinstance(value, tuple) else tuple(value)
    for item in items:
        if not isinstance(item, Node):
            raise MjcfValueError(f"children must be nodes, found {type(item).__name__}: {item!r}")
    return items


@node
class Node:
    """Anything that can stand in an element's ``children``: an element or a comment."""

    #: What the library knows about the class (built by :func:`~mjcf_model.nodes.declaring.node`).
    __node_info__: ClassVar[NodeInfo]
    if TYPE_CHECKING:  # lets ``attrs.fields`` and ``attrs.has`` type-check on node classes
        __attrs_attrs__: ClassVar[tuple[attrs.Attribute[Any], ...]]

    def __eq__(self, other: object) -> bool:
        """Equal when of the same class with equal fields (``==`` of attrs, any depth)."""
        if other.__class__ is not self.__class__:
            return NotImplemented
        return other is self or forests_equal((self,), (other,))

    def __hash__(self) -> int:
        """Hash of the class and every field ``==`` compares, children included."""
        return forest_hash((self,))

    def __copy__(self) -> Node:
        return self  # immutable: a copy could only be the same value

    def __deepcopy__(self, memo: dict[int, Any]) -> Node:
        return self  # immutable all the way down, so sharing is copying (at any depth)


def _check_comment(_instance: Any, _attribute: Any, value: str) -> None:
    if not isinstance(value, str):
        raise MjcfValueError(f"comment text must be a string, found {value!r}")
    if "--" in value or value.endswith("-"):
        raise MjcfValueError(f"an XML comment cannot contain '--' or end with '-': {value!r}")
    if "\r" in value:  # XML reads it as a line feed, and a comment has no character references
        raise MjcfValueError(f"an XML comment cannot keep a carriage return: {value!r}")
    check_text(value, "comment")


@node
class Comment(Node):
    """An XML comment, kept where it stood.

    Examples:
        >>> Comment(text=" left arm ")
        Comment(text=' left arm ')

    """

    #: The text between ``<!--`` and ``-->``, spaces included.
    text: str = attrs.field(validator=_check_comment, kw_only=True)


def _optional_text(_instance: Any, _attribute: Any, value: str | None) -> None:
    if value is not None:
        if not isinstance(value, str):
            raise MjcfValueError(f"element text must be a string, found {value!r}")
        check_text(value, "element text")


@node
class Element(Node):
    """Base of every element node, typed or generic.

    ``isinstance(node, Element)`` tells elements from comments; every element has a ``tag``.
    """

    #: The XML tag: a class variable of a typed class (from its schema keys), a field
    #: of a generic element.
    tag: ClassVar[str]
    #: Child elements and comments, in document order (compared as a :class:`Subtree`).
    children: tuple[Node, ...] = attrs.field(default=(), converter=to_children, eq=Subtree)
    #: Character data inside the element, unless it is only white space.
    text: str | None = attrs.field(default=None, validator=_optional_text)
    #: How the element was written in its file (ignored by ``==``, ``hash`` and the dict
    #: form); ``None`` for an element built in code.
    layout: FileLayout | None = attrs.field(default=None, eq=False, repr=False)

    def __reduce_ex__(self, protocol: SupportsIndex) -> str | tuple[Any, ...]:
        """Pickle an element read from text as its layout says, any other field by field.

        A loaded element pickles small: its values are read again from its text when
        unpickled (:meth:`~mjcf_model.nodes.file_layout.FileLayout.reduced`); any other
        element is pickled field by field (:meth:`__getstate__`).
        """
        if self.layout is not None:
            reduced = self.layout.reduced(self)
            if reduced is not None:
                return reduced
        return super().__reduce_ex__(protocol)

    def __getstate__(self) -> dict[str, Any]:
        """The fields to pickle: the layout first, so that it cuts the text its children share.

        A pickled element carries the piece of its file's text it stands in (see
        :meth:`Layout.__reduce__ <mjcf_model.serializers.layout.Layout.__reduce__>`), and of the
        children it was read with only what the writer needs when they were replaced.
        """
        state = self.__dict__
        layout = state.get("layout")
        if layout is None:
            return state
        return {"layout": layout.without_old_children(self.children), **state}

    def _repr_frame(self) -> tuple[str, str]:
        """The repr before and after the children (each element class writes its own)."""
        raise NotImplementedError

    def _of_type(self, cls: type[_T]) -> tuple[_T, ...]:
        return tuple(c for c in self.children if isinstance(c, cls))

    def _first(self, cls: type[_T]) -> _T | None:
        for child in self.children:
            if isinstance(child, cls):
                return child
        return None

    @property
    def elements(self) -> tuple[AnyElement, ...]:
        """The child elements, comments left out."""
        return tuple(c for c in self.children if isinstance(c, Element))


@node
class TypedElement(Element):
    """Base of the typed element classes (``Geom``, ``Body``, ...).

    Subclasses set the class variable ``schema_keys`` (the rows of the schema table
    they model; their ``tag`` is the last part) and declare one field per MJCF
    attribute, spelled as in MJCF (``class`` is ``dclass``). ``None`` means
    "not written".
    """

    #: Attributes this class does not model, in source order, as text.
    extra: AttributeMap = attrs.field(default=EMPTY_ATTRIBUTES, converter=to_attribute_map)
    #: XML attribute names in the order they stood in the source (ignored by ``==``).
    attribute_order: tuple[str, ...] = attrs.field(default=(), eq=False, repr=False)

    def __repr__(self) -> str:
        """Show only the attributes that are written, then extras and children.

        A large subtree shows as one line (see :func:`full_repr` for all of it).
        """
        return _short_or_full_repr(self)

    def _repr_frame(self) -> tuple[str, str]:
        table = field_table(type(self))
        parts = [
            f"{field}={getattr(self, field)!r}"
            for field in table.values()
            if getattr(self, field) is not None
        ]
        if self.extra:
            parts.append(f"extra={self.extra!r}")
        if self.text is not None:
            parts.append(f"text={self.text!r}")
        head = f"{type(self).__name__}({', '.join(parts)}"
        if not self.children:
            return head + ")", ""
        return head + (", " if parts else "") + "children=(", "))"

    def _repr_pretty_(self, printer: Any, cycle: bool) -> None:
        """Print the compact repr in IPython and in hypothesis' failure reports."""
        printer.text(repr(self))


def _check_tag(_instance: Any, _attribute: Any, value: str) -> None:
    if not isinstance(value, str):
        raise MjcfValueError(f"a tag must be a string, found {value!r}")
    check_name(value, "tag")


@node
class GenericElement(Element):
    """An element without a typed class: future MJCF, plugins' configuration, ``visual``...

    Examples:
        >>> e = GenericElement(tag="replicate", attributes={"count": "3"})
        >>> e.attributes["count"]
        '3'

    """

    #: The XML tag.
    tag: str = attrs.field(validator=_check_tag, kw_only=True)  # type: ignore[misc]
    #: All attributes, as text, in source order.
    attributes: AttributeMap = attrs.field(default=EMPTY_ATTRIBUTES, converter=to_attribute_map)

    def __repr__(self) -> str:
        return _short_or_full_repr(self)

    def _repr_frame(self) -> tuple[str, str]:
        rest = f"text={self.text!r}, tag={self.tag!r}, attributes={self.attributes!r})"
        if not self.children:
            return f"GenericElement(children=(), {rest}", ""
        return "GenericElement(children=(", f"), {rest}"


#: A subtree of more elements than this shows as one line in ``repr``.
FULL_REPR_ELEMENTS = 20


def _short_or_full_repr(node: TypedElement | GenericElement) -> str:
    """The full repr of a small subtree, the one-line summary of a larger one."""
    count = 0
    stack: list[Node] = [node]
    while stack:
        item = stack.pop()
        if isinstance(item, Element):
            count += 1
            stack.extend(item.children)
    if count <= FULL_REPR_ELEMENTS:
        return _tree_repr(node)
    named = [
        f"{key}={value!r}"
        for key in ("model", "name")
        if isinstance(value := getattr(node, key, None), str)
    ]
    label = node.tag if isinstance(node, GenericElement) else type(node).__name__
    where = ""
    layout = node.layout
    if layout is not None:
        filename, line = layout.where()
        if filename is not None:
            where = f" from {filename!r}, line {line}"
    return f"<{' '.join([label, *named])}: {count:,} elements{where}>"


def full_repr(node: Node) -> str:
    """The whole repr of ``node``, every element and field, whatever its size.

    ``repr`` shows a subtree of more than :data:`FULL_REPR_ELEMENTS` elements as
    one line: its class, name, element count and the file it was read from.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(name="arm", children=[Geom(name=f"g{i}") for i in range(20)])
        >>> repr(body)
        "<Body name='arm': 21 elements>"
        >>> full_repr(body)[:44]
        "Body(name='arm', children=(Geom(name='g0'), "

    """
    if isinstance(node, Element):
        return _tree_repr(node)
    return repr(node)


def _tree_repr(node: Element) -> str:
    """The repr of ``node``, built with an explicit stack so that any depth prints.

    It is the repr recursion would give: each element's own fields, then its
    children as a tuple.
    """
    out: list[str] = []
    stack: list[Node | str] = [node]
    while stack:
        item = stack.pop()
        if isinstance(item, str):
            out.append(item)
            continue
        if not isinstance(item, Element):
            out.append(repr(item))  # a comment, or a node subclass of someone else's
            continue
        head, tail = item._repr_frame()
        out.append(head)
        if not item.children:
            continue
        sequence: list[Node | str] = []
        for index, child in enumerate(item.children):
            if index:
                sequence.append(", ")
            sequence.append(child)
        sequence.append(("," if len(item.children) == 1 else "") + tail)
        stack.extend(reversed(sequence))
    return "".join(out)


#: Either kind of element.
AnyElement = Element
_E = TypeVar("_E", bound=Element)


def field_table(cls: type[Element]) -> dict[str, str]:
    """Map each MJCF attribute name a typed class models to its field name.

    Examples:
        >>> from mjcf_model import Geom
        >>> field_table(Geom)["class"]
        'dclass'

    """
    return cls.__node_info__.table


def _first_item(pair: tuple[Any, Any]) -> Any:
    return pair[0]


def attribute_items(element: AnyElement) -> list[tuple[str, Value]]:
    """The element's written attributes as ``(xml name, value)``, in source order.

    Attributes that were not in the source (set in Python) follow in field order;
    typed values stay typed, unknown ones are text.

    Examples:
        >>> from mjcf_model import Joint
        >>> attribute_items(Joint(name="j", range=(0, 1)))
        [('name', 'j'), ('range', (0.0, 1.0))]

    """
    if isinstance(element, GenericElement):
        return list(element.attributes.items())
    typed = cast(TypedElement, element)
    info = type(typed).__node_info__
    rank = info.rank
    present = [
        (rank[field], value)
        for field, value in typed.__dict__.items()
        if value is not None and field in rank
    ]  # only the fields the node stores: a few, not every field of the class
    present.sort(key=_first_item)
    names = info.names
    values: dict[str, Value] = {names[index]: value for index, value in present}
    if typed.extra:
        values.update(typed.extra)
    if not typed.attribute_order:
        return list(values.items())
    ordered = [(k, values.pop(k)) for k in typed.attribute_order if k in values]
    ordered.extend(values.items())
    return ordered


def get_attribute(element: AnyElement, name: str) -> Value | None:
    """The value of the MJCF attribute ``name``, or ``None`` when not written.

    Examples:
        >>> from mjcf_model import Geom
        >>> get_attribute(Geom(dclass="arm"), "class")
        'arm'

    """
    if isinstance(element, GenericElement):
        return element.attributes.get(name)
    typed = cast(TypedElement, element)
    field = field_table(type(typed)).get(name)
    if field is not None:
        value: Value | None = getattr(typed, field)
        return value
    return typed.extra.get(name)


def attribute_text(node: Node, name: str) -> str | None:
    """The text attribute ``name`` is written as; ``None`` when not written or for a comment.

    Examples:
        >>> from mjcf_model import Comment, Geom
        >>> attribute_text(Geom(group=1), "group"), attribute_text(Geom(), "group")
        ('1', None)
        >>> attribute_text(Comment(text="note"), "group") is None
        True

    """
    if not isinstance(node, Element):
        return None
    value = get_attribute(node, name)
    return None if value is None else format_value(value)


def with_attributes(
    element: _E,
    changes: Mapping[str, Value | None] | None = None,
    /,
    **keyword_changes: Value | None,
) -> _E:
    """Return a copy with MJCF attributes set (``None`` removes one).

    The attributes come as keywords, as :func:`attrs.evolve` takes them, or as a
    mapping for names that are not Python identifiers (``"class"``); both may be
    given. Keys are MJCF attribute names (``"class"``, not the field ``dclass``).
    Typed fields receive typed values (converted as usual); other attributes go
    to ``extra`` as text. The source order is kept; new attributes go last.

    Raises:
        TypeError: The same attribute is given both in ``changes`` and as a keyword.

    Examples:
        >>> from mjcf_model import Site
        >>> with_attributes(Site(name="s"), pos=(0, 0, 1)).pos
        (0.0, 0.0, 1.0)
        >>> with_attributes(Site(name="s"), {"class": "c"}, name="p_s").dclass
        'c'

    """
    if keyword_changes:
        twice = sorted(set(changes or ()) & keyword_changes.keys())
        if twice:
            given = ", ".join(twice)
            raise TypeError(f"with_attributes() got {given} both in changes and as keywords")
        changes = {**(changes or {}), **keyword_changes}
    if not changes:
        return element
    if isinstance(element, GenericElement):
        text = {
            k: v if v is None or type(v) is str else format_value(v) for k, v in changes.items()
        }
        attributes = element.attributes.replaced(text)  # checks only the new text
        return build_node(type(element), {"attributes": attributes}, element)
    assert isinstance(element, TypedElement)
    cls = type(element)
    plain = cls.__node_info__.plain_names
    if all(type(value) is str and key in plain for key, value in changes.items()):
        # Names and keywords held as written (a rename's changes): their one check is
        # the text's, so the new node is the old one's fields with these replaced.
        data = element.__dict__.copy()
        for key, value in changes.items():
            data[plain[key]] = check_text(cast(str, value))
        renamed = object.__new__(cls)
        object.__setattr__(renamed, "__dict__", data)
        return renamed
    table = field_table(cls)
    fields: dict[str, Any] = {}
    extra: dict[str, str | None] = {}
    for key, value in changes.items():
        field = table.get(key)
        if field is not None:
            fields[field] = value
        elif value is None or isinstance(value, str):
            extra[key] = value
        else:
            extra[key] = format_value(value)
    if extra:
        fields["extra"] = element.extra.replaced(extra)
    return build_node(cls, fields, element)
