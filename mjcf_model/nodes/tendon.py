"""The ``<tendon>`` section: spatial and fixed tendons and their path elements.

>>> Fixed(name="t", children=[TendonJoint(joint="j", coef=1)]).joints[0].coef
1.0
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.keywords import LIMITED
from mjcf_model.values import (
    Floats,
    float_key,
    one_of,
    to_float,
    to_floats,
    to_int,
    to_str,
    to_vec1to2,
    to_vec1to5,
    to_vec2,
    to_vec4,
)

__all__ = [
    "DefaultTendon",
    "Fixed",
    "Pulley",
    "Spatial",
    "Tendon",
    "TendonElement",
    "TendonGeom",
    "TendonJoint",
    "TendonSettings",
    "TendonSite",
]


@attrs.frozen(kw_only=True, repr=False)
class Tendon(TypedElement):
    """Section of tendons."""

    tag: ClassVar[str] = "tendon"


@attrs.frozen(kw_only=True, repr=False)
class TendonSettings(TypedElement):
    """The tendon settings that both tendon types and ``<default><tendon>`` share."""

    #: Whether the total actuator force is clamped: ``true``, ``false`` or ``auto``.
    actuatorfrclimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the total actuator force.
    actuatorfrcrange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Armature inertia added to the degree of freedom.
    armature: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Dry friction loss.
    frictionloss: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Integer group, used for visualization filters and by convention.
    group: int | None = attrs.field(default=None, converter=to_int)
    #: Whether limits apply: ``true``, ``false`` or ``auto``.
    limited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Distance at which contacts (or limits) become active.
    margin: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Lower and upper limits.
    range: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Solver impedance parameters of the friction constraint.
    solimpfriction: Floats | None = attrs.field(default=None, converter=to_vec1to5)
    #: Solver impedance parameters of the limit constraint.
    solimplimit: Floats | None = attrs.field(default=None, converter=to_vec1to5)
    #: Solver reference parameters of the friction constraint.
    solreffriction: Floats | None = attrs.field(default=None, converter=to_vec1to2)
    #: Solver reference parameters of the limit constraint.
    solreflimit: Floats | None = attrs.field(default=None, converter=to_vec1to2)
    #: Spring rest length (or dead band).
    springlength: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Yield threshold of the spring.
    springyield: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Custom user data (numbers).
    user: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class TendonElement(TendonSettings):
    """Fields both tendon types share: the settings plus a name and a class."""

    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})


@attrs.frozen(kw_only=True, repr=False)
class DefaultTendon(TendonSettings):
    """Default values for tendons (``<default><tendon>``)."""

    tag: ClassVar[str] = "tendon"
    #: Name of the material asset used for rendering.
    material: str | None = attrs.field(default=None, converter=to_str)
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Width.
    width: float | None = attrs.field(default=None, converter=to_float, eq=float_key)


@attrs.frozen(kw_only=True, repr=False)
class Spatial(TendonElement):
    """A spatial tendon: a path through sites and around geoms."""

    tag: ClassVar[str] = "spatial"
    #: Name of the material asset used for rendering.
    material: str | None = attrs.field(default=None, converter=to_str)
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Width.
    width: float | None = attrs.field(default=None, converter=to_float, eq=float_key)


@attrs.frozen(kw_only=True, repr=False)
class Fixed(TendonElement):
    """A fixed tendon: a linear combination of joint positions."""

    tag: ClassVar[str] = "fixed"

    @property
    def joints(self) -> tuple[TendonJoint, ...]:
        """The joints and coefficients of the tendon."""
        return self._of_type(TendonJoint)


@attrs.frozen(kw_only=True, repr=False)
class TendonSite(TypedElement):
    """A site the spatial tendon passes through."""

    tag: ClassVar[str] = "site"
    #: Name of the site.
    site: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class TendonGeom(TypedElement):
    """A geom the spatial tendon wraps around."""

    tag: ClassVar[str] = "geom"
    #: MJCF attribute ``geom``; see the MuJoCo XML reference.
    geom: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the site that chooses the wrapping side.
    sidesite: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Pulley(TypedElement):
    """Starts a new branch of a spatial tendon."""

    tag: ClassVar[str] = "pulley"
    #: Divisor of the tendon length of the branch after the pulley.
    divisor: float | None = attrs.field(default=None, converter=to_float, eq=float_key)


@attrs.frozen(kw_only=True, repr=False)
class TendonJoint(TypedElement):
    """A joint and its coefficient in a fixed tendon."""

    tag: ClassVar[str] = "joint"
    #: Coefficient of the joint in the fixed tendon.
    coef: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the joint.
    joint: str | None = attrs.field(default=None, converter=to_str)
