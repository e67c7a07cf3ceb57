"""Scaling what is a length only over slide joints: tendons and equality couplings.

A slide joint's coordinate is a length, a hinge's an angle. A spatial tendon's
length is a length. A fixed tendon's length is ``sum(coef * q)`` over its
joints: with a slide joint in it, it is a length, and a hinge's ``coef`` is then
a lever arm (a length per radian, like a pulley's radius) that scales with the
tendon; over hinges alone it is an angle and nothing in it scales. Each
``coef`` is multiplied by the tendon's factor over its joint's, so the scaled
tendon's length is, at every configuration, the original's times its factor.

An equality ``y1 = a0 + a1 y2 + ... + a4 y2**4`` between joints or tendons has
``a_k`` in units of ``y1 / y2**k``.

>>> from mjcf_model.transforms.scaling.context import ScaleContext
>>> slide_factor("slide", (1.0, 0.0, 0.0), ScaleContext(factors=(2.0, 3.0, 3.0)))
2.0
"""

from __future__ import annotations

from collections.abc import Sequence

from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.transforms.scaling.context import ScaleContext, times
from mjcf_model.transforms.scaling.pieces import Changes, builtin_default, combine
from mjcf_model.tree.traversal import keyed_walk
from mjcf_model.values import numbers_of

__all__ = [
    "fixed_tendon",
    "joint_coupling",
    "slide_factor",
    "spatial_tendon",
    "tendon_coefficient",
    "tendon_coupling",
]

#: MuJoCo's coupling when ``polycoef`` leaves values out: ``y1 = y2``.
_IDENTITY = (0.0, 1.0, 0.0, 0.0, 0.0)


def slide_factor(kind: object, axis: object, context: ScaleContext) -> float:
    """The factor of a joint's coordinate: along its axis for a slide joint, else 1."""
    if kind != "slide":
        return 1.0
    return context.along(numbers_of(axis) or (0.0, 0.0, 1.0))  # type: ignore[arg-type]


def _joint_factor(name: object, context: ScaleContext) -> float | None:
    """The factor of the coordinate of the joint called ``name``; ``None`` if unknown."""
    joint = context.joint(name)
    return None if joint is None else slide_factor(joint.type, joint.axis, context)


def _tendon_factor(tendon: AnyElement, context: ScaleContext) -> float | None:
    """The factor of a tendon's length (see the module's text); ``None`` if a joint is unknown."""
    if tendon.tag == "spatial":
        return context.mean
    joints = [context.joint(get_attribute(c, "joint")) for c in tendon.elements]
    if not joints or any(j is None for j in joints):
        return None
    return context.mean if any(j.type == "slide" for j in joints if j) else 1.0


def _tendon_named(name: object, context: ScaleContext) -> AnyElement | None:
    """The tendon called ``name`` in the model being scaled."""

    def find() -> dict[object, AnyElement]:
        found: dict[object, AnyElement] = {}
        for element, key, _ in keyed_walk(context.model) if context.model else ():
            if key in ("tendon/spatial", "tendon/fixed"):
                found.setdefault(get_attribute(element, "name"), element)
        return found

    return context.cached("tendons", find).get(name) if name is not None else None


class _Materialized:
    """Write a tendon length scaled on the element, whether its own or inherited.

    The default tendon is shared by spatial and fixed tendons, so it is left alone.
    """

    __slots__ = ("attribute",)

    def __init__(self, attribute: str) -> None:
        #: ``range``, ``springlength`` or ``margin``.
        self.attribute = attribute

    def __call__(
        self, element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
    ) -> Changes:
        """The scaled length of ``element``."""
        attribute = self.attribute
        value = context.classes.resolve(element, ancestors, attribute, "tendon")
        numbers = numbers_of(value)
        if numbers is None or (attribute == "springlength" and set(numbers) == {-1.0}):
            return {}  # ``-1 -1``: MuJoCo's "the length at qpos_spring", measured scaled
        assert value is not None
        return {attribute: times(value, context.mean)}


_TENDON_LENGTHS = combine(*[_Materialized(a) for a in ("range", "springlength", "margin")])


def spatial_tendon(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """A spatial tendon's lengths and width (MuJoCo's built-in width written where unset)."""
    changes = _TENDON_LENGTHS(element, ancestors, context)
    width = numbers_of(context.classes.resolve(element, ancestors, "width", "tendon"))
    changes["width"] = (width or builtin_default("tendon", "width"))[0] * context.mean
    return changes


def fixed_tendon(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """A fixed tendon's lengths, when a slide joint makes its length a length."""
    factor = _tendon_factor(element, context)
    if factor is None or factor == 1.0:
        return {}
    return _TENDON_LENGTHS(element, ancestors, context)


def tendon_coefficient(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """A fixed tendon's ``coef`` of a joint: times the tendon's factor over the joint's."""
    tendon = _tendon_factor(ancestors[-1], context) if ancestors else None
    joint = _joint_factor(get_attribute(element, "joint"), context)
    coef = get_attribute(element, "coef")
    if tendon is None or joint is None or numbers_of(coef) is None or tendon == joint:
        return {}
    assert coef is not None
    return {"coef": times(coef, tendon / joint)}


def _coupled(element: AnyElement, first: float | None, second: float | None) -> Changes:
    """``polycoef`` of a coupling of coordinates scaled by ``first`` and ``second``.

    MuJoCo's built-in ``0 1 0 0 0`` completes what is not written. Without a
    second object (``second`` is ``0.0``) the first is held at ``a0``, the only
    coefficient MuJoCo reads; the others are kept as written.
    """
    if first is None or second is None:
        return {}
    factors = (
        [first, 1.0, 1.0, 1.0, 1.0] if second == 0.0 else [first / second**k for k in range(5)]
    )
    if all(f == 1.0 for f in factors):
        return {}
    own = numbers_of(get_attribute(element, "polycoef")) or ()
    values = (*own, *_IDENTITY[len(own) :])
    return {"polycoef": tuple(v * f for v, f in zip(values, factors, strict=True))}


def joint_coupling(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """An equality between joints (slide joints' coordinates are lengths)."""
    second = get_attribute(element, "joint2")
    return _coupled(
        element,
        _joint_factor(get_attribute(element, "joint1"), context),
        0.0 if second is None else _joint_factor(second, context),
    )


def tendon_coupling(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """An equality between tendons (whose lengths are lengths or angles, as above)."""

    def factor(attribute: str) -> float | None:
        tendon = _tendon_named(get_attribute(element, attribute), context)
        return None if tendon is None else _tendon_factor(tendon, context)

    second = 0.0 if get_attribute(element, "tendon2") is None else factor("tendon2")
    return _coupled(element, factor("tendon1"), second)
