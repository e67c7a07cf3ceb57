"""Nodes to and from plain dicts (JSON-safe), through one cattrs converter.

Every node becomes a dict whose ``"_node"`` key names its class (a
tag-discriminated union over all node classes; no MJCF attribute starts with
``_``, so the key never collides); only written attributes appear.
Non-finite floats become the strings ``"inf"``, ``"-inf"`` and ``"nan"`` so the
result passes ``json.dumps(..., allow_nan=False)``; an
:class:`~mjcf_model.values.Unparsed` value becomes ``{"_unparsed": text}``.
Both directions walk the tree with an explicit stack: any depth converts.

The converter is a value the caller may own: :func:`make_converter` gives a new one
(its hooks yours to change, nobody else's), and ``to_dict``/``from_dict`` take it as
``converter=``. Without it they use a default one, built on first use and built again
when more node classes have been declared since.

>>> from mjcf_model import Geom
>>> to_dict(Geom(name="g", size=[0.1]))
{'name': 'g', 'size': [0.1], '_node': 'Geom'}
>>> from_dict(to_dict(Geom(name="g", size=[0.1]))) == Geom(name="g", size=[0.1])
True
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Mapping
from typing import Any

import attrs
import cattrs
from cattrs.strategies import configure_tagged_union, include_subclasses

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AttributeMap, Element, Node, TypedElement
from mjcf_model.nodes.building import build_node
from mjcf_model.nodes.declaring import declared_count
from mjcf_model.serializers.dict_codec import (
    UNPARSED,
    Codec,
    built_directly,
    is_unparsed,
    union_members,
)
from mjcf_model.serializers.layout import Layout
from mjcf_model.tree.traversal import with_children
from mjcf_model.values import Floats, Unparsed

__all__ = ["NodeConverter", "default_converter", "from_dict", "make_converter", "to_dict"]


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


class NodeConverter(cattrs.Converter):
    """A cattrs converter configured for node classes (made by :func:`make_converter`).

    It carries the node classes of its ``"_node"`` union and the per-class plans
    ``to_dict`` and ``from_dict`` read from its hooks, made on first use: register
    hooks before the first conversion.
    """

    #: The classes of the ``"_node"`` union, as they were when the converter was made.
    node_classes: tuple[type, ...]
    #: The per-class plans read from the converter's hooks, made on first use.
    codec: Codec | None


def make_converter() -> NodeConverter:
    """A new converter for every node class declared so far, owned by the caller.

    Examples:
        >>> from mjcf_model import Site
        >>> mine = make_converter()
        >>> mine.register_unstructure_hook(str, str.upper)
        >>> to_dict(Site(name="tip"), converter=mine), to_dict(Site(name="tip"))
        ({'name': 'TIP', '_node': 'Site'}, {'name': 'tip', '_node': 'Site'})

    """
    made = NodeConverter(omit_if_default=True, forbid_extra_keys=True)
    made.register_unstructure_hook(float, _unstructure_float)
    made.register_unstructure_hook_func(lambda t: t == Floats, _unstructure_floats)
    made.register_structure_hook_func(
        lambda t: t == Floats, lambda value, _: tuple(map(float, value))
    )
    made.register_unstructure_hook(AttributeMap, dict)
    made.register_structure_hook(AttributeMap, lambda value, _: AttributeMap(value))
    # A layout (how a loaded element was written) is not part of the value: to_dict drops it.
    made.register_unstructure_hook(Layout, lambda _layout: None)
    members = union_members()
    include_subclasses(Node, made, subclasses=members[1:], union_strategy=_union)
    made.node_classes = members
    made.codec = None
    return made


@functools.lru_cache(maxsize=1)
def _default_for(declared: int) -> NodeConverter:
    """The default converter while ``declared`` node classes exist."""
    return make_converter()


def default_converter() -> NodeConverter:
    """The converter ``to_dict`` and ``from_dict`` use when given none.

    It is built on first use (configuring the union over every node class takes longer
    than importing the library, and most programs never need it), and built again once
    more node classes have been declared, so it knows them too.

    Examples:
        >>> default_converter() is default_converter()
        True

    """
    return _default_for(declared_count())


def _codec(converter: cattrs.Converter | None) -> Codec:
    """The plans of ``converter`` (the default one for ``None``), made once per converter."""
    owner = default_converter() if converter is None else converter
    codec = getattr(owner, "codec", None)
    if codec is None:
        members = getattr(owner, "node_classes", None) or union_members()
        codec = Codec(owner, members)
        if isinstance(owner, NodeConverter):
            owner.codec = codec
    return codec


def _children_of(data: Mapping[str, Any], where: Callable[[], str]) -> list[Any]:
    children = data.get("children", [])
    if not isinstance(children, list):
        raise MjcfValueError(f"not a node dict: {where()}.children must be a list")
    return children


def to_dict(node: Node, *, converter: cattrs.Converter | None = None) -> dict[str, Any]:
    """Convert a node and its subtree to plain, JSON-safe dicts and lists.

    Args:
        node: The node.
        converter: The converter whose hooks write each value (see :func:`make_converter`);
            :func:`default_converter` by default.

    Examples:
        >>> from mjcf_model import Joint
        >>> to_dict(Joint(range=(0, float("inf"))))
        {'range': [0.0, 'inf'], '_node': 'Joint'}

    """
    codec = _codec(converter)
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
                    out[name] = {UNPARSED: value.text}
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
            out[key] = {UNPARSED: value.text}
    return out


def from_dict(data: Mapping[str, Any], *, converter: cattrs.Converter | None = None) -> Node:
    """Rebuild a node from what :func:`to_dict` produced.

    Args:
        data: The dict.
        converter: The converter whose hooks read each value (see :func:`make_converter`);
            :func:`default_converter` by default.

    Raises:
        MjcfValueError: The dict does not describe a node; the message says where.

    Examples:
        >>> from_dict({"_node": "Site", "name": "s"})
        Site(name='s')

    """
    if not isinstance(data, Mapping):
        raise MjcfValueError(f"not a node dict: expected a mapping, found {type(data).__name__}")
    codec = _codec(converter)
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
                built.append(_node_from_dict(codec, child, functools.partial(where, index), []))
                continue  # a leaf: built at once, without a stack entry
            stack.append((child, index, [], None))  # on the stack first: errors name it
            stack[-1] = (child, index, [], iter(enumerate(_children_of(child, where))))
            break
        else:
            node = _node_from_dict(codec, current, where, built)
            stack.pop()
            if not stack:
                return node
            stack[-1][2].append(node)


def _node_from_dict(
    codec: Codec, data: Mapping[str, Any], where: Callable[[], str], children: list[Node]
) -> Node:
    """One node from its dict, its children already rebuilt."""
    try:
        node = built_directly(codec, data, children)
    except Exception:  # the converter's way below says what is wrong
        node = None
    return _node_through_converter(codec, data, where, children) if node is None else node


#: What ``from_dict`` reads as the children of a dict without them.
_NO_CHILDREN: list[Any] = []


def _node_through_converter(
    codec: Codec, data: Mapping[str, Any], where: Callable[[], str], children: list[Node]
) -> Node:
    """One node from its dict through the converter, which explains what it refuses."""
    shallow = {k: v for k, v in data.items() if k != "children"}
    unparsed = {k: Unparsed(v[UNPARSED]) for k, v in shallow.items() if is_unparsed(v)}
    for key in unparsed:
        del shallow[key]
    try:
        node: Node = codec.converter.structure(shallow, Node)
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
