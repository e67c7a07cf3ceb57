"""The context every scaling rule reads, and the arithmetic of scaled values.

A :class:`ScaleContext` holds the factors of one scaling, what they come to for
lengths, areas, volumes, masses and inertias, the model's default classes and its
joints (for keyframes and actuators); :func:`numbers`, :func:`times` and
:func:`factor_cycle` read and multiply attribute values.

>>> context = ScaleContext(factors=(2.0, 2.0, 2.0), mass="volume")
>>> context.mean, context.mass_factor, times("0.5 1", context.cycles.per_axis)
(2.0, 8.0, '1 2')
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

import attrs
import numpy as np

from mjcf_model.nodes.base import AnyElement
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.joints import JointInfo, joint_layout
from mjcf_model.values import Value, format_value, numbers_of

__all__ = [
    "Cycles",
    "ScaleContext",
    "factor_cycle",
    "times",
    "times_cycle",
]

_T = TypeVar("_T")


@attrs.frozen(kw_only=True)
class Cycles:
    """The factors positions, lengths, masses and inertias cycle over, worked out once."""

    #: Per axis: x, y and z (one number when they are equal).
    per_axis: tuple[float, ...]
    #: The mean factor.
    mean: tuple[float]
    #: The mass factor.
    mass: tuple[float]
    #: ixx, iyy, izz, ixy, ixz, iyz (exact when uniform).
    inertia: tuple[float, ...]
    #: The factors of a geom or site ``size`` of 0, 1, 2 or 3 written values, by
    #: robosuite's per-axis convention: three values scale per axis; two are a
    #: radius (mean of x and y) and a half-length (z); one is a radius (mean of
    #: all three); values completed from defaults beyond those written scale per
    #: axis. Exact when uniform.
    sizes: tuple[tuple[float, ...], ...]


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
    #: The factor for a length without a direction.
    mean: float = attrs.field(init=False, eq=False, repr=False)
    #: The factor for a volume.
    volume: float = attrs.field(init=False, eq=False, repr=False)
    #: The factor for an area (exact when uniform; per axis the volume's to the 2/3).
    area: float = attrs.field(init=False, eq=False, repr=False)
    #: The factor for a mass: 1, or the volume's under ``mass="volume"``.
    mass_factor: float = attrs.field(init=False, eq=False, repr=False)
    #: The factors of the value rules, as :func:`factor_cycle` makes them.
    cycles: Cycles = attrs.field(init=False, eq=False, repr=False)
    #: The joints and what rules work out once per scaling, on first use.
    _memo: dict[object, Any] = attrs.field(factory=dict, init=False, eq=False, repr=False)
    #: The geoms met whose mass, spread over their surface, grows with the area while
    #: the other masses grow with the volume (under ``mass="volume"``), for people.
    surface_masses: list[str] = attrs.field(factory=list, init=False, eq=False, repr=False)

    @mean.default
    def _mean(self) -> float:
        x, y, z = self.factors
        if x == y == z:
            return x  # exactly: (0.8 + 0.8 + 0.8) / 3 is 0.8000000000000002
        return float(np.mean(self.factors))

    @volume.default
    def _volume(self) -> float:
        return self.factors[0] * self.factors[1] * self.factors[2]

    @area.default
    def _area(self) -> float:
        if self.factors[0] == self.factors[1] == self.factors[2]:
            return self.factors[0] ** 2
        return float(self.volume ** (2 / 3))

    @mass_factor.default
    def _mass_factor(self) -> float:
        return self.volume if self.mass == "volume" else 1.0

    @cycles.default
    def _cycles(self) -> Cycles:
        x, y, z = self.factors
        mass = self.mass_factor
        inertia = (
            mass * (y * y + z * z) / 2,
            mass * (x * x + z * z) / 2,
            mass * (x * x + y * y) / 2,
            mass * x * y,
            mass * x * z,
            mass * y * z,
        )
        by_count = {0: (), 1: (self.mean,), 2: ((x + y) / 2, z), 3: (x, y, z)}
        return Cycles(
            per_axis=factor_cycle(self.factors),
            mean=(self.mean,),
            mass=(mass,),
            inertia=factor_cycle(inertia),
            sizes=tuple((*by_count[count], *(x, y, z)[count:]) for count in range(4)),
        )

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

    def cached(self, name: object, compute: Callable[[], _T]) -> _T:
        """``compute()``, worked out once per scaling and kept under ``name`` (any hashable)."""
        if name not in self._memo:
            self._memo[name] = compute()
        found: _T = self._memo[name]
        return found

    def along(self, axis: tuple[float, ...]) -> float:
        """The factor for a length along ``axis`` (robosuite: norm of the scaled unit axis)."""
        return self.cached(("along", tuple(axis)), lambda: self._along(axis))

    def _along(self, axis: tuple[float, ...]) -> float:
        direction = np.asarray(axis, dtype=float)
        norm = np.linalg.norm(direction)
        if norm == 0:
            return self.factors[0]
        return float(np.linalg.norm(direction / norm * np.asarray(self.factors)))


def times(value: Value, factors: Any) -> Value:
    """``value`` multiplied by ``factors`` (cycled), in the value's own shape.

    Text (an attribute a typed field keeps as text, a plugin setting) stays text.

    Examples:
        >>> times((1.0, 2.0), 2), times(0.5, [2, 3]), times("0.25 1", 2)
        ((2.0, 4.0), 1.0, '0.5 2')

    """
    return times_cycle(value, factor_cycle(factors))


def times_cycle(value: Value, cycle: tuple[float, ...]) -> Value:
    """:func:`times` by factors already made a cycle (:func:`factor_cycle`).

    Examples:
        >>> times_cycle((1.0, 2.0), (2.0,)), times_cycle("1 1 1", (1.0, 2.0))
        ((2.0, 4.0), '1 2 1')

    """
    if type(value) is tuple:  # a typed vector: no text to read
        if len(cycle) == 1:
            factor = cycle[0]
            return tuple([v * factor for v in value])
        if len(cycle) == len(value):
            return tuple([v * f for v, f in zip(value, cycle, strict=True)])
    elif type(value) is float:
        return value * cycle[0]
    found = numbers_of(value)
    assert found is not None
    result = tuple(n * cycle[i % len(cycle)] for i, n in enumerate(found))
    if isinstance(value, str):
        return format_value(result)
    if isinstance(value, (int, float)) and len(result) == 1:
        return result[0]
    return result


def factor_cycle(factors: Any) -> tuple[float, ...]:
    """``factors`` as a tuple of floats to cycle over a value; one float when all are equal.

    Examples:
        >>> factor_cycle(2), factor_cycle([2, 2, 2]), factor_cycle((1.0, 2.0))
        ((2.0,), (2.0,), (1.0, 2.0))

    """
    if type(factors) is float:
        return (factors,)
    cycle: tuple[float, ...]
    if type(factors) in (tuple, list) and all(type(f) is float for f in factors):
        cycle = tuple(factors)
    else:
        cycle = tuple(float(f) for f in np.ravel(np.asarray(factors, dtype=float)))
    if len(cycle) > 1 and all(f == cycle[0] for f in cycle):
        return cycle[:1]  # the same products, one multiplication each
    return cycle
