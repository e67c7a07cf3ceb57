"""Nodes to and from plain dicts (JSON-safe), through one cattrs converter.

Every node becomes a dict whose ``"_node"`` key names its class (a
tag-discriminated union over all node classes; no MJCF attribute starts with
``_``, so the key never collides); only written attributes appear.
Non-finite floats become the strings ``"inf"``, ``"-inf"`` and ``"nan"`` so the
result passes ``json.dumps(..., allow_nan=False)``.

>>> from mjcf_model import Geom
>>> to_dict(Geom(name="g", size=[0.1]))
{'name': 'g', 'size': [0.1], '_node': 'Geom'}
>>> from_dict(to_dict(Geom(name="g", size=[0.1]))) == Geom(name="g", size=[0.1])
True
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from typing import Any

import cattrs
from cattrs.strategies import configure_tagged_union, include_subclasses

from mjcf_model.base import AttributeMap, Node
from mjcf_model.errors import MjcfValueError
from mjcf_model.values import Floats

__all__ = ["converter", "from_dict", "to_dict"]

#: The converter behind :func:`to_dict` and :func:`from_dict`, built on first use
#: (``serializers.dicts.converter``): configuring the union over every node class
#: takes longer than importing the whole library, and most programs never need it.
converter: cattrs.Converter


def _json_float(value: float) -> float | str:
    return value if math.isfinite(value) else repr(value)


def _unstructure_floats(values: Floats) -> list[float | str]:
    return [_json_float(v) if isinstance(v, float) else v for v in values]


def _union(cl: Any, conv: cattrs.Converter) -> None:
    configure_tagged_union(cl, conv, tag_name="_node")


@functools.cache
def _built_converter() -> cattrs.Converter:
    built = cattrs.Converter(omit_if_default=True, forbid_extra_keys=True)
    built.register_unstructure_hook(float, _json_float)
    built.register_unstructure_hook_func(lambda t: t == Floats, _unstructure_floats)
    built.register_structure_hook_func(
        lambda t: t == Floats, lambda value, _: tuple(float(v) for v in value)
    )
    built.register_unstructure_hook(AttributeMap, dict)
    built.register_structure_hook(AttributeMap, lambda value, _: AttributeMap(value))
    include_subclasses(Node, built, union_strategy=_union)
    return built


def __getattr__(name: str) -> Any:
    if name == "converter":
        return _built_converter()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def to_dict(node: Node) -> dict[str, Any]:
    """Convert a node and its subtree to plain, JSON-safe dicts and lists.

    Example:
        >>> from mjcf_model import Joint
        >>> to_dict(Joint(range=(0, float("inf"))))
        {'range': [0.0, 'inf'], '_node': 'Joint'}

    """
    result: dict[str, Any] = _built_converter().unstructure(node, Node)
    return result


def from_dict(data: Mapping[str, Any]) -> Node:
    """Rebuild a node from what :func:`to_dict` produced.

    Raises:
        MjcfValueError: The dict does not describe a node; the message says where.

    Example:
        >>> from_dict({"_node": "Site", "name": "s"})
        Site(name='s')

    """
    try:
        node: Node = _built_converter().structure(dict(data), Node)
    except MjcfValueError:
        raise
    except (cattrs.BaseValidationError, KeyError, TypeError, ValueError) as error:
        detail = (
            "; ".join(cattrs.transform_error(error))
            if isinstance(error, cattrs.BaseValidationError)
            else str(error)
        )
        raise MjcfValueError(f"not a node dict: {detail}") from None
    return node
