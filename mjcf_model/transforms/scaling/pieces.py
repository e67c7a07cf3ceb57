"""The pieces scaling rules are made of.

A rule reads an element (and the classes it inherits from) and returns the
attribute changes that scale it, given the
:class:`~mjcf_model.transforms.scaling.context.ScaleContext` of the scaling;
:mod:`mjcf_model.transforms.scaling.rules` assembles one per schema key from these
pieces.

>>> from mjcf_model import Body
>>> points("pos")[0](Body(pos=[1, 2, 3]), (), ScaleContext(factors=(2.0, 1.0, 1.0)))
{'pos': (2.0, 2.0, 3.0)}
"""

from __future__ import annotations

import functools
import operator
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.transforms.scaling.context import ScaleContext, times, times_cycle
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.queries import attribute_values
from mjcf_model.values import Value, numbers_of

__all__ = [
    "NO_LENGTHS",
    "Changes",
    "BuiltinRule",
    "Rule",
    "ValueRule",
    "ValueScale",
    "builtin_default",
    "combine",
    "inertias",
    "lengths",
    "masses",
    "parts",
    "points",
    "principal_inertias",
]

Changes = dict[str, Value | None]


#: ``rule(element, ancestors, context)``: the attribute changes that scale ``element``.
Rule = Callable[[AnyElement, Sequence[AnyElement], ScaleContext], Changes]


@functools.cache
def builtin_default(tag: str, attribute: str) -> tuple[float, ...]:
    """MuJoCo's built-in default of an attribute, read from an empty ``MjSpec``.

    Values MuJoCo keeps in single precision are given by their shortest text
    (``0.02``, not ``0.019999999552965164``).

    Examples:
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

    Examples:
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
    return type(value) is tuple or type(value) is float or numbers_of(value) is not None


class _CycleScale:
    """Multiply by the factors ``context.cycles`` keeps under the name ``cycle``."""

    __slots__ = ("read",)

    def __init__(self, cycle: str) -> None:
        #: Reads the factors from ``context.cycles``.
        self.read = operator.attrgetter(cycle)

    def __call__(self, value: Value, context: ScaleContext) -> Value | None:
        """``value`` scaled; ``None`` for text without numbers."""
        factors: tuple[float, ...] = self.read(context.cycles)
        if type(value) is tuple and len(factors) == 1:  # the common case, inline
            factor = factors[0]
            return tuple([v * factor for v in value])
        return times_cycle(value, factors) if _readable(value) else None


_POINTS, _LENGTHS, _MASSES, _INERTIAS = map(_CycleScale, ("per_axis", "mean", "mass", "inertia"))


def points(*attributes: str) -> list[Rule]:
    """Positions: x, y and z (repeated for lists of points) scale per axis."""
    return [ValueRule(a, _POINTS) for a in attributes]


def lengths(*attributes: str) -> list[Rule]:
    """Lengths without a direction: the mean factor."""
    return [ValueRule(a, _LENGTHS) for a in attributes]


def parts(attribute: str, unit: tuple[float, ...], start: int) -> Rule:
    """Multiply the values from index ``start`` on (friction: torsion and rolling)."""
    return ValueRule(attribute, _PartsScale(unit, start))


class _PartsScale:
    """The scale of :func:`parts`: ``unit`` before index ``start``, the mean factor from it."""

    __slots__ = ("start", "unit")

    def __init__(self, unit: tuple[float, ...], start: int) -> None:
        #: The factors of the values before ``start``.
        self.unit = unit
        #: The index of the first length.
        self.start = start

    def __call__(self, value: Value, context: ScaleContext) -> Value | None:
        """``value`` scaled; ``None`` for text without numbers."""
        found = numbers_of(value)
        if found is None:
            return None
        length = len(found) - self.start
        factors = [*self.unit[: self.start], *[context.mean] * length][: len(found)]
        return tuple(n * f for n, f in zip(found, factors, strict=True))


def masses(*attributes: str) -> list[Rule]:
    """Masses: unchanged, or with the volume under ``mass="volume"``."""
    return [ValueRule(a, _MASSES) for a in attributes]


def inertias(*attributes: str) -> list[Rule]:
    """Inertias: length squared, times the mass factor (per axis an approximation)."""
    return [ValueRule(a, _INERTIAS) for a in attributes]


def principal_inertias(attribute: str) -> list[Rule]:
    """Principal moments: inertias that MuJoCo still accepts where it accepted them before.

    MuJoCo rejects moments of which one exceeds the sum of the two others. Moments on
    that edge (``0.1 0.2 0.3``, where ``0.1 + 0.2 >= 0.3`` in floating point) can fall
    off it once scaled and rounded (``0.144 + 0.288 < 0.432``); the largest is then the
    sum of the two others, the nearest value MuJoCo accepts.

    Examples:
        >>> from mjcf_model import Inertial
        >>> rule = principal_inertias("diaginertia")[0]
        >>> rule(Inertial(diaginertia=[0.1, 0.2, 0.3]), (), ScaleContext(factors=(1.2,) * 3))
        {'diaginertia': (0.144, 0.288, 0.43199999999999994)}

    """
    return [ValueRule(attribute, _triangle_kept)]


def _triangle_kept(value: Value, context: ScaleContext) -> Value | None:
    """``value`` scaled as an inertia, its largest moment lowered to keep the triangle."""
    scaled = _INERTIAS(value, context)
    before, after = numbers_of(value), numbers_of(scaled)
    if before is None or after is None or len(before) != 3 or len(after) != 3:
        return scaled
    if not _is_triangle(before) or _is_triangle(after):
        return scaled
    largest = max(range(3), key=after.__getitem__)
    first, second = (after[i] for i in range(3) if i != largest)
    kept = list(after)
    kept[largest] = first + second
    return tuple(kept)


def _is_triangle(moments: tuple[float, ...]) -> bool:
    """Whether no moment exceeds the sum of the two others."""
    a, b, c = moments
    return a + b >= c and a + c >= b and b + c >= a


class BuiltinRule:
    """Scale ``attribute``; where nothing sets it, write MuJoCo's default (``builtin()``) scaled.

    A partial value (a sphere site's one size) is completed from its classes and
    the built-in default first, because the values it leaves out are lengths too.
    In a default class only what is written is scaled.

    Examples:
        >>> from mjcf_model import Site
        >>> rule = BuiltinRule("size", "site", lambda: (0.005, 0.005, 0.005), lambda *_: 2.0)
        >>> rule(Site(size=[0.1]), (), ScaleContext(factors=(2.0, 2.0, 2.0)))
        {'size': (0.2, 0.01, 0.01)}

    """

    __slots__ = ("attribute", "builtin", "factors", "tag")

    def __init__(
        self,
        attribute: str,
        tag: str,
        builtin: Callable[[], tuple[float, ...]],
        factors: Callable[[AnyElement, Sequence[AnyElement], ScaleContext], Any],
    ) -> None:
        #: The attribute scaled.
        self.attribute = attribute
        #: The tag of the elements (and class settings) that hold it.
        self.tag = tag
        #: MuJoCo's built-in value.
        self.builtin = builtin
        #: The factor (or per-value factors) of an element.
        self.factors = factors

    def __call__(
        self, element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
    ) -> Changes:
        """The change of :attr:`attribute` on ``element``."""
        value = get_attribute(element, self.attribute)
        own = numbers_of(value)
        full = None if _in_default(ancestors) else self._unwritten(element, ancestors, context, own)
        if full is not None:
            factors = self.factors(element, ancestors, context)
            return {self.attribute: times(_completed(full, own), factors)}
        if value is None or own is None:
            return {}
        return {self.attribute: times(value, self.factors(element, ancestors, context))}

    def _unwritten(
        self,
        element: AnyElement,
        ancestors: Sequence[AnyElement],
        context: ScaleContext,
        own: tuple[float, ...] | None,
    ) -> tuple[float, ...] | None:
        """The full value the element's classes and MuJoCo give it; ``None`` if it is not needed.

        It is not needed when the element writes every value, or its classes do.
        """
        full = self.builtin()
        if own is not None and len(own) >= len(full):
            return None
        classes = context.classes
        if not classes.sets(self.tag):
            return full
        name = classes.class_of(element, ancestors)
        full, covered = context.cached(
            ("builtin", self.tag, self.attribute, name),
            lambda: self._class_values(classes, name),
        )
        return None if covered >= len(full) else full

    def _class_values(self, classes: DefaultClasses, name: str) -> tuple[tuple[float, ...], int]:
        """The built-in value completed by class ``name``, and how many values classes write."""
        full = list(self.builtin())
        covered = 0  # how many leading values the classes write (and scale themselves)
        for current in reversed(classes.chain(name)):
            setting = classes.settings.get((current, self.tag))
            inherited = numbers_of(get_attribute(setting, self.attribute)) if setting else None
            if inherited:
                full[: len(inherited)] = inherited
                covered = max(covered, len(inherited))
        return tuple(full), covered


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

    Examples:
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
