"""Nodes to and from plain dicts (JSON-safe), through one cattrs converter.

Every node becomes a dict whose ``"_node"`` key names its class (a
tag-discriminated union over all node classes; no MJCF attribute starts with
``_``, so the key never collides); only written attributes appear.
Non-finite floats become the strings ``"inf"``, ``"-inf"`` and ``"nan"`` so the
result passes ``json.dumps(..., allow_nan=False)``; an
:class:`~mjcf_model.values.Unparsed` value becomes ``{"_unparsed": text}``.
Both directions walk the tree with an explicit stack: any depth converts.

>>> from mjcf_model import Geom
>>> to_dict(Geom(name="g", size=[0.1]))
{'name': 'g', 'size': [0.1], '_node': 'Geom'}
>>> from_dict(to_dict(Geom(name="g", size=[0.1]))) == Geom(name="g", size=[0.1])
True
"""

from __future__ import annotations

import functools
import math
import types
import typing
from collections.abc import Callable, Mapping
from typing import Any

import attrs
import cattrs
from cattrs.fns import identity
from cattrs.strategies import configure_tagged_union, include_subclasses

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AttributeMap, Element, Node, TypedElement
from mjcf_model.nodes.building import build_node
from mjcf_model.nodes.layout import Layout
from mjcf_model.tree.traversal import with_children
from mjcf_model.values import Floats, Unparsed

__all__ = ["converter", "from_dict", "to_dict"]

#: The converter behind :func:`to_dict` and :func:`from_dict`, built on first use
#: (``serializers.dicts.converter``): configuring the union over every node class
#: takes longer than importing the whole library, and most programs never need it.
converter: cattrs.Converter


def _json_float(value: float) -> float | str:
    return value if math.isfinite(value) else repr(value)


def _unstructure_floats(values: Floats | Unparsed) -> list[float | str] | Unparsed:
    if type(values) is Unparsed:
        return values  # written as {"_unparsed": text} by to_dict
    try:
        if all(map(math.isfinite, values)):  # in C: the usual case, nothing to spell
            return list(values)
    except (TypeError, OverflowError):
        pass
    return [_json_float(v) if isinstance(v, float) else v for v in values]


def _unstructure_float(value: float | Unparsed) -> float | str | Unparsed:
    return value if type(value) is Unparsed else _json_float(value)  # type: ignore[arg-type]


def _union(cl: Any, conv: cattrs.Converter) -> None:
    configure_tagged_union(cl, conv, tag_name="_node")


def _built_converter() -> cattrs.Converter:
    return _converter_and_union()[0]


@functools.cache
def _converter_and_union() -> tuple[cattrs.Converter, tuple[type, ...]]:
    """The converter, and the classes of its union of node classes (``"_node"`` tags)."""
    built = cattrs.Converter(omit_if_default=True, forbid_extra_keys=True)
    built.register_unstructure_hook(float, _unstructure_float)
    built.register_unstructure_hook_func(lambda t: t == Floats, _unstructure_floats)
    built.register_structure_hook_func(
        lambda t: t == Floats, lambda value, _: tuple(map(float, value))
    )
    built.register_unstructure_hook(AttributeMap, dict)
    built.register_structure_hook(AttributeMap, lambda value, _: AttributeMap(value))
    # A layout (how a loaded element was written) is not part of the value: to_dict drops it.
    built.register_unstructure_hook(Layout, lambda _layout: None)
    members = _union_members()
    include_subclasses(Node, built, subclasses=members[1:], union_strategy=_union)
    return built, members


def __getattr__(name: str) -> Any:
    if name == "converter":
        return _built_converter()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


_UNPARSED = "_unparsed"
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
#: Past this many, the per-shape plans are forgotten (hostile input could make any number).
_MAX_PLANS = 4096


class _Codec:
    """What ``to_dict`` and ``from_dict`` read from the converter, per node class, once.

    The converter's generated hooks read every field of a class (dozens) where a
    node stores a few; these tables let both directions work on the fields a node
    stores, calling for each value the hook the converter has for its type, so the
    result is the converter's own (``tests/test_equality_speed_paths.py`` checks it).
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
        #: Per class and stored fields, what ``to_dict`` writes (``(cls, *keys)``).
        self.plans: dict[tuple[Any, ...], tuple[str, tuple[_FieldOut, ...]] | None] = {}
        #: Per class, how ``from_dict`` reads each field (see :meth:`_reader`).
        self.fields_in: dict[type, dict[str, _FieldIn]] = {}

    def plan_of(self, node: Node) -> tuple[str, tuple[_FieldOut, ...]] | None:
        """The tag and fields ``to_dict`` writes for ``node``; ``None`` outside the union."""
        cls = type(node)
        signature = (cls, *node.__dict__)
        if len(self.plans) >= _MAX_PLANS:
            self.plans.clear()
        if cls not in self.tags:
            self.plans[signature] = None
            return None
        table = self.fields_out.get(cls)
        if table is None:
            table = self.fields_out[cls] = self._fields_out(cls)
        stored = sorted((table[name][0], name) for name in node.__dict__ if name in table)
        plan = (
            self.tags[cls],
            tuple((name, table[name][1], table[name][2]) for _, name in stored),
        )
        self.plans[signature] = plan
        return plan

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


def _union_members() -> tuple[type, ...]:
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


@functools.cache
def _codec() -> _Codec:
    return _Codec(*_converter_and_union())


def _children_of(data: Mapping[str, Any], where: Callable[[], str]) -> list[Any]:
    children = data.get("children", [])
    if not isinstance(children, list):
        raise MjcfValueError(f"not a node dict: {where()}.children must be a list")
    return children


def to_dict(node: Node) -> dict[str, Any]:
    """Convert a node and its subtree to plain, JSON-safe dicts and lists.

    Example:
        >>> from mjcf_model import Joint
        >>> to_dict(Joint(range=(0, float("inf"))))
        {'range': [0.0, 'inf'], '_node': 'Joint'}

    """
    codec = _codec()
    plans = codec.plans
    result: dict[str, Any] = {}
    stack: list[tuple[Node, dict[str, Any]]] = [(node, result)]
    while stack:
        current, out = stack.pop()
        data = current.__dict__
        plan = plans.get((type(current), *data)) or codec.plan_of(current)
        if plan is None:
            out.update(_unstructured(codec.converter, current))
        else:
            tag, fields = plan
            for name, hook, default in fields:
                value = data[name]
                if value is default or (default is not None and value == default):
                    continue  # the converter leaves out a field holding its default
                if type(value) is Unparsed:
                    out[name] = {_UNPARSED: value.text}
                else:
                    out[name] = value if hook is None else hook(value)
            out["_node"] = tag
        children = data.get("children")
        if children:
            written: list[dict[str, Any]] = [{} for _ in children]
            out["children"] = written
            stack.extend(zip(children, written, strict=True))
    return result


def _unstructured(converter: cattrs.Converter, node: Node) -> dict[str, Any]:
    """``node`` without its children through the converter (a class outside its union fails)."""
    shallow = with_children(node, ()) if isinstance(node, Element) and node.children else node
    out: dict[str, Any] = converter.unstructure(shallow, Node)
    out.pop("layout", None)
    for key, value in out.items():
        if type(value) is Unparsed:
            out[key] = {_UNPARSED: value.text}
    return out


def from_dict(data: Mapping[str, Any]) -> Node:
    """Rebuild a node from what :func:`to_dict` produced.

    Raises:
        MjcfValueError: The dict does not describe a node; the message says where.

    Example:
        >>> from_dict({"_node": "Site", "name": "s"})
        Site(name='s')

    """
    if not isinstance(data, Mapping):
        raise MjcfValueError(f"not a node dict: expected a mapping, found {type(data).__name__}")
    # Children are rebuilt before their parent, from an explicit stack. Each entry
    # keeps its index in its parent: the path for an error is built only then.
    stack: list[tuple[Mapping[str, Any], int, list[Node], Any]] = []

    def where(extra: int | None = None) -> str:
        steps = [f".children[{index}]" for _, index, _, _ in stack[1:]]
        if extra is not None:
            steps.append(f".children[{extra}]")
        return "$" + "".join(steps)

    stack.append((data, 0, [], iter(enumerate(_children_of(data, where)))))
    while True:
        current, _, built, pending = stack[-1]
        for index, child in pending:
            if type(child) is not dict and not isinstance(child, Mapping):
                raise MjcfValueError(f"not a node dict: {where(index)} is not a mapping")
            grandchildren = child.get("children", _NO_CHILDREN)
            if grandchildren is _NO_CHILDREN or (type(grandchildren) is list and not grandchildren):
                built.append(_node_from_dict(child, functools.partial(where, index), []))
                continue  # a leaf: built at once, without a stack entry
            stack.append((child, index, [], None))  # on the stack first: errors name it
            stack[-1] = (child, index, [], iter(enumerate(_children_of(child, where))))
            break
        else:
            node = _node_from_dict(current, where, built)
            stack.pop()
            if not stack:
                return node
            stack[-1][2].append(node)


def _node_from_dict(
    data: Mapping[str, Any], where: Callable[[], str], children: list[Node]
) -> Node:
    """One node from its dict, its children already rebuilt."""
    try:
        node = _built_directly(data, children)
    except Exception:  # the converter's way below says what is wrong
        node = None
    return _node_through_converter(data, where, children) if node is None else node


#: What ``from_dict`` reads as the children of a dict without them.
_NO_CHILDREN: list[Any] = []
#: Types of values that cannot be a mapping (``{"_unparsed": text}``), checked first.
_NOT_MAPPINGS = frozenset({str, float, int, bool, list})


def _built_directly(data: Mapping[str, Any], children: list[Node]) -> Node | None:
    """The node :func:`_node_through_converter` builds, or ``None`` where it might not.

    Each value goes through the converter's hook for its field, then the node is
    built once from the fields given (the converter reads every field of the
    class and builds a node with children twice). ``None`` for anything unusual:
    an unknown tag or key, unparsed text outside a typed element, children of a
    comment; an exception for a value a hook or the node refuses.
    """
    codec = _codec()
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
        elif type(value) not in _NOT_MAPPINGS and _is_unparsed(value):
            if unparsed is None:
                unparsed = {}
            unparsed[key] = Unparsed(value[_UNPARSED])
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


def _is_unparsed(value: Any) -> bool:
    """Whether ``value`` is ``{"_unparsed": text}``, how ``to_dict`` writes unparsed text."""
    return (
        isinstance(value, Mapping)
        and set(value) == {_UNPARSED}
        and isinstance(value[_UNPARSED], str)
    )


def _node_through_converter(
    data: Mapping[str, Any], where: Callable[[], str], children: list[Node]
) -> Node:
    """One node from its dict through the converter, which explains what it refuses."""
    shallow = {k: v for k, v in data.items() if k != "children"}
    unparsed = {k: Unparsed(v[_UNPARSED]) for k, v in shallow.items() if _is_unparsed(v)}
    for key in unparsed:
        del shallow[key]
    try:
        node: Node = _built_converter().structure(shallow, Node)
    except MjcfValueError as error:
        raise MjcfValueError(f"{where()}: {error.detail}") from None
    except (cattrs.BaseValidationError, KeyError, TypeError, ValueError) as error:
        detail = (
            "; ".join(cattrs.transform_error(error, path=where()))
            if isinstance(error, cattrs.BaseValidationError)
            else f"{where()}: {error}"
        )
        raise MjcfValueError(f"not a node dict: {detail}") from None
    if isinstance(node, TypedElement):
        values: dict[str, Any] = dict(unparsed)
        if children:
            values["children"] = tuple(children)
        return build_node(type(node), values, node) if values else node
    if unparsed:
        raise MjcfValueError(f"not a node dict: {where()}: only typed fields hold unparsed text")
    if isinstance(node, Element) and children:
        return attrs.evolve(node, children=tuple(children))
    if children:
        raise MjcfValueError(f"not a node dict: {where()}: a {type(node).__name__} has no children")
    return node
