"""The per-class plans behind :func:`~mjcf_model.to_dict` and :func:`~mjcf_model.from_dict`.

The converter's generated hooks read every field of a class (dozens) where a
node stores a few. A :class:`Codec` reads, once per class, the converter's own
hook for each field's type, so both directions work on the fields a node
stores and give the converter's own result (``tests/serializers/test_dict_codec.py``).
"""

from __future__ import annotations

import functools
import types
import typing
from collections.abc import Callable, Mapping
from typing import Any

import attrs
import cattrs
from cattrs.fns import identity

from mjcf_model.caching import BoundedCache
from mjcf_model.nodes.base import Element, Node, TypedElement
from mjcf_model.nodes.building import build_node
from mjcf_model.values import Unparsed

__all__ = ["UNPARSED", "Codec", "built_directly", "is_unparsed", "union_members"]

#: The key of ``{"_unparsed": text}``, how a dict holds text a typed field cannot read.
UNPARSED = "_unparsed"
#: A field without a default: ``to_dict`` always writes it.
_REQUIRED = object()
#: How ``to_dict`` writes one stored field: its name, the converter's hook for its
#: type (``None`` when the hook returns the value itself) and its default.
_FieldOut = tuple[str, Callable[[Any], Any] | None, Any]
#: How ``from_dict`` reads one field: its rank among the class's fields, a type whose
#: values need no hook (or ``None``), the converter's structure hook for the field
#: called with the value only, and whether the field is optional (``None`` stays ``None``).
_FieldIn = tuple[int, type | None, Callable[[Any], Any], bool]
#: Fields ``to_dict`` leaves to its walk (``children``) or drops (``layout``).
_NOT_UNSTRUCTURED = frozenset({"children", "layout"})


class Codec:
    """What ``to_dict`` and ``from_dict`` read from the converter, per node class, once.

    The converter's generated hooks read every field of a class (dozens) where a
    node stores a few; these tables let both directions work on the fields a node
    stores, calling for each value the hook the converter has for its type, so the
    result is the converter's own (``tests/serializers/test_dict_codec.py`` checks it).
    """

    def __init__(self, converter: cattrs.Converter, members: tuple[type, ...]) -> None:
        self.converter = converter
        names = [cls.__name__ for cls in members]
        #: The ``"_node"`` tag of each class of the union.
        self.tags: dict[type, str] = {cls: cls.__name__ for cls in members}
        #: The class of each tag, for tags that name one class only.
        self.classes: dict[str, type] = {
            cls.__name__: cls for cls in members if names.count(cls.__name__) == 1
        }
        #: Per class, each field's rank, hook and default (``to_dict``).
        self.fields_out: dict[type, dict[str, tuple[int, Callable[[Any], Any] | None, Any]]] = {}
        #: Per class and stored fields, what ``to_dict`` writes (``(cls, *keys)``); hostile
        #: input could make any number of such shapes, hence the bound.
        self.plans: BoundedCache[tuple[Any, ...], tuple[str, tuple[_FieldOut, ...]] | None] = (
            BoundedCache(4096)
        )
        #: Per class, how ``from_dict`` reads each field (see :meth:`_reader`).
        self.fields_in: dict[type, dict[str, _FieldIn]] = {}

    def plan_of(self, node: Node) -> tuple[str, tuple[_FieldOut, ...]] | None:
        """The tag and fields ``to_dict`` writes for ``node``; ``None`` outside the union."""
        cls = type(node)
        signature = (cls, *node.__dict__)
        if cls not in self.tags:
            return self.plans.remember(signature, None)
        table = self.fields_out.get(cls)
        if table is None:
            table = self.fields_out[cls] = self._fields_out(cls)
        stored = sorted((table[name][0], name) for name in node.__dict__ if name in table)
        plan = (
            self.tags[cls],
            tuple((name, table[name][1], table[name][2]) for _, name in stored),
        )
        return self.plans.remember(signature, plan)

    def _fields_out(self, cls: type) -> dict[str, tuple[int, Callable[[Any], Any] | None, Any]]:
        table: dict[str, tuple[int, Callable[[Any], Any] | None, Any]] = {}
        for rank, field in enumerate(_resolved_fields(cls)):
            if field.name in _NOT_UNSTRUCTURED:
                continue
            inner = _optional_member(field.type)
            hook = self.converter.get_unstructure_hook(field.type if inner is None else inner)
            default = _REQUIRED if field.default is attrs.NOTHING else field.default
            table[field.name] = (rank, None if hook is identity else hook, default)
        return table

    def fields_in_of(self, cls: type) -> dict[str, _FieldIn]:
        """Each field of ``cls`` that a dict may hold, with its structure hook."""
        table = self.fields_in.get(cls)
        if table is None:
            table = self.fields_in[cls] = {}
            for rank, field in enumerate(_resolved_fields(cls)):
                inner = _optional_member(field.type)
                target = field.type if inner is None else inner
                try:
                    hook = self.converter.get_structure_hook(target)
                except cattrs.errors.StructureHandlerNotFoundError:
                    continue  # ``layout``: a dict holding one goes the converter's way, and fails
                unchanged, read = self._reader(hook, target)
                table[field.name] = (rank, unchanged, read, inner is not None)
        return table

    def _reader(
        self, hook: Callable[[Any, Any], Any], target: Any
    ) -> tuple[type | None, Callable[[Any], Any]]:
        """The structure hook ``hook`` for ``target`` called with the value only.

        Also the type whose values the hook returns unchanged, if there is one:
        cattrs reads a ``str`` field as ``str(value)``, which is ``value`` itself
        when it is a ``str`` already.
        """
        if hook is _STRUCTURE_CALL:
            return target, target  # cattrs calls ``target(value)``
        if hook == getattr(self.converter, "_structure_tuple", None):
            parameters = typing.get_args(target)
            if len(parameters) == 2 and parameters[1] is Ellipsis:
                item = parameters[0]
                if self.converter.get_structure_hook(item) is _STRUCTURE_CALL:
                    return None, functools.partial(_mapped_tuple, item)  # its result, in C
        return None, functools.partial(_call_hook, hook, target)


def union_members() -> tuple[type, ...]:
    """The classes of the converter's union: ``Node`` and every subclass whose types resolve.

    A subclass declared where its annotations cannot be resolved (in a function, a
    doctest, a module that imports its types only for type checkers) is left out:
    converting one of its nodes raises, and every other node still converts.
    """
    seen: dict[type, None] = {}
    stack: list[type] = [Node]
    while stack:
        cls = stack.pop()
        if cls in seen:
            continue
        try:
            attrs.resolve_types(cls)
        except Exception:  # NameError, TypeError...: any failure to resolve
            continue
        seen[cls] = None
        stack.extend(cls.__subclasses__())
    return tuple(seen)


def _resolved_fields(cls: type) -> tuple[attrs.Attribute[Any], ...]:
    attrs.resolve_types(cls)  # as cattrs does: the annotations are strings until resolved
    fields: tuple[attrs.Attribute[Any], ...] = attrs.fields(cls)
    return fields


def _optional_member(annotation: Any) -> Any:
    """``X`` of ``X | None`` (cattrs' hook for it gives ``None`` or ``X``'s hook), else ``None``."""
    if typing.get_origin(annotation) in (typing.Union, types.UnionType):
        members = typing.get_args(annotation)
        if len(members) == 2 and type(None) in members:
            return members[0] if members[1] is type(None) else members[1]
    return None


#: cattrs' hook for ``str``, ``float``, ``int``...: ``target(value)`` (private to cattrs:
#: if a release renames it, every value goes through its hook, as it does then anyway).
_STRUCTURE_CALL = getattr(cattrs.BaseConverter, "_structure_call", None)


def _call_hook(hook: Callable[[Any, Any], Any], target: Any, value: Any) -> Any:
    return hook(value, target)


def _mapped_tuple(item: Callable[[Any], Any], values: Any) -> tuple[Any, ...]:
    return tuple(map(item, values))


#: Types of values that cannot be a mapping (``{"_unparsed": text}``), checked first.
_NOT_MAPPINGS = frozenset({str, float, int, bool, list})


def built_directly(codec: Codec, data: Mapping[str, Any], children: list[Node]) -> Node | None:
    """The node the converter builds, or ``None`` where it might not.

    Each value goes through the converter's hook for its field, then the node is
    built once from the fields given (the converter reads every field of the
    class and builds a node with children twice). ``None`` for anything unusual:
    an unknown tag or key, unparsed text outside a typed element, children of a
    comment; an exception for a value a hook or the node refuses.
    """
    cls = codec.classes.get(data.get("_node"))  # type: ignore[arg-type]
    if cls is None:
        return None
    fields = codec.fields_in_of(cls)
    values: dict[str, Any] = {}
    unparsed: dict[str, Unparsed] | None = None
    last = -1
    in_order = True
    for key, value in data.items():
        if key == "_node" or key == "children":
            continue
        reading = fields.get(key)
        if reading is None:
            return None
        rank, unchanged, read, optional = reading
        in_order = in_order and rank > last
        last = rank
        if type(value) is unchanged or (value is None and optional):
            values[key] = value
        elif type(value) not in _NOT_MAPPINGS and is_unparsed(value):
            if unparsed is None:
                unparsed = {}
            unparsed[key] = Unparsed(value[UNPARSED])
        else:
            values[key] = read(value)
    if not in_order:  # the converter gives the node its fields in the class's order
        values = dict(sorted(values.items(), key=lambda item: fields[item[0]][0]))
    if unparsed is not None:
        if not issubclass(cls, TypedElement):
            return None
        values.update(unparsed)
    if children:
        if not issubclass(cls, Element):
            return None
        values["children"] = tuple(children)
    return build_node(cls, values)


def is_unparsed(value: Any) -> bool:
    """Whether ``value`` is ``{"_unparsed": text}``, how ``to_dict`` writes unparsed text."""
    return (
        isinstance(value, Mapping) and set(value) == {UNPARSED} and isinstance(value[UNPARSED], str)
    )
