"""The ``<contact>`` section: explicit pairs and exclusions.

>>> Pair(geom1="a", geom2="b").geom2
'b'
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import integer, number, numbers, text, vec1to2, vec1to5
from mjcf_model.values import Floats

__all__ = ["Contact", "Exclude", "Pair"]


@node
class Contact(TypedElement):
    """Section of explicit contact pairs and exclusions."""

    schema_keys: ClassVar[tuple[str, ...]] = ("contact",)


@node
class Pair(TypedElement):
    """An explicit contact pair of two geoms."""

    schema_keys: ClassVar[tuple[str, ...]] = ("contact/pair", "default/pair")
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")
    #: Adhesion force parameter.
    adhesion: str | None = text()
    #: Dimensionality of the contact space (1, 3, 4 or 6).
    condim: int | None = integer()
    #: Sliding, torsional and rolling friction coefficients.
    friction: Floats | None = numbers()
    #: Part of the margin within which contacts are not generated.
    gap: float | None = number()
    #: Name of the first geom.
    geom1: str | None = text()
    #: Name of the second geom.
    geom2: str | None = text()
    #: Distance at which contacts (or limits) become active.
    margin: float | None = number()
    #: Constraint solver impedance parameters.
    solimp: Floats | None = vec1to5()
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = vec1to2()
    #: Solver reference parameters of the friction constraint.
    solreffriction: Floats | None = vec1to2()


@node
class Exclude(TypedElement):
    """Excludes contacts between two bodies."""

    schema_keys: ClassVar[tuple[str, ...]] = ("contact/exclude",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Name of the first body.
    body1: str | None = text()
    #: Name of the second body.
    body2: str | None = text()
