"""The ``<visual>`` section. Its settings are kept as text: they never take part in transforms.

>>> VisualGlobal(offwidth="1920").offwidth
'1920'
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.values import to_str

__all__ = [
    "Visual",
    "VisualGlobal",
    "VisualHeadlight",
    "VisualMap",
    "VisualQuality",
    "VisualRgba",
    "VisualScale",
]


@attrs.frozen(kw_only=True, repr=False)
class Visual(TypedElement):
    """Visualization settings section."""

    tag: ClassVar[str] = "visual"


@attrs.frozen(kw_only=True, repr=False)
class VisualGlobal(TypedElement):
    """Global visualization settings."""

    tag: ClassVar[str] = "global"
    #: Visualization setting ``azimuth``; see the MuJoCo XML reference.
    azimuth: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``bvactive``; see the MuJoCo XML reference.
    bvactive: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``cameraid``; see the MuJoCo XML reference.
    cameraid: str | None = attrs.field(default=None, converter=to_str)
    #: Elevation data.
    elevation: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``ellipsoidinertia``; see the MuJoCo XML reference.
    ellipsoidinertia: str | None = attrs.field(default=None, converter=to_str)
    #: Vertical field of view in degrees.
    fovy: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``glow``; see the MuJoCo XML reference.
    glow: str | None = attrs.field(default=None, converter=to_str)
    #: Inter-pupillary distance for stereo rendering.
    ipd: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``linewidth``; see the MuJoCo XML reference.
    linewidth: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``offheight``; see the MuJoCo XML reference.
    offheight: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``offwidth``; see the MuJoCo XML reference.
    offwidth: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``orthographic``; see the MuJoCo XML reference.
    orthographic: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``realtime``; see the MuJoCo XML reference.
    realtime: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class VisualQuality(TypedElement):
    """Rendering quality settings."""

    tag: ClassVar[str] = "quality"
    #: Visualization setting ``numquads``; see the MuJoCo XML reference.
    numquads: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``numslices``; see the MuJoCo XML reference.
    numslices: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``numstacks``; see the MuJoCo XML reference.
    numstacks: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``offsamples``; see the MuJoCo XML reference.
    offsamples: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``shadowsize``; see the MuJoCo XML reference.
    shadowsize: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class VisualHeadlight(TypedElement):
    """The headlight."""

    tag: ClassVar[str] = "headlight"
    #: Whether the element is active initially.
    active: str | None = attrs.field(default=None, converter=to_str)
    #: Ambient colour.
    ambient: str | None = attrs.field(default=None, converter=to_str)
    #: Diffuse colour.
    diffuse: str | None = attrs.field(default=None, converter=to_str)
    #: Specular colour or intensity.
    specular: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class VisualMap(TypedElement):
    """Mapping of model quantities to visual ones."""

    tag: ClassVar[str] = "map"
    #: Visualization setting ``actuatortendon``; see the MuJoCo XML reference.
    actuatortendon: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``alpha``; see the MuJoCo XML reference.
    alpha: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``fogend``; see the MuJoCo XML reference.
    fogend: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``fogstart``; see the MuJoCo XML reference.
    fogstart: str | None = attrs.field(default=None, converter=to_str)
    #: Peak force.
    force: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``haze``; see the MuJoCo XML reference.
    haze: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``shadowclip``; see the MuJoCo XML reference.
    shadowclip: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``shadowscale``; see the MuJoCo XML reference.
    shadowscale: str | None = attrs.field(default=None, converter=to_str)
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``stiffnessrot``; see the MuJoCo XML reference.
    stiffnessrot: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``torque``; see the MuJoCo XML reference.
    torque: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``zfar``; see the MuJoCo XML reference.
    zfar: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``znear``; see the MuJoCo XML reference.
    znear: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class VisualScale(TypedElement):
    """Sizes of decorative elements."""

    tag: ClassVar[str] = "scale"
    #: Visualization setting ``actuatorlength``; see the MuJoCo XML reference.
    actuatorlength: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``actuatorwidth``; see the MuJoCo XML reference.
    actuatorwidth: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the camera.
    camera: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``com``; see the MuJoCo XML reference.
    com: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``connect``; see the MuJoCo XML reference.
    connect: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``constraint``; see the MuJoCo XML reference.
    constraint: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``contactheight``; see the MuJoCo XML reference.
    contactheight: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``contactwidth``; see the MuJoCo XML reference.
    contactwidth: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``forcewidth``; see the MuJoCo XML reference.
    forcewidth: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``framelength``; see the MuJoCo XML reference.
    framelength: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``framewidth``; see the MuJoCo XML reference.
    framewidth: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``frustum``; see the MuJoCo XML reference.
    frustum: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``jointlength``; see the MuJoCo XML reference.
    jointlength: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``jointwidth``; see the MuJoCo XML reference.
    jointwidth: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``light``; see the MuJoCo XML reference.
    light: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``selectpoint``; see the MuJoCo XML reference.
    selectpoint: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``slidercrank``; see the MuJoCo XML reference.
    slidercrank: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class VisualRgba(TypedElement):
    """Colours of decorative elements."""

    tag: ClassVar[str] = "rgba"
    #: Name of the actuator.
    actuator: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``actuatornegative``; see the MuJoCo XML reference.
    actuatornegative: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``actuatorpositive``; see the MuJoCo XML reference.
    actuatorpositive: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``bv``; see the MuJoCo XML reference.
    bv: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``bvactive``; see the MuJoCo XML reference.
    bvactive: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the camera.
    camera: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``com``; see the MuJoCo XML reference.
    com: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``connect``; see the MuJoCo XML reference.
    connect: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``constraint``; see the MuJoCo XML reference.
    constraint: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``contactforce``; see the MuJoCo XML reference.
    contactforce: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``contactfriction``; see the MuJoCo XML reference.
    contactfriction: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``contactgap``; see the MuJoCo XML reference.
    contactgap: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``contactpoint``; see the MuJoCo XML reference.
    contactpoint: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``contacttorque``; see the MuJoCo XML reference.
    contacttorque: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``crankbroken``; see the MuJoCo XML reference.
    crankbroken: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``fog``; see the MuJoCo XML reference.
    fog: str | None = attrs.field(default=None, converter=to_str)
    #: Peak force.
    force: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``frustum``; see the MuJoCo XML reference.
    frustum: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``haze``; see the MuJoCo XML reference.
    haze: str | None = attrs.field(default=None, converter=to_str)
    #: How inertia is computed from the mesh.
    inertia: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the joint.
    joint: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``light``; see the MuJoCo XML reference.
    light: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``rangefinder``; see the MuJoCo XML reference.
    rangefinder: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``selectpoint``; see the MuJoCo XML reference.
    selectpoint: str | None = attrs.field(default=None, converter=to_str)
    #: Visualization setting ``slidercrank``; see the MuJoCo XML reference.
    slidercrank: str | None = attrs.field(default=None, converter=to_str)
