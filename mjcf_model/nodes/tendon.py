"""The ``<tendon>`` section: spatial and fixed tendons and their path elements.

>>> Fixed(name="t", children=[TendonJoint(joint="j", coef=1)]).joints[0].coef
1.0
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import (
    integer,
    keyword,
    number,
    numbers,
    text,
    vec1to2,
    vec1to5,
    vec2,
    vec4,
)
from mjcf_model.schema.keywords import LIMITED
from mjcf_model.values import Floats

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


@node
class Tendon(TypedElement):
    """Section of tendons."""

    schema_keys: ClassVar[tuple[str, ...]] = ("tendon",)


@node
class TendonSettings(TypedElement):
    """The tendon settings that both tendon types and ``<default><tendon>`` share."""

    #: Whether the total actuator force is clamped: ``true``, ``false`` or ``auto``.
    actuatorfrclimited: str | None = keyword(LIMITED)
    #: Range of the total actuator force.
    actuatorfrcrange: Floats | None = vec2()
    #: Armature inertia added to the degree of freedom.
    armature: float | None = number()
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = numbers()
    #: Dry friction loss.
    frictionloss: float | None = number()
    #: Integer group, used for visualization filters and by convention.
    group: int | None = integer()
    #: Whether limits apply: ``true``, ``false`` or ``auto``.
    limited: str | None = keyword(LIMITED)
    #: Distance at which contacts (or limits) become active.
    margin: float | None = number()
    #: Lower and upper limits.
    range: Floats | None = vec2()
    #: Solver impedance parameters of the friction constraint.
    solimpfriction: Floats | None = vec1to5()
    #: Solver impedance parameters of the limit constraint.
    solimplimit: Floats | None = vec1to5()
    #: Solver reference parameters of the friction constraint.
    solreffriction: Floats | None = vec1to2()
    #: Solver reference parameters of the limit constraint.
    solreflimit: Floats | None = vec1to2()
    #: Spring rest length (or dead band).
    springlength: Floats | None = numbers()
    #: Yield threshold of the spring.
    springyield: float | None = number()
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: Floats | None = numbers()
    #: Custom user data (numbers).
    user: Floats | None = numbers()


@node
class TendonElement(TendonSettings):
    """Fields both tendon types share: the settings plus a name and a class."""

    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")


@node
class DefaultTendon(TendonSettings):
    """Default values for tendons (``<default><tendon>``)."""

    schema_keys: ClassVar[tuple[str, ...]] = ("default/tendon",)
    #: Name of the material asset used for rendering.
    material: str | None = text()
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = vec4()
    #: Width.
    width: float | None = number()


@node
class Spatial(TendonElement):
    """A spatial tendon: a path through sites and around geoms."""

    schema_keys: ClassVar[tuple[str, ...]] = ("tendon/spatial",)
    #: Name of the material asset used for rendering.
    material: str | None = text()
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = vec4()
    #: Width.
    width: float | None = number()


@node
class Fixed(TendonElement):
    """A fixed tendon: a linear combination of joint positions."""

    schema_keys: ClassVar[tuple[str, ...]] = ("tendon/fixed",)

    @property
    def joints(self) -> tuple[TendonJoint, ...]:
        """The joints and coefficients of the tendon."""
        return self._of_type(TendonJoint)


@node
class TendonSite(TypedElement):
    """A site the spatial tendon passes through."""

    schema_keys: ClassVar[tuple[str, ...]] = ("tendon/spatial/site",)
    #: Name of the site.
    site: str | None = text()


@node
class TendonGeom(TypedElement):
    """A geom the spatial tendon wraps around."""

    schema_keys: ClassVar[tuple[str, ...]] = ("tendon/spatial/geom",)
    #: MJCF attribute ``geom``; see the MuJoCo XML reference.
    geom: str | None = text()
    #: Name of the site that chooses the wrapping side.
    sidesite: str | None = text()


@node
class Pulley(TypedElement):
    """Starts a new branch of a spatial tendon."""

    schema_keys: ClassVar[tuple[str, ...]] = ("tendon/spatial/pulley",)
    #: Divisor of the tendon length of the branch after the pulley.
    divisor: float | None = number()


@node
class TendonJoint(TypedElement):
    """A joint and its coefficient in a fixed tendon."""

    schema_keys: ClassVar[tuple[str, ...]] = ("tendon/fixed/joint",)
    #: Coefficient of the joint in the fixed tendon.
    coef: float | None = number()
    #: Name of the joint.
    joint: str | None = text()
