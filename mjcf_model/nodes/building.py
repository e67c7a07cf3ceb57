"""Building nodes fast: store the given fields, convert only what was given.

attrs' generated ``__init__`` converts and stores every field; a typed class
has dozens and an element writes a few. :func:`build_node` stores only the
given fields in the instance's ``__dict__`` (absent ones read their default
from the class, see :func:`~mjcf_model.nodes.declaring.node`), running each given
field's converter and validator. It is an owned contract, checked by
``tests/mjcf_model/nodes/test_building.py`` for every class of the registry: the result equals
``cls(**values)``, or ``attrs.evolve(base, **values)`` when a base is given.
:func:`~mjcf_model.nodes.declaring.node` refuses, when a class is declared, what the
builder could not honour (``__attrs_post_init__``, slots, non-init fields).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

if TYPE_CHECKING:
    from mjcf_model.nodes.node_info import DeclaredNode as Node

__all__ = ["build_node", "fill_node"]

_N = TypeVar("_N", bound="Node")
_set_dict = object.__setattr__


def build_node(
    cls: type[_N],
    values: Mapping[str, Any],
    base: _N | None = None,
    *,
    memo: dict[tuple[Any, str], Any] | None = None,
) -> _N:
    """A ``cls`` node with field ``values`` converted and validated, the rest from ``base``.

    The same result as ``cls(**values)`` (or ``attrs.evolve(base, **values)``),
    storing only the fields that differ from their default. ``children`` must be
    a sequence of nodes already (it is not checked again). A reader passes one
    ``memo`` dict per document: text met twice (``pos="0 0 0"``) is converted
    once, and the nodes share the value.

    Examples:
        >>> from mjcf_model import Geom
        >>> g = build_node(Geom, {"size": "0.1 0.2"})
        >>> g == Geom(size=[0.1, 0.2]), build_node(Geom, {"name": "g"}, g).size
        (True, (0.1, 0.2))
        >>> build_node(Geom, {"colour": "red"})
        Traceback (most recent call last):
        ...
        TypeError: Geom has no field 'colour'

    """
    node = object.__new__(cls)
    fill_node(node, values, base, checked_children=False, memo=memo)
    return node


def fill_node(
    node: Node,
    values: Mapping[str, Any],
    base: Node | None,
    *,
    checked_children: bool,
    memo: dict[tuple[Any, str], Any] | None = None,
) -> None:
    """Give the new ``node`` its fields: ``values`` converted and validated, the rest from ``base``.

    The one place nodes are filled: :func:`build_node` and the constructor of
    every node class (see :func:`~mjcf_model.nodes.declaring.node`) both call it.
    ``checked_children`` runs the ``children`` converter (the constructor does;
    the readers and transforms pass tuples of nodes they built); ``memo`` keeps
    the converted value of each text (see :func:`build_node`).

    Examples:
        >>> from mjcf_model import Site
        >>> site = object.__new__(Site)
        >>> fill_node(site, {"name": "tip"}, None, checked_children=True)
        >>> site.name, vars(site)
        ('tip', {'name': 'tip'})

    """
    cls = type(node)
    info = cls.__node_info__
    data: dict[str, Any] = {} if base is None else base.__dict__.copy()
    converters, validators, defaults = info.converters, info.validators, info.defaults
    for name, value in values.items():
        if name == "children" and not checked_children:
            value = value if isinstance(value, tuple) else tuple(value)
        else:
            converter = converters.get(name)
            if converter is None:
                if name not in info.field_names:
                    raise TypeError(f"{cls.__name__} has no field {name!r}")
            elif memo is not None and type(value) is str:
                key = (converter, value)
                converted = memo.get(key, memo)
                if converted is memo:
                    converted = memo[key] = converter(value)
                value = converted
            else:
                value = converter(value)
        checks = validators.get(name)
        if checks is not None:
            checks[0](node, checks[1], value)
        if value is None and defaults.get(name, ...) is None:
            data.pop(name, None)
        else:
            data[name] = value
    if "children" in values and "layout" not in values:
        layout = data.get("layout")
        if layout is not None:  # the nodes it replaced are not kept alive by the layout
            data["layout"] = layout.without_old_children(data.get("children", ()))
    if base is None and info.required and not info.required <= data.keys():
        raise TypeError(f"{cls.__name__} needs {', '.join(sorted(info.required - data.keys()))}")
    _set_dict(node, "__dict__", data)
