"""The ``<equality>`` section: constraints that connect, weld or couple objects.

>>> Weld(body1="a", body2="b").body1
'a'
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.values import (
    Floats,
    float_key,
    to_bool,
    to_float,
    to_floats,
    to_str,
    to_vec1to2,
    to_vec1to5,
    to_vec3,
)

__all__ = [
    "Connect",
    "DefaultEquality",
    "Equality",
    "EqualityElement",
    "EqualityFlex",
    "EqualityFlexStrain",
    "EqualityJoint",
    "EqualitySettings",
    "EqualityTendon",
    "Weld",
]


@attrs.frozen(kw_only=True, repr=False)
class Equality(TypedElement):
    """Section of equality constraints."""

    tag: ClassVar[str] = "equality"


@attrs.frozen(kw_only=True, repr=False)
class EqualitySettings(TypedElement):
    """The settings every equality constraint and ``<default><equality>`` share."""

    #: Whether the element is active initially.
    active: bool | None = attrs.field(default=None, converter=to_bool)
    #: Constraint solver impedance parameters.
    solimp: Floats | None = attrs.field(default=None, converter=to_vec1to5)
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = attrs.field(default=None, converter=to_vec1to2)


@attrs.frozen(kw_only=True, repr=False)
class EqualityElement(EqualitySettings):
    """Fields every equality constraint shares: the settings plus a name and a class."""

    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})


@attrs.frozen(kw_only=True, repr=False)
class DefaultEquality(EqualitySettings):
    """Default values for equality constraints (``<default><equality>``)."""

    tag: ClassVar[str] = "equality"


@attrs.frozen(kw_only=True, repr=False)
class Connect(EqualityElement):
    """Connects two bodies at a point (ball joint constraint)."""

    tag: ClassVar[str] = "connect"
    #: Anchor point of the constraint.
    anchor: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Name of the first body.
    body1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the second body.
    body2: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the first site.
    site1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the second site.
    site2: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Weld(EqualityElement):
    """Welds two bodies together."""

    tag: ClassVar[str] = "weld"
    #: Anchor point of the constraint.
    anchor: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Name of the first body.
    body1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the second body.
    body2: str | None = attrs.field(default=None, converter=to_str)
    #: Relative pose of the welded bodies.
    relpose: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Name of the first site.
    site1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the second site.
    site2: str | None = attrs.field(default=None, converter=to_str)
    #: Scale of rotational relative to translational residual.
    torquescale: float | None = attrs.field(default=None, converter=to_float, eq=float_key)


@attrs.frozen(kw_only=True, repr=False)
class EqualityJoint(EqualityElement):
    """Couples two joints with a polynomial."""

    tag: ClassVar[str] = "joint"
    #: Name of the first joint.
    joint1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the second joint.
    joint2: str | None = attrs.field(default=None, converter=to_str)
    #: Polynomial coefficients of the coupling.
    polycoef: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class EqualityTendon(EqualityElement):
    """Couples two tendons with a polynomial."""

    tag: ClassVar[str] = "tendon"
    #: Polynomial coefficients of the coupling.
    polycoef: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Name of the first tendon.
    tendon1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the second tendon.
    tendon2: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class EqualityFlex(EqualityElement):
    """Fixes the edge lengths of a flex."""

    tag: ClassVar[str] = "flex"
    #: Name of the flex.
    flex: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class EqualityFlexStrain(EqualityElement):
    """Constrains the strain of a flex."""

    tag: ClassVar[str] = "flexstrain"
    #: Index of the cell.
    cell: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the flex.
    flex: str | None = attrs.field(default=None, converter=to_str)
