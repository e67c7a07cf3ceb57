"""The ``<equality>`` section: constraints that connect, weld or couple objects.

>>> Weld(body1="a", body2="b").body1
'a'
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import (
    boolean,
    number,
    numbers,
    text,
    vec1to2,
    vec1to5,
    vec3,
)
from mjcf_model.values import Floats

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


@node
class Equality(TypedElement):
    """Section of equality constraints."""

    schema_keys: ClassVar[tuple[str, ...]] = ("equality",)


@node
class EqualitySettings(TypedElement):
    """The settings every equality constraint and ``<default><equality>`` share."""

    #: Whether the element is active initially.
    active: bool | None = boolean()
    #: Constraint solver impedance parameters.
    solimp: Floats | None = vec1to5()
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = vec1to2()


@node
class EqualityElement(EqualitySettings):
    """Fields every equality constraint shares: the settings plus a name and a class."""

    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")


@node
class DefaultEquality(EqualitySettings):
    """Default values for equality constraints (``<default><equality>``)."""

    schema_keys: ClassVar[tuple[str, ...]] = ("default/equality",)


@node
class Connect(EqualityElement):
    """Connects two bodies at a point (ball joint constraint)."""

    schema_keys: ClassVar[tuple[str, ...]] = ("equality/connect",)
    #: Anchor point of the constraint.
    anchor: Floats | None = vec3()
    #: Name of the first body.
    body1: str | None = text()
    #: Name of the second body.
    body2: str | None = text()
    #: Name of the first site.
    site1: str | None = text()
    #: Name of the second site.
    site2: str | None = text()


@node
class Weld(EqualityElement):
    """Welds two bodies together."""

    schema_keys: ClassVar[tuple[str, ...]] = ("equality/weld",)
    #: Anchor point of the constraint.
    anchor: Floats | None = vec3()
    #: Name of the first body.
    body1: str | None = text()
    #: Name of the second body.
    body2: str | None = text()
    #: Relative pose of the welded bodies.
    relpose: Floats | None = numbers()
    #: Name of the first site.
    site1: str | None = text()
    #: Name of the second site.
    site2: str | None = text()
    #: Scale of rotational relative to translational residual.
    torquescale: float | None = number()


@node
class EqualityJoint(EqualityElement):
    """Couples two joints with a polynomial."""

    schema_keys: ClassVar[tuple[str, ...]] = ("equality/joint",)
    #: Name of the first joint.
    joint1: str | None = text()
    #: Name of the second joint.
    joint2: str | None = text()
    #: Polynomial coefficients of the coupling.
    polycoef: Floats | None = numbers()


@node
class EqualityTendon(EqualityElement):
    """Couples two tendons with a polynomial."""

    schema_keys: ClassVar[tuple[str, ...]] = ("equality/tendon",)
    #: Polynomial coefficients of the coupling.
    polycoef: Floats | None = numbers()
    #: Name of the first tendon.
    tendon1: str | None = text()
    #: Name of the second tendon.
    tendon2: str | None = text()


@node
class EqualityFlex(EqualityElement):
    """Fixes the edge lengths of a flex."""

    schema_keys: ClassVar[tuple[str, ...]] = ("equality/flex",)
    #: Name of the flex.
    flex: str | None = text()


@node
class EqualityFlexStrain(EqualityElement):
    """Constrains the strain of a flex."""

    schema_keys: ClassVar[tuple[str, ...]] = ("equality/flexstrain",)
    #: Index of the cell.
    cell: str | None = text()
    #: Name of the flex.
    flex: str | None = text()
