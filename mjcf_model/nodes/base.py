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

import operator
from collections.abc import Callable, ItemsView, Iterable, Iterator, KeysView, Mapping, ValuesView
from typing import TYPE_CHECKING, Any, ClassVar, TypeVar, overload

import attrs

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.building import build_node
from mjcf_model.nodes.declaring import NodeInfo, node, xml_name
from mjcf_model.nodes.layout import Layout
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
    "build_node",
    "field_table",
    "get_attribute",
    "to_attribute_map",
    "to_children",
    "with_attributes",
    "xml_name",
]

_T = TypeVar("_T")


class AttributeMap(Mapping[str, str]):
    """An immutable, ordered, hashable mapping of XML attribute names to text.

    Equality ignores order, like XML itself.

    Example:
        >>> m = AttributeMap({"b": "1", "a": "2"})
        >>> list(m), m == AttributeMap({"a": "2", "b": "1"})
        (['b', 'a'], True)

    """

    __slots__ = ("_data", "_hash")

    def __init__(self, items: Mapping[str, str] | Iterable[tuple[str, str]] = ()) -> None:
        data = dict(items)
        for key, value in data.items():
            if not isinstance(key, str) or not isinstance(value, str):
                raise MjcfValueError(
                    f"attribute names and values must be text, found {key!r}={value!r}"
                )
            check_name(key, "attribute name")
            check_text(value, f"attribute {key!r}")
        self._data = data
        self._hash: int | None = None

    @classmethod
    def unchecked(cls, data: dict[str, str]) -> AttributeMap:
        r"""Wrap ``data`` without checking that XML can carry it.

        Only for the robosuite layer, whose ElementTree elements take any text
        (robosuite's ``new_element(name="\x1f")`` works); such a map is converted
        to ElementTree at once and never written by :mod:`serializers`.
        """
        made = cls.__new__(cls)
        made._data = data
        made._hash = None
        return made

    def __getitem__(self, key: str) -> str:
        return self._data[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    # The Mapping mixins work item by item in Python; these pass through to the dict.
    def __contains__(self, key: object) -> bool:
        return key in self._data

    @overload
    def get(self, key: str, /) -> str | None: ...
    @overload
    def get(self, key: str, /, default: str | _T) -> str | _T: ...
    def get(self, key: str, /, default: object = None) -> object:
        """The text of ``key``, or ``default`` when the element does not write it."""
        return self._data.get(key, default)

    def keys(self) -> KeysView[str]:
        """The attribute names, in order."""
        return self._data.keys()

    def values(self) -> ValuesView[str]:
        """The attribute texts, in order."""
        return self._data.values()

    def items(self) -> ItemsView[str, str]:
        """The ``(name, text)`` pairs, in order."""
        return self._data.items()

    def __hash__(self) -> int:
        if self._hash is None:
            self._hash = hash(frozenset(self._data.items()))
        return self._hash

    def __eq__(self, other: object) -> bool:
        if isinstance(other, AttributeMap):
            return self._data == other._data
        if isinstance(other, Mapping):
            return self._data == dict(other)
        return NotImplemented

    def __repr__(self) -> str:
        return f"AttributeMap({self._data!r})"

    def replaced(self, changes: Mapping[str, str | None]) -> AttributeMap:
        """Return a copy with ``changes`` applied; ``None`` removes a key.

        Example:
            >>> AttributeMap({"a": "1"}).replaced({"a": None, "b": "2"})
            AttributeMap({'b': '2'})

        """
        data = dict(self._data)
        for key, value in changes.items():
            if value is None:
                data.pop(key, None)
            else:
                data[key] = value
        return AttributeMap(data)


_EMPTY = AttributeMap()


def to_attribute_map(value: Mapping[str, str] | Iterable[tuple[str, str]] | None) -> AttributeMap:
    """Converter: any mapping or pair sequence becomes an :class:`AttributeMap`.

    Example:
        >>> to_attribute_map({"x": "1"})
        AttributeMap({'x': '1'})

    """
    if isinstance(value, AttributeMap):
        return value
    if not value:
        return _EMPTY
    return AttributeMap(value)


def to_children(value: Iterable[Node] | None) -> tuple[Node, ...]:
    """Converter: any iterable of nodes becomes a tuple, checking each item is a node.

    Example:
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
        return other is self or _forests_equal((self,), (other,))

    def __hash__(self) -> int:
        """Hash of the class and every field ``==`` compares, children included."""
        return _forest_hash((self,))

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

    Example:
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


class _Shape:
    """What ``==`` and ``hash`` read from nodes of one class that store one set of fields.

    Made once per class and set of stored fields (:func:`_shape_of`) and shared, so
    two nodes store the same compared fields exactly when they have the same shape.
    """

    __slots__ = ("defaultable", "hash_getter", "hash_token", "values")

    def __init__(self, cls: type[Node], compared: tuple[str, ...]) -> None:
        defaults = cls.__node_info__.defaults
        #: The stored fields whose default is not ``None`` (``extra``): a node may
        #: store such a field holding its default, and equal one that does not.
        self.defaultable = tuple(k for k in compared if defaults.get(k) is not None)
        hashed = tuple(k for k in compared if k not in self.defaultable)
        #: The compared fields' values, from the node's ``__dict__``.
        self.values = _items_getter(compared)
        #: The values of the fields that are never stored holding their default.
        self.hash_getter = _items_getter(hashed)
        #: The class and those fields' names, hashed once.
        self.hash_token = hash((cls, hashed))


def _items_getter(keys: tuple[str, ...]) -> Callable[[dict[str, Any]], Any]:
    """Read ``keys`` of a dict at once (one value bare, several as a tuple)."""
    return operator.itemgetter(*keys) if keys else _nothing


def _nothing(_data: dict[str, Any]) -> tuple[()]:
    return ()


#: Per class, the shape of each tuple of stored fields, in storage order (``tuple(__dict__)``).
_SHAPES: dict[type, dict[tuple[str, ...], _Shape]] = {}
#: The one shape of each class and set of compared fields (``(cls, *sorted names)``).
_SHAPES_BY_SET: dict[tuple[Any, ...], _Shape] = {}
#: Past this many, a table is forgotten (hostile text could make any number).
_MAX_SHAPES = 1024
#: What ``_SHAPES.get`` gives for a class not met yet (never filled).
_NO_SHAPES: dict[tuple[str, ...], _Shape] = {}


def _shape_of(node: Node, keys: tuple[str, ...] | None = None) -> _Shape:
    """The shape of ``node``, whose stored fields are ``keys`` if given.

    The walks of ``==`` and ``hash`` look the shape up inline first.
    """
    cls = type(node)
    if keys is None:
        keys = tuple(node.__dict__)
    known = _SHAPES.get(cls)
    if known is None:
        known = _SHAPES[cls] = {}
    shape = known.get(keys)
    if shape is None:
        if len(known) >= _MAX_SHAPES:
            known.clear()
        if len(_SHAPES_BY_SET) >= _MAX_SHAPES:
            _SHAPES_BY_SET.clear()  # older shapes stay valid: only ``is`` between them fails
        skip = cls.__node_info__.not_compared
        compared = tuple(sorted(k for k in keys if k not in skip))
        shape = _SHAPES_BY_SET.get((cls, *compared))
        if shape is None:
            shape = _SHAPES_BY_SET[(cls, *compared)] = _Shape(cls, compared)
        known[keys] = shape
    return shape


def _nodes_equal(a: Node, b: Node) -> bool:
    """Whether ``a`` and ``b`` hold the same compared values (their children left out).

    The general case of :func:`_forests_equal`, for nodes that do not store the
    same fields in the same order: either class, either order, and a field one
    stores holding its default while the other leaves it out.
    """
    if type(a) is not type(b):
        return False
    shape = _shape_of(a)
    if shape is _shape_of(b):
        va, vb = shape.values(a.__dict__), shape.values(b.__dict__)
        return va is vb or va == vb  # ``is``: a field holds the one NAN object, equal to itself
    skip = type(a).__node_info__.not_compared
    names = sorted({*a.__dict__, *b.__dict__} - skip)
    return [getattr(a, n) for n in names] == [getattr(b, n) for n in names]


def _forests_equal(left: tuple[Node, ...], right: tuple[Node, ...]) -> bool:
    """Whether two forests are equal by value, walked with an explicit stack.

    Nodes of one class that store the same fields in the same order (two loaded
    copies of a file, or two nodes built alike) take the fast path: one shape,
    and their values compared as two tuples in C.
    """
    shapes = _SHAPES
    stack = [(left, right)]
    while stack:
        left, right = stack.pop()
        if len(left) != len(right):
            return False
        for a, b in zip(left, right, strict=True):
            if a is b:
                continue  # shared: equal by identity
            da = a.__dict__
            db = b.__dict__
            cls = type(a)
            keys = tuple(da)
            if cls is type(b) and keys == tuple(db):
                shape = shapes.get(cls, _NO_SHAPES).get(keys) or _shape_of(a, keys)
                va = shape.values(da)
                vb = shape.values(db)
                if va is not vb and va != vb:  # ``is``: the one NAN object equals itself
                    return False
            elif not _nodes_equal(a, b):
                return False
            ca = da.get("children")
            cb = db.get("children")
            if ca is not cb:
                stack.append((ca or (), cb or ()))
    return True


def _forest_hash(forest: tuple[Node, ...]) -> int:
    """The hash of a forest: every node's class, compared fields and values, and shape."""
    shapes = _SHAPES
    parts: list[Any] = []
    stack = [forest]
    while stack:
        forest = stack.pop()
        parts.append(len(forest))
        for item in forest:
            data = item.__dict__
            keys = tuple(data)
            shape = shapes.get(type(item), _NO_SHAPES).get(keys) or _shape_of(item, keys)
            parts.append(shape.hash_token)
            parts.append(shape.hash_getter(data))
            if shape.defaultable:
                stored = _not_default(item, shape.defaultable)
                if stored:
                    parts.append(stored)
            children = data.get("children")
            if children:
                stack.append(children)
    return hash(tuple(parts))


def _not_default(node: Node, names: tuple[str, ...]) -> tuple[Any, ...]:
    """The fields among ``names`` that ``node`` stores holding other than their default."""
    data, defaults = node.__dict__, type(node).__node_info__.defaults
    return tuple([(n, data[n]) for n in names if data[n] != defaults[n]])


class Subtree:
    """What ``==`` and ``hash`` see of an element's ``children``: the whole forest below.

    Comparing and hashing walk the forest with an explicit stack, not by
    recursion, so trees of any depth compare and hash (MuJoCo reads bodies
    nested 496 deep; an include chain makes deeper ones). Shared subtrees are
    skipped by identity.
    """

    __slots__ = ("children",)

    def __init__(self, children: tuple[Node, ...]) -> None:
        #: The children of the element compared.
        self.children = children

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Subtree):
            return NotImplemented
        return self.children is other.children or _forests_equal(self.children, other.children)

    def __hash__(self) -> int:
        return _forest_hash(self.children)


@node
class Element(Node):
    """Base of every element node, typed or generic."""

    #: Child elements and comments, in document order (compared as a :class:`Subtree`).
    children: tuple[Node, ...] = attrs.field(default=(), converter=to_children, eq=Subtree)
    #: Character data inside the element, unless it is only white space.
    text: str | None = attrs.field(default=None, validator=_optional_text)
    #: How the element was written in its file (ignored by ``==``, ``hash`` and the dict
    #: form); ``None`` for an element built in code.
    layout: Layout | None = attrs.field(default=None, eq=False, repr=False)

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
        return tuple(c for c in self.children if isinstance(c, (TypedElement, GenericElement)))


@node
class TypedElement(Element):
    """Base of the typed element classes (``Geom``, ``Body``, ...).

    Subclasses set the class variable ``tag`` and declare one field per MJCF
    attribute, spelled as in MJCF (``class`` is ``dclass``). ``None`` means
    "not written".
    """

    #: The XML tag of this element type.
    tag: ClassVar[str]
    #: Attributes this class does not model, in source order, as text.
    extra: AttributeMap = attrs.field(default=_EMPTY, converter=to_attribute_map)
    #: XML attribute names in the order they stood in the source (ignored by ``==``).
    attribute_order: tuple[str, ...] = attrs.field(default=(), eq=False, repr=False)

    def __repr__(self) -> str:
        """Show only the attributes that are written, then extras and children."""
        return _tree_repr(self)

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

    Example:
        >>> e = GenericElement(tag="replicate", attributes={"count": "3"})
        >>> e.attributes["count"]
        '3'

    """

    #: The XML tag.
    tag: str = attrs.field(validator=_check_tag, kw_only=True)
    #: All attributes, as text, in source order.
    attributes: AttributeMap = attrs.field(default=_EMPTY, converter=to_attribute_map)

    def __repr__(self) -> str:
        return _tree_repr(self)

    def _repr_frame(self) -> tuple[str, str]:
        rest = f"text={self.text!r}, tag={self.tag!r}, attributes={self.attributes!r})"
        if not self.children:
            return f"GenericElement(children=(), {rest}", ""
        return "GenericElement(children=(", f"), {rest}"


def _tree_repr(node: TypedElement | GenericElement) -> str:
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
        if not isinstance(item, (TypedElement, GenericElement)):
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
AnyElement = TypedElement | GenericElement
_E = TypeVar("_E", bound=TypedElement | GenericElement)


def field_table(cls: type[TypedElement]) -> dict[str, str]:
    """Map each MJCF attribute name a typed class models to its field name.

    Example:
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

    Example:
        >>> from mjcf_model import Joint
        >>> attribute_items(Joint(name="j", range=(0, 1)))
        [('name', 'j'), ('range', (0.0, 1.0))]

    """
    if isinstance(element, GenericElement):
        return list(element.attributes.items())
    info = type(element).__node_info__
    rank = info.rank
    present = [
        (rank[field], value)
        for field, value in element.__dict__.items()
        if value is not None and field in rank
    ]  # only the fields the node stores: a few, not every field of the class
    present.sort(key=_first_item)
    names = info.names
    values: dict[str, Value] = {names[index]: value for index, value in present}
    if element.extra:
        values.update(element.extra)
    if not element.attribute_order:
        return list(values.items())
    ordered = [(k, values.pop(k)) for k in element.attribute_order if k in values]
    ordered.extend(values.items())
    return ordered


def get_attribute(element: AnyElement, name: str) -> Value | None:
    """The value of the MJCF attribute ``name``, or ``None`` when not written.

    Example:
        >>> from mjcf_model import Geom
        >>> get_attribute(Geom(dclass="arm"), "class")
        'arm'

    """
    if isinstance(element, GenericElement):
        return element.attributes.get(name)
    field = field_table(type(element)).get(name)
    if field is not None:
        value: Value | None = getattr(element, field)
        return value
    return element.extra.get(name)


def with_attributes(element: _E, changes: Mapping[str, Value | None]) -> _E:
    """Return a copy with MJCF attributes set (``None`` removes one).

    Typed fields receive typed values (converted as usual); other attributes go
    to ``extra`` as text. The source order is kept; new attributes go last.

    Example:
        >>> from mjcf_model import Site
        >>> with_attributes(Site(name="s"), {"name": "p_s", "class": "c"}).dclass
        'c'

    """
    if not changes:
        return element
    if isinstance(element, GenericElement):
        text = {k: None if v is None else format_value(v) for k, v in changes.items()}
        return attrs.evolve(element, attributes=element.attributes.replaced(text))
    assert isinstance(element, TypedElement)
    table = field_table(type(element))
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
    return build_node(type(element), fields, element)
