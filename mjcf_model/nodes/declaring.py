"""Declaring node classes: one decorator and one metadata object per class.

Every node class is written as::

    @node
    class Geom(Oriented):
        schema_keys: ClassVar[tuple[str, ...]] = ("body/geom", "default/geom")
        #: Size parameters; their number and meaning depend on ``type``.
        size: Floats | None = vec1to3()

:func:`node` (with the field helpers of :mod:`mjcf_model.nodes.fields`) makes
the class a frozen attrs class whose instances store only the fields that were
given (absent fields read their default from the class), sets its ``tag`` (the last
part of its schema keys, the rows of :mod:`mjcf_model.schema.namespaces` it models), and
builds its
:class:`~mjcf_model.nodes.node_info.NodeInfo` once: the MJCF attribute table,
converters, validators and defaults that the readers, writers and the fast builder use.

>>> from mjcf_model import Geom
>>> info = Geom.__node_info__
>>> info.tag, info.table["class"], info.keys
('geom', 'dclass', ('body/geom', 'default/geom'))
"""

from __future__ import annotations

import inspect
from typing import TYPE_CHECKING, Any, TypeVar

import attrs

from mjcf_model.nodes.building import fill_node
from mjcf_model.nodes.comparing import Subtree
from mjcf_model.nodes.node_info import NodeInfo
from mjcf_model.values import float_key

__all__ = ["declare", "declared_classes", "declared_count", "node"]

_C = TypeVar("_C", bound=type)

_DECLARED: list[type] = []


def declared_classes() -> tuple[type, ...]:
    """Every class declared with :func:`node`, in the order they were declared.

    Examples:
        >>> from mjcf_model import Geom
        >>> Geom in declared_classes()
        True

    """
    return tuple(_DECLARED)


def declared_count() -> int:
    """How many classes :func:`node` has declared: it grows when a class is declared.

    Examples:
        >>> declared_count() == len(declared_classes())
        True

    """
    return len(_DECLARED)


def _compared_as_is() -> frozenset[object]:
    """The eq keys ``==`` of nodes honours without applying them (see ``Node.__eq__``).

    ``float_key`` only makes NaN equal to NaN, which holding one NaN object already
    does; ``Subtree`` is how children compare, which ``Node.__eq__`` does itself.
    """
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
        ...     schema_keys: ClassVar[tuple[str, ...]] = ("body/thing",)
        ...     size: tuple[float, ...] | None = vec3()
        >>> Thing(size=[1, 2, 3]).size, Thing().size, Thing.tag
        ((1.0, 2.0, 3.0), None, 'thing')

    """
    _set_tag(cls)
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


def _set_tag(cls: type) -> None:
    """Give a class that models schema rows its XML tag: the last part of every key.

    The tag is not written in the class, so the table's keys are its one source.
    """
    keys = cls.__dict__.get("schema_keys", ())
    tags = {key.rsplit("/", 1)[-1] for key in keys}
    if len(tags) > 1:
        raise TypeError(f"{cls.__name__}: schema keys {keys} name more than one tag")
    if "tag" in cls.__dict__ and tags:
        raise TypeError(f"{cls.__name__}: the tag comes from schema_keys; do not set it")
    if tags:
        cls.tag = tags.pop()  # type: ignore[attr-defined]


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
    fill_node(self, values, None, checked_children=True)


if TYPE_CHECKING:
    # mypy's attrs plugin knows attrs' own decorators by name: under this name it
    # reads node classes as the frozen attrs classes they are (converters' input
    # types in ``__init__``, ``attrs.evolve`` and ``attrs.fields`` checked).
    from attrs import frozen as node
else:
    node = declare
