"""Deformable bodies: ``<flexcomp>`` in the tree and the ``<deformable>`` section.

>>> Flexcomp(name="cloth", type="grid", count=[3, 3, 1]).count
(3, 3, 1)
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import (
    integer,
    integers,
    number,
    numbers,
    text,
    vec1to2,
    vec1to3,
    vec1to5,
    vec3,
    vec4,
)
from mjcf_model.nodes.geom import Oriented
from mjcf_model.values import Floats, Ints

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


@node
class Flexcomp(Oriented):
    """A flex generated from a grid, mesh or points."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/flexcomp",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Element type keyword.
    type: str | None = text()
    #: Number of cells.
    cellcount: str | None = text()
    #: Number of repetitions or grid points.
    count: Ints | None = integers()
    #: Dimension.
    dim: int | None = integer()
    #: Degree-of-freedom parametrization.
    dof: str | None = text()
    #: Element vertex indices.
    element: Ints | None = integers()
    #: File name, relative to the model (or asset) directory.
    file: str | None = text()
    #: Whether the flex skin is rendered flat.
    flatskin: str | None = text()
    #: Integer group, used for visualization filters and by convention.
    group: int | None = integer()
    #: Size of the inertia box of each point body.
    inertiabox: str | None = text()
    #: Mass.
    mass: float | None = number()
    #: Name of the material asset used for rendering.
    material: str | None = text()
    #: Name of the mesh asset.
    mesh: str | None = text()
    #: Origin of the flexcomp.
    origin: str | None = text()
    #: Point coordinates.
    point: Floats | None = numbers()
    #: Radius of the flex elements.
    radius: float | None = number()
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = vec4()
    #: Whether all points are in one rigid body.
    rigid: str | None = text()
    #: Scale factor(s).
    scale: Floats | None = vec3()
    #: Spacing between grid points.
    spacing: Floats | None = numbers()
    #: Texture coordinates.
    texcoord: Floats | None = numbers()


@node
class FlexcompEdge(TypedElement):
    """Edge properties of a flexcomp."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/flexcomp/edge",)
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = numbers()
    #: Whether edge equality constraints are generated.
    equality: str | None = text()
    #: Constraint solver impedance parameters.
    solimp: Floats | None = vec1to5()
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = vec1to2()
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: Floats | None = numbers()


@node
class FlexElasticity(TypedElement):
    """Elasticity of a flex."""

    schema_keys: ClassVar[tuple[str, ...]] = (
        "body/flexcomp/elasticity",
        "deformable/flex/elasticity",
    )
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = numbers()
    #: Elastic 2D mode.
    elastic2d: str | None = text()
    #: Poisson ratio.
    poisson: float | None = number()
    #: Cross-section shape.
    section: str | None = text()
    #: Cross-section size.
    sectionsize: str | None = text()
    #: Shear parameter.
    shear: float | None = number()
    #: Shell thickness.
    thickness: float | None = number()
    #: Yield parameter.
    yield_: str | None = text(xml="yield")
    #: Young modulus.
    young: float | None = number()


@node
class FlexContact(TypedElement):
    """Contact properties of a flex."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/flexcomp/contact", "deformable/flex/contact")
    #: Number of active collision layers.
    activelayers: str | None = text()
    #: Contact affinity bitmask.
    conaffinity: int | None = integer()
    #: Dimensionality of the contact space (1, 3, 4 or 6).
    condim: int | None = integer()
    #: Contact type bitmask.
    contype: int | None = integer()
    #: Sliding, torsional and rolling friction coefficients.
    friction: Floats | None = vec1to3()
    #: Part of the margin within which contacts are not generated.
    gap: float | None = number()
    #: Distance at which contacts (or limits) become active.
    margin: float | None = number()
    #: Whether passive contacts are generated.
    passive: str | None = text()
    #: Contact priority.
    priority: int | None = integer()
    #: Self-collision mode.
    selfcollide: str | None = text()
    #: Constraint solver impedance parameters.
    solimp: Floats | None = vec1to5()
    #: Weight for mixing solver parameters of two contacting geoms.
    solmix: float | None = number()
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = vec1to2()


@node
class FlexcompPin(TypedElement):
    """Points of a flexcomp pinned in place."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/flexcomp/pin",)
    #: Grid coordinates of pinned points.
    grid: Ints | None = integers()
    #: Grid ranges of pinned points.
    gridrange: Ints | None = integers()
    #: Indices of pinned points.
    id: Ints | None = integers()
    #: Lower and upper limits.
    range: Ints | None = integers()


@node
class Deformable(TypedElement):
    """Section of flexes and skins."""

    schema_keys: ClassVar[tuple[str, ...]] = ("deformable",)


@node
class Flex(TypedElement):
    """A flex: a deformable collection of elements."""

    schema_keys: ClassVar[tuple[str, ...]] = ("deformable/flex",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Names of the bodies the vertices belong to, separated by spaces.
    body: str | None = text()
    #: Number of cells.
    cellcount: str | None = text()
    #: Dimension.
    dim: int | None = integer()
    #: Degree-of-freedom parametrization.
    dof: str | None = text()
    #: Element vertex indices.
    element: Ints | None = integers()
    #: Element texture coordinates.
    elemtexcoord: Floats | None = numbers()
    #: Whether the flex skin is rendered flat.
    flatskin: str | None = text()
    #: Integer group, used for visualization filters and by convention.
    group: int | None = integer()
    #: Name of the material asset used for rendering.
    material: str | None = text()
    #: Names of the bodies used as nodes.
    node: str | None = text()
    #: Node coordinates.
    nodecoord: Floats | None = numbers()
    #: Radius of the flex elements.
    radius: float | None = number()
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = vec4()
    #: Texture coordinates.
    texcoord: Floats | None = numbers()
    #: Vertex coordinates.
    vertex: Floats | None = numbers()


@node
class FlexEdge(TypedElement):
    """Edge properties of a flex."""

    schema_keys: ClassVar[tuple[str, ...]] = ("deformable/flex/edge",)
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = numbers()
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: Floats | None = numbers()
