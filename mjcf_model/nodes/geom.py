"""Geoms, sites, cameras and lights: the things a body carries.

>>> Geom(type="box", size=[0.1, 0.2, 0.3]).size
(0.1, 0.2, 0.3)
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import (
    boolean,
    integer,
    integers,
    keyword,
    number,
    numbers,
    text,
    vec1to2,
    vec1to3,
    vec1to5,
    vec2,
    vec3,
    vec4,
    vec6,
)
from mjcf_model.schema.keywords import GEOM_TYPES, LIGHT_TYPES, TRACKING_MODES
from mjcf_model.values import Floats, Ints

__all__ = ["Camera", "Geom", "Light", "Oriented", "Site"]


@node
class Oriented(TypedElement):
    """Base of elements placed in their parent's frame by a position and one orientation."""

    #: Position (x, y, z) in the parent frame, in length units.
    pos: Floats | None = vec3()
    #: Orientation as a unit quaternion (w, x, y, z).
    quat: Floats | None = vec4()
    #: Orientation as a rotation axis and angle.
    axisangle: Floats | None = vec4()
    #: Orientation as the frame's X and Y axes.
    xyaxes: Floats | None = vec6()
    #: Orientation as the frame's Z axis (minimal rotation from +Z).
    zaxis: Floats | None = vec3()
    #: Orientation as Euler angles in the compiler's ``eulerseq``.
    euler: Floats | None = vec3()


@node
class Geom(Oriented):
    """A geometric shape used for collision, rendering and inertia."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/geom", "default/geom")
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")
    #: Element type keyword.
    type: str | None = keyword(GEOM_TYPES)
    #: Size parameters; their number and meaning depend on ``type``.
    size: Floats | None = vec1to3()
    #: Start and end points (x1 y1 z1 x2 y2 z2) of a capsule, cylinder, box or ellipsoid.
    fromto: Floats | None = vec6()
    #: Adhesion force parameter.
    adhesion: str | None = text()
    #: Whether the element casts shadows.
    castshadow: str | None = text()
    #: Contact affinity bitmask.
    conaffinity: int | None = integer()
    #: Dimensionality of the contact space (1, 3, 4 or 6).
    condim: int | None = integer()
    #: Contact type bitmask.
    contype: int | None = integer()
    #: Density used to compute mass from volume.
    density: float | None = number()
    #: Scale applied when fitting a primitive to a mesh.
    fitscale: str | None = text()
    #: Coefficients of the ellipsoid fluid model.
    fluidcoef: Floats | None = numbers()
    #: Fluid interaction model (``none`` or ``ellipsoid``).
    fluidshape: str | None = text()
    #: Sliding, torsional and rolling friction coefficients.
    friction: Floats | None = vec1to3()
    #: Part of the margin within which contacts are not generated.
    gap: float | None = number()
    #: Integer group, used for visualization filters and by convention.
    group: int | None = integer()
    #: Name of the height-field asset.
    hfield: str | None = text()
    #: Distance at which contacts (or limits) become active.
    margin: float | None = number()
    #: Mass.
    mass: float | None = number()
    #: Name of the material asset used for rendering.
    material: str | None = text()
    #: Name of the mesh asset.
    mesh: str | None = text()
    #: Contact priority.
    priority: int | None = integer()
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = vec4()
    #: Whether mass is distributed over the surface rather than the volume.
    shellinertia: bool | None = boolean()
    #: Constraint solver impedance parameters.
    solimp: Floats | None = vec1to5()
    #: Weight for mixing solver parameters of two contacting geoms.
    solmix: float | None = number()
    #: Constraint solver reference parameters (timeconst, dampratio).
    solref: Floats | None = vec1to2()
    #: Surface velocity of a conveyor-like geom.
    surfacevel: str | None = text()
    #: Custom user data (numbers).
    user: Floats | None = numbers()


@node
class Site(Oriented):
    """A site: a frame of interest that does not collide."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/site", "default/site")
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")
    #: Element type keyword.
    type: str | None = text()
    #: Size parameters; their number and meaning depend on ``type``.
    size: Floats | None = vec1to3()
    #: Start and end points (x1 y1 z1 x2 y2 z2) of a capsule, cylinder, box or ellipsoid.
    fromto: Floats | None = vec6()
    #: Integer group, used for visualization filters and by convention.
    group: int | None = integer()
    #: Name of the material asset used for rendering.
    material: str | None = text()
    #: Name of the mesh asset.
    mesh: str | None = text()
    #: Colour and transparency (r, g, b, a).
    rgba: Floats | None = vec4()
    #: Custom user data (numbers).
    user: Floats | None = numbers()


@node
class Camera(Oriented):
    """A camera."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/camera", "default/camera")
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")
    #: Focal length in length units.
    focal: Floats | None = vec2()
    #: Focal length in pixels.
    focalpixel: Floats | None = vec2()
    #: Vertical field of view in degrees.
    fovy: float | None = number()
    #: Inter-pupillary distance for stereo rendering.
    ipd: float | None = number()
    #: How the element tracks its target (``fixed``, ``track``, ``trackcom``, ...).
    mode: str | None = keyword(TRACKING_MODES)
    #: Output channels of the camera.
    output: str | None = text()
    #: Principal point in length units.
    principal: Floats | None = vec2()
    #: Principal point in pixels.
    principalpixel: Floats | None = vec2()
    #: Projection type (``perspective`` or ``orthographic``).
    projection: str | None = text()
    #: Image resolution in pixels (width, height).
    resolution: Ints | None = integers()
    #: Physical sensor size.
    sensorsize: Floats | None = vec2()
    #: Name of the body a tracking camera or light targets.
    target: str | None = text()
    #: Custom user data (numbers).
    user: Floats | None = numbers()


@node
class Light(TypedElement):
    """A light."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/light", "default/light")
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")
    #: Element type keyword.
    type: str | None = keyword(LIGHT_TYPES)
    #: Position (x, y, z) in the parent frame, in length units.
    pos: Floats | None = vec3()
    #: Whether the element is active initially.
    active: bool | None = boolean()
    #: Ambient colour.
    ambient: Floats | None = vec3()
    #: Constant, linear and quadratic attenuation.
    attenuation: Floats | None = vec3()
    #: Radius of the light bulb, for soft shadows.
    bulbradius: float | None = number()
    #: Whether the element casts shadows.
    castshadow: bool | None = boolean()
    #: Cutoff (spot angle for lights; output clamp for sensors).
    cutoff: float | None = number()
    #: Diffuse colour.
    diffuse: Floats | None = vec3()
    #: Direction the light points in.
    dir: Floats | None = vec3()
    #: Whether the light is directional (legacy form of ``type``).
    directional: bool | None = boolean()
    #: Spotlight exponent.
    exponent: float | None = number()
    #: Light intensity.
    intensity: float | None = number()
    #: How the element tracks its target (``fixed``, ``track``, ``trackcom``, ...).
    mode: str | None = keyword(TRACKING_MODES)
    #: Lower and upper limits.
    range: float | None = number()
    #: Shadow softness.
    softness: str | None = text()
    #: Specular colour or intensity.
    specular: Floats | None = vec3()
    #: Name of the body a tracking camera or light targets.
    target: str | None = text()
    #: Name of the texture asset.
    texture: str | None = text()
