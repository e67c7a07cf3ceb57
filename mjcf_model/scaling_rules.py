"""The pieces scaling rules are made of, and the context every rule reads.

A rule reads an element (and the classes it inherits from) and returns the
attribute changes that scale it; :mod:`mjcf_model.scaling_table` assembles one
per schema key from these pieces.

>>> from mjcf_model import Body
>>> points("pos")[0](Body(pos=[1, 2, 3]), (), ScaleContext(factors=(2.0, 1.0, 1.0)))
{'pos': (2.0, 2.0, 3.0)}
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

import attrs
import numpy as np

from mjcf_model.base import AnyElement, get_attribute
from mjcf_model.defaults import DefaultClasses
from mjcf_model.traversal import keyed_walk
from mjcf_model.values import Value, format_value

__all__ = [
    "NO_LENGTHS",
    "Changes",
    "JointInfo",
    "Rule",
    "ScaleContext",
    "builtin_default",
    "combine",
    "inertias",
    "joint_layout",
    "joint_type",
    "lengths",
    "masses",
    "numbers",
    "parts",
    "points",
    "times",
    "with_builtin",
]

Changes = dict[str, Value | None]

_T = TypeVar("_T")


@attrs.frozen(kw_only=True)
class JointInfo:
    """A joint as the scaling of keyframes and actuators needs it."""

    #: Its name, or ``None``.
    name: str | None
    #: ``free``, ``ball``, ``slide`` or ``hinge`` (its own or its class's).
    type: str
    #: Its axis (its own, its class's, or MuJoCo's default ``0 0 1``).
    axis: tuple[float, ...]


@attrs.frozen(kw_only=True)
class ScaleContext:
    """What every rule needs: the factors, the mass policy, classes and joints."""

    #: The x, y and z factors.
    factors: tuple[float, float, float]
    #: ``"keep"`` or ``"volume"``.
    mass: str = "keep"
    #: The model's default classes.
    classes: DefaultClasses = attrs.field(factory=DefaultClasses.empty)
    #: The tree being scaled, whose joints keyframes, fixed tendons and position
    #: actuators refer to (read only when one of those is met).
    model: AnyElement | None = None
    #: The joints, worked out on first use.
    _memo: dict[str, Any] = attrs.field(factory=dict, init=False, eq=False, repr=False)

    @property
    def layout(self) -> tuple[JointInfo, ...] | None:
        """The joints in ``qpos`` order, or ``None`` when that order cannot be known."""
        if "layout" not in self._memo:
            found = () if self.model is None else joint_layout(self.model, self.classes)
            self._memo["layout"] = found
        layout: tuple[JointInfo, ...] | None = self._memo["layout"]
        return layout

    def joint(self, name: object) -> JointInfo | None:
        """The joint called ``name`` (``None`` for no such joint, or no known order)."""
        if "by_name" not in self._memo:
            self._memo["by_name"] = {j.name: j for j in self.layout or () if j.name}
        found: JointInfo | None = self._memo["by_name"].get(name)
        return found

    def cached(self, name: str, compute: Callable[[], _T]) -> _T:
        """``compute()``, worked out once per scaling and kept under ``name``."""
        if name not in self._memo:
            self._memo[name] = compute()
        found: _T = self._memo[name]
        return found

    @property
    def mean(self) -> float:
        """The factor for a length without a direction."""
        return float(np.mean(self.factors))

    def along(self, axis: tuple[float, ...]) -> float:
        """The factor for a length along ``axis`` (robosuite: norm of the scaled unit axis)."""
        direction = np.asarray(axis, dtype=float)
        norm = np.linalg.norm(direction)
        if norm == 0:
            return self.factors[0]
        return float(np.linalg.norm(direction / norm * np.asarray(self.factors)))

    @property
    def volume(self) -> float:
        """The factor for a volume."""
        return self.factors[0] * self.factors[1] * self.factors[2]

    @property
    def area(self) -> float:
        """The factor for an area (exact when uniform; per axis the volume's to the 2/3)."""
        if self.factors[0] == self.factors[1] == self.factors[2]:
            return self.factors[0] ** 2
        return float(self.volume ** (2 / 3))


#: ``rule(element, ancestors, context)``: the attribute changes that scale ``element``.
Rule = Callable[[AnyElement, Sequence[AnyElement], ScaleContext], Changes]


def numbers(value: Value | None) -> tuple[float, ...] | None:
    """The numbers in an attribute value, typed or text; ``None`` when it has none.

    Example:
        >>> numbers("1 2.5"), numbers(3), numbers("x")
        ((1.0, 2.5), (3.0,), None)

    """
    if value is None:
        return None
    if isinstance(value, str):
        try:
            return tuple(float(part) for part in value.split())
        except ValueError:
            return None
    if isinstance(value, (int, float)):
        return (float(value),)
    return tuple(float(v) for v in value)


def times(value: Value, factors: Any) -> Value:
    """``value`` multiplied by ``factors`` (cycled), in the value's own shape.

    Text (an attribute a typed field keeps as text, a plugin setting) stays text.

    Example:
        >>> times((1.0, 2.0), 2), times(0.5, [2, 3]), times("0.25 1", 2)
        ((2.0, 4.0), 1.0, '0.5 2')

    """
    found = numbers(value)
    assert found is not None
    cycle = np.resize(np.asarray(factors, dtype=float), len(found))
    result = tuple(float(n * f) for n, f in zip(found, cycle, strict=True))
    if isinstance(value, str):
        return format_value(result)
    if isinstance(value, (int, float)) and len(result) == 1:
        return result[0]
    return result


@functools.cache
def builtin_default(tag: str, attribute: str) -> tuple[float, ...]:
    """MuJoCo's built-in default of an attribute, read from an empty ``MjSpec``.

    Values MuJoCo keeps in single precision are given by their shortest text
    (``0.02``, not ``0.019999999552965164``).

    Example:
        >>> builtin_default("site", "size"), builtin_default("geom", "density")
        ((0.005, 0.005, 0.005), (1000.0,))

    """
    import mujoco

    value = getattr(getattr(mujoco.MjSpec().default, tag), attribute)
    values = []
    for number in np.atleast_1d(np.asarray(value, dtype=float)):
        single = np.float32(number)
        values.append(float(str(single)) if float(single) == number else float(number))
    return tuple(values)


def _in_default(ancestors: Sequence[AnyElement]) -> bool:
    return bool(ancestors) and ancestors[-1].tag == "default"


def _scale(attribute: str, factors: Callable[[ScaleContext], Any]) -> Rule:
    """Multiply ``attribute`` where written."""

    def rule(
        element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
    ) -> Changes:
        value = get_attribute(element, attribute)
        if numbers(value) is None:
            return {}
        assert value is not None
        return {attribute: times(value, factors(context))}

    return rule


def points(*attributes: str) -> list[Rule]:
    """Positions: x, y and z (repeated for lists of points) scale per axis."""
    return [_scale(a, lambda c: c.factors) for a in attributes]


def lengths(*attributes: str) -> list[Rule]:
    """Lengths without a direction: the mean factor."""
    return [_scale(a, lambda c: c.mean) for a in attributes]


def parts(attribute: str, unit: tuple[float, ...], start: int) -> Rule:
    """Multiply the values from index ``start`` on (friction: torsion and rolling)."""

    def rule(
        element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
    ) -> Changes:
        found = numbers(get_attribute(element, attribute))
        if found is None:
            return {}
        factors = [*unit[:start], *[context.mean] * (len(found) - start)][: len(found)]
        return {attribute: tuple(n * f for n, f in zip(found, factors, strict=True))}

    return rule


def masses(*attributes: str) -> list[Rule]:
    """Masses: unchanged, or with the volume under ``mass="volume"``."""
    return [_scale(a, lambda c: c.volume if c.mass == "volume" else 1.0) for a in attributes]


def _inertia_factors(context: ScaleContext) -> tuple[float, float, float, float, float, float]:
    """Factors for ixx, iyy, izz, ixy, ixz, iyz (exact when uniform)."""
    x, y, z = context.factors
    mass = context.volume if context.mass == "volume" else 1.0
    return (
        mass * (y * y + z * z) / 2,
        mass * (x * x + z * z) / 2,
        mass * (x * x + y * y) / 2,
        mass * x * y,
        mass * x * z,
        mass * y * z,
    )


def inertias(*attributes: str) -> list[Rule]:
    """Inertias: length squared, times the mass factor (per axis an approximation)."""
    return [_scale(a, _inertia_factors) for a in attributes]


def with_builtin(
    attribute: str,
    tag: str,
    builtin: Callable[[], tuple[float, ...]],
    factors: Callable[[AnyElement, Sequence[AnyElement], ScaleContext], Any],
) -> Rule:
    """Scale ``attribute``; where nothing sets it, write MuJoCo's default (``builtin()``) scaled.

    A partial value (a sphere site's one size) is completed from its classes and
    the built-in default first, because the values it leaves out are lengths too.
    In a default class only what is written is scaled.
    """

    def rule(
        element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
    ) -> Changes:
        value = get_attribute(element, attribute)
        own = numbers(value)
        scale = factors(element, ancestors, context)
        if _in_default(ancestors) or (own is not None and len(own) >= len(builtin())):
            return {} if value is None or own is None else {attribute: times(value, scale)}
        full = list(builtin())
        covered = 0  # how many leading values the classes write (and scale themselves)
        classes = context.classes
        for name in reversed(classes.chain(classes.class_of(element, ancestors))):
            setting = classes.settings.get((name, tag))
            inherited = numbers(get_attribute(setting, attribute)) if setting else None
            if inherited:
                full[: len(inherited)] = inherited
                covered = max(covered, len(inherited))
        written = len(own or ())
        if covered >= len(full):
            return {} if value is None or own is None else {attribute: times(value, scale)}
        full[:written] = own or ()
        return {attribute: times(tuple(full) if len(full) > 1 else full[0], scale)}

    return rule


def combine(*rules: Rule | list[Rule]) -> Rule:
    """One rule applying several, in order."""
    flat: list[Rule] = []
    for given in rules:
        flat.extend(given if isinstance(given, list) else [given])

    def rule(
        element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
    ) -> Changes:
        changes: Changes = {}
        for part in flat:
            changes.update(part(element, ancestors, context))
        return changes

    return rule


def _no_lengths(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    return {}


#: The rule of elements without lengths.
NO_LENGTHS: Rule = _no_lengths


def joint_layout(node: AnyElement, classes: DefaultClasses) -> tuple[JointInfo, ...] | None:
    """The joints of ``node`` in ``qpos`` order; ``None`` when replicate or flexcomp hide some.

    Example:
        >>> from mjcf_model import Body, Joint
        >>> body = Body(children=[Joint(type="slide")])
        >>> [j.type for j in joint_layout(body, DefaultClasses.empty())]
        ['slide']

    """
    joints: list[JointInfo] = []
    for element, key, ancestors in keyed_walk(node):
        if key in ("body/replicate", "body/flexcomp", "body/attach"):
            return None
        kind = joint_type(element, key, ancestors, classes)
        if kind is not None:
            axis = numbers(classes.resolve(element, ancestors, "axis")) if kind != "free" else None
            joints.append(JointInfo(name=_name(element), type=kind, axis=axis or (0.0, 0.0, 1.0)))
    return tuple(joints)


def joint_type(
    element: AnyElement, key: str | None, ancestors: Sequence[AnyElement], classes: DefaultClasses
) -> str | None:
    """The type of a body's joint: ``free``, ``ball``, ``slide`` or ``hinge``.

    Its own type or its class's (MuJoCo's default is ``hinge``); ``None`` for an
    element that is not a body's joint.

    Example:
        >>> from mjcf_model import Joint
        >>> joint_type(Joint(type="slide"), "body/joint", (), DefaultClasses.empty())
        'slide'

    """
    if key == "body/freejoint":
        return "free"
    if key != "body/joint":
        return None
    return str(classes.resolve(element, ancestors, "type") or "hinge")


def _name(element: AnyElement) -> str | None:
    name = get_attribute(element, "name")
    return name if isinstance(name, str) else None
