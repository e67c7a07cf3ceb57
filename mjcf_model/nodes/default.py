"""Default classes (``<default>``) and the default-only element types.

>>> from mjcf_model.nodes.geom import Geom
>>> Default(dclass="arm", children=[Geom(rgba=(1, 0, 0, 1))]).dclass
'arm'
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.keywords import LIMITED
from mjcf_model.values import (
    Floats,
    one_of,
    to_bool,
    to_float,
    to_floats,
    to_int,
    to_str,
    to_vec2,
    to_vec3to5,
    to_vec4,
)

__all__ = ["Default", "DefaultEquality", "DefaultTendon"]


@attrs.frozen(kw_only=True, repr=False)
class Default(TypedElement):
    """A default class: attribute values its members take unless they set their own."""

    tag: ClassVar[str] = "default"
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})

    @property
    def defaults(self) -> tuple[Default, ...]:
        """The nested default classes."""
        return self._of_type(Default)


@attrs.frozen(kw_only=True, repr=False)
class DefaultEquality(TypedElement):
    """Default values for equality constraints."""

    tag: ClassVar[str] = "equality"
    #: Whether the element is active initially.
    active: bool | None = attrs.field(default=None, converter=to_bool)
    #: Constraint solver impedance parameters.
    solimp: Floats | None = attrs.field(default=None, converter=to_vec3to5)
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = attrs.field(default=None, converter=to_vec2)


@attrs.frozen(kw_only=True, repr=False)
class DefaultTendon(TypedElement):
    """Default values for tendons."""

    tag: ClassVar[str] = "tendon"
    #: Whether the total actuator force is clamped: ``true``, ``false`` or ``auto``.
    actuatorfrclimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the total actuator force.
    actuatorfrcrange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Armature inertia added to the degree of freedom.
    armature: float | None = attrs.field(default=None, converter=to_float)
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Dry friction loss.
    frictionloss: float | None = attrs.field(default=None, converter=to_float)
    #: Integer group, used for visualization filters and by convention.
    group: int | None = attrs.field(default=None, converter=to_int)
    #: Whether limits apply: ``true``, ``false`` or ``auto``.
    limited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Distance at which contacts (or limits) become active.
    margin: float | None = attrs.field(default=None, converter=to_float)
    #: Name of the material asset used for rendering.
    material: str | None = attrs.field(default=None, converter=to_str)
    #: Lower and upper limits.
    range: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Solver impedance parameters of the friction constraint.
    solimpfriction: Floats | None = attrs.field(default=None, converter=to_vec3to5)
    #: Solver impedance parameters of the limit constraint.
    solimplimit: Floats | None = attrs.field(default=None, converter=to_vec3to5)
    #: Solver reference parameters of the friction constraint.
    solreffriction: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Solver reference parameters of the limit constraint.
    solreflimit: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Spring rest length (or dead band).
    springlength: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Yield threshold of the spring.
    springyield: float | None = attrs.field(default=None, converter=to_float)
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Custom user data (numbers).
    user: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Width.
    width: float | None = attrs.field(default=None, converter=to_float)
