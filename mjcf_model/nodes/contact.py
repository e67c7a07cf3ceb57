"""The ``<contact>`` section: explicit pairs and exclusions.

>>> Pair(geom1="a", geom2="b").geom2
'b'
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.values import (
    Floats,
    float_key,
    to_float,
    to_floats,
    to_int,
    to_str,
    to_vec1to2,
    to_vec1to5,
)

__all__ = ["Contact", "Exclude", "Pair"]


@attrs.frozen(kw_only=True, repr=False)
class Contact(TypedElement):
    """Section of explicit contact pairs and exclusions."""

    tag: ClassVar[str] = "contact"


@attrs.frozen(kw_only=True, repr=False)
class Pair(TypedElement):
    """An explicit contact pair of two geoms."""

    tag: ClassVar[str] = "pair"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})
    #: Adhesion force parameter.
    adhesion: str | None = attrs.field(default=None, converter=to_str)
    #: Dimensionality of the contact space (1, 3, 4 or 6).
    condim: int | None = attrs.field(default=None, converter=to_int)
    #: Sliding, torsional and rolling friction coefficients.
    friction: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Part of the margin within which contacts are not generated.
    gap: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the first geom.
    geom1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the second geom.
    geom2: str | None = attrs.field(default=None, converter=to_str)
    #: Distance at which contacts (or limits) become active.
    margin: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Constraint solver impedance parameters.
    solimp: Floats | None = attrs.field(default=None, converter=to_vec1to5)
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = attrs.field(default=None, converter=to_vec1to2)
    #: Solver reference parameters of the friction constraint.
    solreffriction: Floats | None = attrs.field(default=None, converter=to_vec1to2)


@attrs.frozen(kw_only=True, repr=False)
class Exclude(TypedElement):
    """Excludes contacts between two bodies."""

    tag: ClassVar[str] = "exclude"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the first body.
    body1: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the second body.
    body2: str | None = attrs.field(default=None, converter=to_str)
