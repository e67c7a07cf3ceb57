"""Deformable bodies: ``<flexcomp>`` in the tree and the ``<deformable>`` section.

>>> Flexcomp(name="cloth", type="grid", count=[3, 3, 1]).count
(3, 3, 1)
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.nodes.geom import Oriented
from mjcf_model.values import (
    Floats,
    Ints,
    float_key,
    to_float,
    to_floats,
    to_int,
    to_ints,
    to_str,
    to_vec1to2,
    to_vec1to3,
    to_vec1to5,
    to_vec3,
    to_vec4,
)

__all__ = [
    "Deformable",
    "Flex",
    "FlexContact",
    "FlexEdge",
    "FlexElasticity",
    "Flexcomp",
    "FlexcompEdge",
    "FlexcompPin",
]


@attrs.frozen(kw_only=True, repr=False)
class Flexcomp(Oriented):
    """A flex generated from a grid, mesh or points."""

    tag: ClassVar[str] = "flexcomp"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Element type keyword.
    type: str | None = attrs.field(default=None, converter=to_str)
    #: Number of cells.
    cellcount: str | None = attrs.field(default=None, converter=to_str)
    #: Number of repetitions or grid points.
    count: Ints | None = attrs.field(default=None, converter=to_ints)
    #: Dimension.
    dim: int | None = attrs.field(default=None, converter=to_int)
    #: Degree-of-freedom parametrization.
    dof: str | None = attrs.field(default=None, converter=to_str)
    #: Element vertex indices.
    element: Ints | None = attrs.field(default=None, converter=to_ints)
    #: File name, relative to the model (or asset) directory.
    file: str | None = attrs.field(default=None, converter=to_str)
    #: Whether the flex skin is rendered flat.
    flatskin: str | None = attrs.field(default=None, converter=to_str)
    #: Integer group, used for visualization filters and by convention.
    group: int | None = attrs.field(default=None, converter=to_int)
    #: Size of the inertia box of each point body.
    inertiabox: str | None = attrs.field(default=None, converter=to_str)
    #: Mass.
    mass: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the material asset used for rendering.
    material: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the mesh asset.
    mesh: str | None = attrs.field(default=None, converter=to_str)
    #: Origin of the flexcomp.
    origin: str | None = attrs.field(default=None, converter=to_str)
    #: Point coordinates.
    point: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Radius of the flex elements.
    radius: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Whether all points are in one rigid body.
    rigid: str | None = attrs.field(default=None, converter=to_str)
    #: Scale factor(s).
    scale: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Spacing between grid points.
    spacing: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Texture coordinates.
    texcoord: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class FlexcompEdge(TypedElement):
    """Edge properties of a flexcomp."""

    tag: ClassVar[str] = "edge"
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Whether edge equality constraints are generated.
    equality: str | None = attrs.field(default=None, converter=to_str)
    #: Constraint solver impedance parameters.
    solimp: Floats | None = attrs.field(default=None, converter=to_vec1to5)
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = attrs.field(default=None, converter=to_vec1to2)
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class FlexElasticity(TypedElement):
    """Elasticity of a flex."""

    tag: ClassVar[str] = "elasticity"
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Elastic 2D mode.
    elastic2d: str | None = attrs.field(default=None, converter=to_str)
    #: Poisson ratio.
    poisson: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Cross-section shape.
    section: str | None = attrs.field(default=None, converter=to_str)
    #: Cross-section size.
    sectionsize: str | None = attrs.field(default=None, converter=to_str)
    #: Shear parameter.
    shear: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Shell thickness.
    thickness: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Yield parameter.
    yield_: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "yield"})
    #: Young modulus.
    young: float | None = attrs.field(default=None, converter=to_float, eq=float_key)


@attrs.frozen(kw_only=True, repr=False)
class FlexContact(TypedElement):
    """Contact properties of a flex."""

    tag: ClassVar[str] = "contact"
    #: Number of active collision layers.
    activelayers: str | None = attrs.field(default=None, converter=to_str)
    #: Contact affinity bitmask.
    conaffinity: int | None = attrs.field(default=None, converter=to_int)
    #: Dimensionality of the contact space (1, 3, 4 or 6).
    condim: int | None = attrs.field(default=None, converter=to_int)
    #: Contact type bitmask.
    contype: int | None = attrs.field(default=None, converter=to_int)
    #: Sliding, torsional and rolling friction coefficients.
    friction: Floats | None = attrs.field(default=None, converter=to_vec1to3)
    #: Part of the margin within which contacts are not generated.
    gap: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Distance at which contacts (or limits) become active.
    margin: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Whether passive contacts are generated.
    passive: str | None = attrs.field(default=None, converter=to_str)
    #: Contact priority.
    priority: int | None = attrs.field(default=None, converter=to_int)
    #: Self-collision mode.
    selfcollide: str | None = attrs.field(default=None, converter=to_str)
    #: Constraint solver impedance parameters.
    solimp: Floats | None = attrs.field(default=None, converter=to_vec1to5)
    #: Weight for mixing solver parameters of two contacting geoms.
    solmix: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = attrs.field(default=None, converter=to_vec1to2)


@attrs.frozen(kw_only=True, repr=False)
class FlexcompPin(TypedElement):
    """Points of a flexcomp pinned in place."""

    tag: ClassVar[str] = "pin"
    #: Grid coordinates of pinned points.
    grid: Ints | None = attrs.field(default=None, converter=to_ints)
    #: Grid ranges of pinned points.
    gridrange: Ints | None = attrs.field(default=None, converter=to_ints)
    #: Indices of pinned points.
    id: Ints | None = attrs.field(default=None, converter=to_ints)
    #: Lower and upper limits.
    range: Ints | None = attrs.field(default=None, converter=to_ints)


@attrs.frozen(kw_only=True, repr=False)
class Deformable(TypedElement):
    """Section of flexes and skins."""

    tag: ClassVar[str] = "deformable"


@attrs.frozen(kw_only=True, repr=False)
class Flex(TypedElement):
    """A flex: a deformable collection of elements."""

    tag: ClassVar[str] = "flex"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Names of the bodies the vertices belong to, separated by spaces.
    body: str | None = attrs.field(default=None, converter=to_str)
    #: Number of cells.
    cellcount: str | None = attrs.field(default=None, converter=to_str)
    #: Dimension.
    dim: int | None = attrs.field(default=None, converter=to_int)
    #: Degree-of-freedom parametrization.
    dof: str | None = attrs.field(default=None, converter=to_str)
    #: Element vertex indices.
    element: Ints | None = attrs.field(default=None, converter=to_ints)
    #: Element texture coordinates.
    elemtexcoord: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Whether the flex skin is rendered flat.
    flatskin: str | None = attrs.field(default=None, converter=to_str)
    #: Integer group, used for visualization filters and by convention.
    group: int | None = attrs.field(default=None, converter=to_int)
    #: Name of the material asset used for rendering.
    material: str | None = attrs.field(default=None, converter=to_str)
    #: Names of the bodies used as nodes.
    node: str | None = attrs.field(default=None, converter=to_str)
    #: Node coordinates.
    nodecoord: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Radius of the flex elements.
    radius: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Texture coordinates.
    texcoord: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Vertex coordinates.
    vertex: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class FlexEdge(TypedElement):
    """Edge properties of a flex."""

    tag: ClassVar[str] = "edge"
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: Floats | None = attrs.field(default=None, converter=to_floats)
