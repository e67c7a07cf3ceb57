"""Building typed nodes fast: one slot assignment per field, converting only given values.

attrs' generated ``__init__`` calls every field's converter; a typed class has
dozens of fields and an element writes a few, so the readers and the transforms
build nodes here instead. The result is the same object ``cls(**values)`` (or
``attrs.evolve(base, **values)``) would give.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

import attrs

if TYPE_CHECKING:
    from mjcf_model.base import TypedElement

__all__ = ["build_node"]

_TE = TypeVar("_TE", bound="TypedElement")


class _Plan:
    """How to build instances of one typed class without attrs' generated ``__init__``.

    Node values that were already converted (a transform copying fields) need no
    conversion again, and fields left at their default need no converter call:
    building a node then costs one assignment per field.
    """

    __slots__ = ("converters", "defaults", "slots", "validators")

    def __init__(self, cls: type[TypedElement]) -> None:
        #: Per field: the slot's setter and the field's default (converted).
        self.defaults: list[tuple[Any, Any]] = []
        #: Per field name: the slot descriptor (its ``__get__``/``__set__`` are the fastest way in).
        self.slots: dict[str, Any] = {}
        self.converters: dict[str, Any] = {}
        self.validators: dict[str, Any] = {}
        for field in attrs.fields(cls):
            default = field.default
            factory = getattr(default, "factory", None)
            if callable(factory) and hasattr(default, "takes_self"):  # an attrs Factory
                default = factory()
            elif field.converter is not None and default is not None:
                default = field.converter(default)
            slot = next(c.__dict__[field.name] for c in cls.__mro__ if field.name in c.__dict__)
            self.slots[field.name] = slot
            self.defaults.append((slot.__set__, default))
            if field.converter is not None:
                self.converters[field.name] = field.converter
            if field.validator is not None:
                self.validators[field.name] = (field.validator, field)


_PLANS: dict[type[TypedElement], _Plan] = {}


def _plan(cls: type[TypedElement]) -> _Plan:
    plan = _PLANS.get(cls)
    if plan is None:
        plan = _PLANS[cls] = _Plan(cls)
    return plan


def build_node(cls: type[_TE], values: Mapping[str, Any], base: _TE | None = None) -> _TE:
    """A ``cls`` node with field ``values`` converted and validated, the rest from ``base``.

    The same result as ``cls(**values)`` (or ``attrs.evolve(base, **values)``) for
    values of the fields' types, without running every field's converter: the
    readers and transforms build nodes this way. ``children`` must be a sequence
    of nodes already (it is not checked again).

    Example:
        >>> from mjcf_model import Geom
        >>> g = build_node(Geom, {"size": "0.1 0.2"})
        >>> g == Geom(size=[0.1, 0.2]), build_node(Geom, {"name": "g"}, g).size
        (True, (0.1, 0.2))

    """
    plan = _plan(cls)
    node = object.__new__(cls)
    if base is None:
        for setter, default in plan.defaults:
            setter(node, default)
    else:
        for slot in plan.slots.values():
            slot.__set__(node, slot.__get__(base))
    converters, validators, slots = plan.converters, plan.validators, plan.slots
    for name, value in values.items():
        if name == "children":
            value = value if isinstance(value, tuple) else tuple(value)
        else:
            converter = converters.get(name)
            if converter is not None:
                value = converter(value)
        checks = validators.get(name)
        if checks is not None:
            checks[0](node, checks[1], value)
        slots[name].__set__(node, value)
    return node
