"""Declaring node classes: one decorator and one metadata object per class.

Every node class is written as::

    @node
    class Geom(Oriented):
        tag: ClassVar[str] = "geom"
        schema_keys: ClassVar[tuple[str, ...]] = ("body/geom", "default/geom")
        #: Size parameters; their number and meaning depend on ``type``.
        size: Floats | None = vec1to3()

:func:`node` (with the field helpers of :mod:`mjcf_model.nodes.fields`) makes
the class a frozen attrs class whose instances store only the fields that were
given (absent fields read their default from the class), and builds its
:class:`NodeInfo` once: the MJCF attribute table, converters, validators and
defaults that the readers, writers and the fast builder use.

>>> from mjcf_model import Geom
>>> info = Geom.__node_info__
>>> info.tag, info.table["class"], info.keys
('geom', 'dclass', ('body/geom', 'default/geom'))
"""

from __future__ import annotations

import inspect
import operator
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TypeVar

import attrs

from mjcf_model.values import (
    float_key,
    text_reader,
    to_str,
)

__all__ = [
    "BASE_FIELDS",
    "NodeInfo",
    "declare",
    "declared_classes",
    "node",
    "tuple_getter",
    "xml_name",
]

_C = TypeVar("_C", bound=type)

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


_DECLARED: list[type] = []


def declared_classes() -> tuple[type, ...]:
    """Every class declared with :func:`node`, in the order they were declared.

    Examples:
        >>> from mjcf_model import Geom
        >>> Geom in declared_classes()
        True

    """
    return tuple(_DECLARED)


def _compared_as_is() -> frozenset[object]:
    """The eq keys ``==`` of nodes honours without applying them (see ``Node.__eq__``).

    ``float_key`` only makes NaN equal to NaN, which holding one NaN object already
    does; ``Subtree`` is how children compare, which ``Node.__eq__`` does itself.
    """
    from mjcf_model.nodes.comparing import Subtree

    return frozenset({float_key, Subtree})


def _check_buildable(cls: type) -> None:
    """Refuse what the fast builder cannot honour: it sets ``__dict__`` and runs nothing else."""
    if hasattr(cls, "__attrs_post_init__") or hasattr(cls, "__attrs_pre_init__"):
        raise TypeError(f"{cls.__name__}: node classes cannot have __attrs_post_init__")
    for klass in cls.__mro__:
        if klass.__dict__.get("__slots__"):
            raise TypeError(f"{cls.__name__}: node classes store fields in __dict__, not slots")
    for field in attrs.fields(cls):
        if not field.init or field.on_setattr not in (None, attrs.setters.NO_OP):
            raise TypeError(f"{cls.__name__}.{field.name}: node fields are plain init fields")
        if field.eq_key is not None and field.eq_key not in _compared_as_is():
            raise TypeError(
                f"{cls.__name__}.{field.name}: node fields compare by value; an eq= key is"
                " not supported (convert the value instead)"
            )


def declare(cls: _C) -> _C:
    """Declare a node class (``@node``): frozen keyword-only attrs, sparse, with a NodeInfo.

    An instance keeps in its ``__dict__`` only the fields it was given; a field
    left out reads its default from the class. ``attrs.fields``, ``attrs.evolve``,
    ``==`` and ``hash`` work as on any attrs class.

    Examples:
        >>> from typing import ClassVar
        >>> from mjcf_model.nodes.base import TypedElement
        >>> from mjcf_model.nodes.fields import vec3
        >>> @node
        ... class Thing(TypedElement):
        ...     tag: ClassVar[str] = "thing"
        ...     size: tuple[float, ...] | None = vec3()
        >>> Thing(size=[1, 2, 3]).size, Thing().size
        ((1.0, 2.0, 3.0), None)

    """
    own_repr = any(_hand_written(klass.__dict__.get("__repr__")) for klass in cls.__mro__[:-1])
    # attrs generates no __init__, __eq__ or __hash__: one implementation of each,
    # over the class's NodeInfo, serves every class (and import stays fast).
    made = attrs.frozen(kw_only=True, slots=False, init=False, eq=False, repr=not own_repr)(cls)
    info = NodeInfo(made)
    for name, default in info.defaults.items():
        setattr(made, name, default)
    _check_buildable(made)
    made.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
        [_parameter(field) for field in attrs.fields(made)]
    )
    made.__init__ = _sparse_init  # type: ignore[misc]
    made.__node_info__ = info  # type: ignore[attr-defined]
    _DECLARED.append(made)
    return made


def _parameter(field: attrs.Attribute[Any]) -> inspect.Parameter:
    """The keyword-only constructor parameter ``help()`` and ``inspect`` show for ``field``."""
    default = inspect.Parameter.empty if field.default is attrs.NOTHING else field.default
    annotation = inspect.Parameter.empty if field.type is None else field.type
    return inspect.Parameter(
        field.name, inspect.Parameter.KEYWORD_ONLY, default=default, annotation=annotation
    )


def _hand_written(method: object) -> bool:
    """Whether ``method`` exists and was written by hand, not generated by attrs."""
    code = getattr(method, "__code__", None)
    return code is not None and not code.co_filename.startswith("<attrs generated")


def _sparse_init(self: Any, **values: Any) -> None:
    """The constructor of every node class: the fields given, converted and validated."""
    from mjcf_model.nodes.building import fill_node

    fill_node(self, values, None, checked_children=True)


if TYPE_CHECKING:
    # mypy's attrs plugin knows attrs' own decorators by name: under this name it
    # reads node classes as the frozen attrs classes they are (converters' input
    # types in ``__init__``, ``attrs.evolve`` and ``attrs.fields`` checked).
    from attrs import frozen as node
else:
    node = declare
