"""Geoms, sites, cameras and lights: the things a body carries.

>>> Geom(type="box", size=[0.1, 0.2, 0.3]).size
(0.1, 0.2, 0.3)
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.keywords import GEOM_TYPES, LIGHT_TYPES, TRACKING_MODES
from mjcf_model.values import (
    Floats,
    Ints,
    float_key,
    one_of,
    to_bool,
    to_float,
    to_floats,
    to_int,
    to_ints,
    to_str,
    to_vec1to2,
    to_vec1to3,
    to_vec1to5,
    to_vec2,
    to_vec3,
    to_vec4,
    to_vec6,
)

__all__ = ["Camera", "Geom", "Light", "Oriented", "Site"]


@attrs.frozen(kw_only=True, repr=False)
class Oriented(TypedElement):
    """Base of elements placed in their parent's frame by a position and one orientation."""

    #: Position (x, y, z) in the parent frame, in length units.
    pos: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Orientation as a unit quaternion (w, x, y, z).
    quat: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Orientation as a rotation axis and angle.
    axisangle: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Orientation as the frame's X and Y axes.
    xyaxes: Floats | None = attrs.field(default=None, converter=to_vec6)
    #: Orientation as the frame's Z axis (minimal rotation from +Z).
    zaxis: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Orientation as Euler angles in the compiler's ``eulerseq``.
    euler: Floats | None = attrs.field(default=None, converter=to_vec3)


@attrs.frozen(kw_only=True, repr=False)
class Geom(Oriented):
    """A geometric shape used for collision, rendering and inertia."""

    tag: ClassVar[str] = "geom"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})
    #: Element type keyword.
    type: str | None = attrs.field(default=None, converter=to_str, validator=one_of(GEOM_TYPES))
    #: Size parameters; their number and meaning depend on ``type``.
    size: Floats | None = attrs.field(default=None, converter=to_vec1to3)
    #: Start and end points (x1 y1 z1 x2 y2 z2) of a capsule, cylinder, box or ellipsoid.
    fromto: Floats | None = attrs.field(default=None, converter=to_vec6)
    #: Adhesion force parameter.
    adhesion: str | None = attrs.field(default=None, converter=to_str)
    #: Whether the element casts shadows.
    castshadow: str | None = attrs.field(default=None, converter=to_str)
    #: Contact affinity bitmask.
    conaffinity: int | None = attrs.field(default=None, converter=to_int)
    #: Dimensionality of the contact space (1, 3, 4 or 6).
    condim: int | None = attrs.field(default=None, converter=to_int)
    #: Contact type bitmask.
    contype: int | None = attrs.field(default=None, converter=to_int)
    #: Density used to compute mass from volume.
    density: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Scale applied when fitting a primitive to a mesh.
    fitscale: str | None = attrs.field(default=None, converter=to_str)
    #: Coefficients of the ellipsoid fluid model.
    fluidcoef: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Fluid interaction model (``none`` or ``ellipsoid``).
    fluidshape: str | None = attrs.field(default=None, converter=to_str)
    #: Sliding, torsional and rolling friction coefficients.
    friction: Floats | None = attrs.field(default=None, converter=to_vec1to3)
    #: Part of the margin within which contacts are not generated.
    gap: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Integer group, used for visualization filters and by convention.
    group: int | None = attrs.field(default=None, converter=to_int)
    #: Name of the height-field asset.
    hfield: str | None = attrs.field(default=None, converter=to_str)
    #: Distance at which contacts (or limits) become active.
    margin: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Mass.
    mass: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Name of the material asset used for rendering.
    material: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the mesh asset.
    mesh: str | None = attrs.field(default=None, converter=to_str)
    #: Contact priority.
    priority: int | None = attrs.field(default=None, converter=to_int)
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Whether mass is distributed over the surface rather than the volume.
    shellinertia: bool | None = attrs.field(default=None, converter=to_bool)
    #: Constraint solver impedance parameters.
    solimp: Floats | None = attrs.field(default=None, converter=to_vec1to5)
    #: Weight for mixing solver parameters of two contacting geoms.
    solmix: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = attrs.field(default=None, converter=to_vec1to2)
    #: Surface velocity of a conveyor-like geom.
    surfacevel: str | None = attrs.field(default=None, converter=to_str)
    #: Custom user data (numbers).
    user: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class Site(Oriented):
    """A site: a frame of interest that does not collide."""

    tag: ClassVar[str] = "site"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})
    #: Element type keyword.
    type: str | None = attrs.field(default=None, converter=to_str)
    #: Size parameters; their number and meaning depend on ``type``.
    size: Floats | None = attrs.field(default=None, converter=to_vec1to3)
    #: Start and end points (x1 y1 z1 x2 y2 z2) of a capsule, cylinder, box or ellipsoid.
    fromto: Floats | None = attrs.field(default=None, converter=to_vec6)
    #: Integer group, used for visualization filters and by convention.
    group: int | None = attrs.field(default=None, converter=to_int)
    #: Name of the material asset used for rendering.
    material: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the mesh asset.
    mesh: str | None = attrs.field(default=None, converter=to_str)
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = attrs.field(default=None, converter=to_vec4)
    #: Custom user data (numbers).
    user: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class Camera(Oriented):
    """A camera."""

    tag: ClassVar[str] = "camera"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})
    #: Focal length in length units.
    focal: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Focal length in pixels.
    focalpixel: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Vertical field of view in degrees.
    fovy: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Inter-pupillary distance for stereo rendering.
    ipd: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: How the element tracks its target (``fixed``, ``track``, ``trackcom``, ...).
    mode: str | None = attrs.field(default=None, converter=to_str, validator=one_of(TRACKING_MODES))
    #: Output channels of the camera.
    output: str | None = attrs.field(default=None, converter=to_str)
    #: Principal point in length units.
    principal: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Principal point in pixels.
    principalpixel: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Projection type (``perspective`` or ``orthographic``).
    projection: str | None = attrs.field(default=None, converter=to_str)
    #: Image resolution in pixels (width, height).
    resolution: Ints | None = attrs.field(default=None, converter=to_ints)
    #: Physical sensor size.
    sensorsize: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Name of the body a tracking camera or light targets.
    target: str | None = attrs.field(default=None, converter=to_str)
    #: Custom user data (numbers).
    user: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class Light(TypedElement):
    """A light."""

    tag: ClassVar[str] = "light"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})
    #: Element type keyword.
    type: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIGHT_TYPES))
    #: Position (x, y, z) in the parent frame, in length units.
    pos: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Whether the element is active initially.
    active: bool | None = attrs.field(default=None, converter=to_bool)
    #: Ambient colour.
    ambient: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Constant, linear and quadratic attenuation.
    attenuation: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Radius of the light bulb, for soft shadows.
    bulbradius: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Whether the element casts shadows.
    castshadow: bool | None = attrs.field(default=None, converter=to_bool)
    #: Cutoff (spot angle for lights; output clamp for sensors).
    cutoff: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Diffuse colour.
    diffuse: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Direction the light points in.
    dir: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Whether the light is directional (legacy form of ``type``).
    directional: bool | None = attrs.field(default=None, converter=to_bool)
    #: Spotlight exponent.
    exponent: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Light intensity.
    intensity: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: How the element tracks its target (``fixed``, ``track``, ``trackcom``, ...).
    mode: str | None = attrs.field(default=None, converter=to_str, validator=one_of(TRACKING_MODES))
    #: Lower and upper limits.
    range: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Shadow softness.
    softness: str | None = attrs.field(default=None, converter=to_str)
    #: Specular colour or intensity.
    specular: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Name of the body a tracking camera or light targets.
    target: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the texture asset.
    texture: str | None = attrs.field(default=None, converter=to_str)
