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
import operator
from collections.abc import Callable, Iterator, Sequence
from typing import Any, TypeVar

import attrs
import numpy as np

from mjcf_model.base import AnyElement, get_attribute
from mjcf_model.defaults import DefaultClasses
from mjcf_model.queries import attribute_values
from mjcf_model.traversal import keyed_walk
from mjcf_model.values import Value, format_value

__all__ = [
    "NO_LENGTHS",
    "Changes",
    "Cycles",
    "JointInfo",
    "Rule",
    "ScaleContext",
    "ValueRule",
    "ValueScale",
    "factor_cycle",
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

    @mean.default
    def _mean(self) -> float:
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
    if type(value) is tuple:
        return tuple(map(float, value))
    if type(value) is float:
        return (value,)
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
    return _times(value, factor_cycle(factors))


def _times(value: Value, cycle: tuple[float, ...]) -> Value:
    """:func:`times` by factors already made a cycle (:func:`factor_cycle`)."""
    if type(value) is tuple:  # a typed vector: no text to read
        if len(cycle) == 1:
            factor = cycle[0]
            return tuple([v * factor for v in value])
        if len(cycle) == len(value):
            return tuple([v * f for v, f in zip(value, cycle, strict=True)])
    elif type(value) is float:
        return value * cycle[0]
    found = numbers(value)
    assert found is not None
    result = tuple(n * cycle[i % len(cycle)] for i, n in enumerate(found))
    if isinstance(value, str):
        return format_value(result)
    if isinstance(value, (int, float)) and len(result) == 1:
        return result[0]
    return result


def factor_cycle(factors: Any) -> tuple[float, ...]:
    """``factors`` as a tuple of floats to cycle over a value; one float when all are equal.

    Example:
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


#: ``scale(value, context)``: the scaled value of one written attribute, ``None`` to keep it.
ValueScale = Callable[[Value, ScaleContext], Value | None]


class ValueRule:
    """The rule that scales one attribute, where written, by a function of its value alone.

    :func:`combine` reads the attributes of all the value rules it holds at once.

    Example:
        >>> from mjcf_model import Body
        >>> rule = ValueRule("pos", lambda value, context: value[:2] + (0.0,))
        >>> rule(Body(pos=[1, 2, 3]), (), ScaleContext(factors=(2.0, 2.0, 2.0)))
        {'pos': (1.0, 2.0, 0.0)}

    """

    __slots__ = ("attribute", "scale")

    def __init__(self, attribute: str, scale: ValueScale) -> None:
        #: The attribute scaled.
        self.attribute = attribute
        #: Its scaled value, given the written one.
        self.scale = scale

    def __call__(
        self, element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
    ) -> Changes:
        """The change of :attr:`attribute` on ``element``."""
        value = get_attribute(element, self.attribute)
        new = None if value is None else self.scale(value, context)
        return {} if new is None else {self.attribute: new}


def _readable(value: Value) -> bool:
    """Whether ``value`` holds numbers (text a typed field keeps may not)."""
    return type(value) is tuple or type(value) is float or numbers(value) is not None


def _by_cycle(cycle: str) -> ValueScale:
    """Multiply by the factors ``context.cycles`` keeps under the name ``cycle``."""
    read = operator.attrgetter(cycle)

    def scale(value: Value, context: ScaleContext) -> Value | None:
        factors: tuple[float, ...] = read(context.cycles)
        if type(value) is tuple and len(factors) == 1:  # the common case, inline
            factor = factors[0]
            return tuple([v * factor for v in value])
        return _times(value, factors) if _readable(value) else None

    return scale


_POINTS, _LENGTHS, _MASSES, _INERTIAS = map(_by_cycle, ("per_axis", "mean", "mass", "inertia"))


def points(*attributes: str) -> list[Rule]:
    """Positions: x, y and z (repeated for lists of points) scale per axis."""
    return [ValueRule(a, _POINTS) for a in attributes]


def lengths(*attributes: str) -> list[Rule]:
    """Lengths without a direction: the mean factor."""
    return [ValueRule(a, _LENGTHS) for a in attributes]


def parts(attribute: str, unit: tuple[float, ...], start: int) -> Rule:
    """Multiply the values from index ``start`` on (friction: torsion and rolling)."""

    def scale(value: Value, context: ScaleContext) -> Value | None:
        found = numbers(value)
        if found is None:
            return None
        factors = [*unit[:start], *[context.mean] * (len(found) - start)][: len(found)]
        return tuple(n * f for n, f in zip(found, factors, strict=True))

    return ValueRule(attribute, scale)


def masses(*attributes: str) -> list[Rule]:
    """Masses: unchanged, or with the volume under ``mass="volume"``."""
    return [ValueRule(a, _MASSES) for a in attributes]


def inertias(*attributes: str) -> list[Rule]:
    """Inertias: length squared, times the mass factor (per axis an approximation)."""
    return [ValueRule(a, _INERTIAS) for a in attributes]


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
        full = None if _in_default(ancestors) else _unwritten(element, ancestors, context, own)
        if full is not None:
            return {attribute: times(_completed(full, own), factors(element, ancestors, context))}
        if value is None or own is None:
            return {}
        return {attribute: times(value, factors(element, ancestors, context))}

    def _unwritten(
        element: AnyElement,
        ancestors: Sequence[AnyElement],
        context: ScaleContext,
        own: tuple[float, ...] | None,
    ) -> tuple[float, ...] | None:
        """The full value the element's classes and MuJoCo give it; ``None`` if it is not needed.

        It is not needed when the element writes every value, or its classes do.
        """
        full = builtin()
        if own is not None and len(own) >= len(full):
            return None
        classes = context.classes
        if not classes.sets(tag):
            return full
        name = classes.class_of(element, ancestors)
        full, covered = context.cached(
            ("builtin", tag, attribute, name),
            lambda: _class_values(classes, name, tag, attribute),
        )
        return None if covered >= len(full) else full

    def _class_values(
        classes: DefaultClasses, name: str, tag: str, attribute: str
    ) -> tuple[tuple[float, ...], int]:
        """The built-in value completed by class ``name``, and how many values classes write."""
        full = list(builtin())
        covered = 0  # how many leading values the classes write (and scale themselves)
        for current in reversed(classes.chain(name)):
            setting = classes.settings.get((current, tag))
            inherited = numbers(get_attribute(setting, attribute)) if setting else None
            if inherited:
                full[: len(inherited)] = inherited
                covered = max(covered, len(inherited))
        return tuple(full), covered

    return rule


def _completed(full: tuple[float, ...], own: tuple[float, ...] | None) -> float | tuple[float, ...]:
    """``full`` with its first values replaced by ``own``; one number alone."""
    values = list(full)
    values[: len(own or ())] = own or ()
    return tuple(values) if len(values) > 1 else values[0]


def combine(*rules: Rule | list[Rule]) -> Rule:
    """One rule applying several.

    The attributes of the :class:`ValueRule` parts are read at once and scaled
    first (a value that scales to itself, such as a zero position, is left out);
    the other rules follow in order, so one of them may overwrite such an
    attribute. Combined rules given here are merged into this one.

    Example:
        >>> from mjcf_model import Geom
        >>> rule = combine(points("pos"), lengths("margin"))
        >>> rule(Geom(pos=[1, 0, 0], margin=0.5), (), ScaleContext(factors=(2.0, 2.0, 2.0)))
        {'pos': (2.0, 0.0, 0.0), 'margin': 1.0}

    """
    flat: list[Rule] = []
    for given in rules:
        for part in given if isinstance(given, list) else [given]:
            flat.extend(part.parts if isinstance(part, _Combined) else [part])
    return _Combined(flat)


class _Combined:
    """The rule :func:`combine` makes."""

    __slots__ = ("names", "others", "parts", "scales")

    def __init__(self, parts: list[Rule]) -> None:
        self.parts = parts
        values = [part for part in parts if isinstance(part, ValueRule)]
        self.names = tuple(part.attribute for part in values)
        self.scales = tuple(part.scale for part in values)
        self.others = [part for part in parts if not isinstance(part, ValueRule)]

    def __call__(
        self, element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
    ) -> Changes:
        changes: Changes = {}
        if self.names:
            written = attribute_values(element, self.names)
            for name, value, scale in zip(self.names, written, self.scales, strict=True):
                if value is not None:
                    new = scale(value, context)
                    if new is not None and new != value:  # ``0 0 0`` stays: the node is shared
                        changes[name] = new
        for part in self.others:
            changes.update(part(element, ancestors, context))
        return changes


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
    for element, key, ancestors in _body_walk(node):
        if key in ("body/replicate", "body/flexcomp", "body/attach"):
            return None
        if key == "body/freejoint":
            joints.append(JointInfo(name=_name(element), type="free", axis=(0.0, 0.0, 1.0)))
        elif key == "body/joint":
            kind, axis = classes.resolve_many(element, ancestors, ("type", "axis"))
            kind = str(kind or "hinge")
            direction = numbers(axis) if kind != "free" else None
            joints.append(
                JointInfo(name=_name(element), type=kind, axis=direction or (0.0, 0.0, 1.0))
            )
    return tuple(joints)


def _body_walk(node: AnyElement) -> Iterator[tuple[AnyElement, str | None, Sequence[AnyElement]]]:
    """:func:`keyed_walk` of the bodies: of a whole model, only its ``<worldbody>`` sections."""
    if node.tag != "mujoco":
        yield from keyed_walk(node)
        return
    for section in node.elements:
        if section.tag == "worldbody":
            yield from keyed_walk(section, "mujoco")


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
