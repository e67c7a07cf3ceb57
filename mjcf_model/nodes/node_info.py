"""What the library knows about one node class: :class:`NodeInfo`, built once per class.

The readers, the writers, ``==`` on subtrees and the fast builder
(:mod:`mjcf_model.nodes.building`) all read it. :class:`DeclaredNode` is what those
helpers need of a node: an attrs instance whose class carries its ``NodeInfo``.

>>> from mjcf_model import Geom
>>> info = Geom.__node_info__
>>> info.tag, info.table["class"], info.keys
('geom', 'dclass', ('body/geom', 'default/geom'))
"""

from __future__ import annotations

import operator
from collections.abc import Callable
from typing import Any, ClassVar, Protocol

import attrs

from mjcf_model.values import text_reader, to_str

__all__ = ["BASE_FIELDS", "DeclaredNode", "NodeInfo", "tuple_getter", "xml_name"]


class DeclaredNode(Protocol):
    """A node as its helpers see it: attrs fields, and the class's :class:`NodeInfo`."""

    #: The attrs fields of the class.
    __attrs_attrs__: ClassVar[Any]
    #: What the library knows about the class (set when the class is declared).
    __node_info__: ClassVar[NodeInfo]


#: Fields every element has that are not MJCF attributes.
BASE_FIELDS = frozenset({"children", "text", "extra", "attribute_order", "base_dir", "layout"})


def xml_name(field: attrs.Attribute[Any]) -> str:
    """The MJCF attribute name of a node field (``dclass`` is ``class``).

    Examples:
        >>> from mjcf_model import Geom
        >>> xml_name(attrs.fields(Geom).dclass)
        'class'

    """
    return str(field.metadata.get("xml", field.name))


class NodeInfo:
    """What the library needs to know about one node class, built once when it is declared.

    The readers, the writers, ``==`` on subtrees and :func:`~mjcf_model.nodes.base.build_node`
    all read it, so none keeps its own per-class cache.
    """

    __slots__ = (
        "cls",
        "converters",
        "defaults",
        "field_names",
        "getter",
        "keys",
        "names",
        "not_compared",
        "plain_names",
        "plain_text",
        "rank",
        "readers",
        "required",
        "table",
        "tag",
        "validators",
    )

    def __init__(self, cls: type) -> None:
        fields = attrs.fields(cls)
        #: The class described.
        self.cls = cls
        #: The XML tag, for a typed element class; ``None`` for a base class.
        tag = cls.__dict__.get("tag")
        self.tag: str | None = tag if isinstance(tag, str) else None
        #: The schema keys (``"body/geom"``) the registry maps to this class.
        self.keys: tuple[str, ...] = tuple(cls.__dict__.get("schema_keys", ()))
        #: Every field's default, converted (absent fields read these from the class);
        #: a field without one (a comment's text) is left out and must be given.
        self.defaults: dict[str, Any] = {
            f.name: _converted_default(f) for f in fields if f.default is not attrs.NOTHING
        }
        #: Every field name.
        self.field_names: frozenset[str] = frozenset(f.name for f in fields)
        #: The fields without a default, which every instance must be given.
        self.required: frozenset[str] = self.field_names - self.defaults.keys()
        #: The converter of each field that has one.
        self.converters: dict[str, Callable[[Any], Any]] = {
            f.name: f.converter for f in fields if f.converter is not None
        }
        #: The validator of each field that has one, with its attrs field.
        self.validators: dict[str, tuple[Any, attrs.Attribute[Any]]] = {
            f.name: (f.validator, f) for f in fields if f.validator is not None
        }
        table = {xml_name(f): f.name for f in fields if f.name not in BASE_FIELDS}
        if "name" in table:  # the name first: it is what people look for
            table = {"name": "name", **table}
        #: Each MJCF attribute the class models, mapped to its field name.
        self.table: dict[str, str] = table
        #: The MJCF names of ``table``, in the same order as ``getter``'s values.
        self.names: tuple[str, ...] = tuple(table)
        #: Each attribute field's position in ``names``.
        self.rank: dict[str, int] = {field: index for index, field in enumerate(table.values())}
        #: Reads every attribute field at once, as a tuple in ``names`` order.
        self.getter: Callable[[Any], tuple[Any, ...]] = tuple_getter(tuple(table.values()))
        #: The fields ``==`` does not compare on the node itself (its children are walked).
        self.not_compared: frozenset[str] = frozenset(
            f.name for f in fields if not f.eq or f.name == "children"
        )
        #: The attribute fields that hold any text XML carries as it is (names and
        #: references: ``to_str``, no validator): text a parser gave needs no check.
        self.plain_text: frozenset[str] = frozenset(
            field
            for field in table.values()
            if self.converters.get(field) is to_str and field not in self.validators
        )
        #: The MJCF names of ``plain_text``, mapped to their fields.
        self.plain_names: dict[str, str] = {
            name: field for name, field in table.items() if field in self.plain_text
        }
        #: Each MJCF attribute, mapped to its field and what reads its value from text
        #: (converted and validated; raises :class:`~mjcf_model.errors.MjcfValueError`).
        self.readers: dict[str, tuple[str, Callable[[str], Any]]] = {
            name: (field, self._text_reader(field)) for name, field in table.items()
        }

    def _text_reader(self, field: str) -> Callable[[str], Any]:
        converter = self.converters.get(field)
        read = _unchanged if converter is None else text_reader(converter)
        checks = self.validators.get(field)
        if checks is None:
            return read
        validator, attribute = checks

        def read_and_check(text: str) -> Any:
            value = read(text)
            validator(None, attribute, value)
            return value

        return read_and_check


def _unchanged(text: str) -> str:
    return text


def _converted_default(field: attrs.Attribute[Any]) -> Any:
    default = field.default
    if isinstance(default, attrs.Factory):  # type: ignore[arg-type]
        raise TypeError(f"node field {field.name!r}: use an immutable default, not a factory")
    if field.converter is not None and default is not None:
        default = field.converter(default)  # type: ignore[operator]
    return default


def tuple_getter(names: tuple[str, ...]) -> Callable[[Any], tuple[Any, ...]]:
    """Read the fields ``names`` of an object at once, always as a tuple.

    Examples:
        >>> from mjcf_model import Geom
        >>> tuple_getter(("name",))(Geom(name="g"))
        ('g',)

    """
    if len(names) > 1:
        return operator.attrgetter(*names)
    if names:
        single = operator.attrgetter(names[0])
        return lambda instance: (single(instance),)
    return lambda instance: ()
