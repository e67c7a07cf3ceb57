"""The ``<visual>`` section. Its settings are kept as text: they never take part in transforms.

>>> VisualGlobal(offwidth="1920").offwidth
'1920'
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import text

__all__ = [
    "Visual",
    "VisualGlobal",
    "VisualHeadlight",
    "VisualMap",
    "VisualQuality",
    "VisualRgba",
    "VisualScale",
]


@node
class Visual(TypedElement):
    """Visualization settings section."""

    schema_keys: ClassVar[tuple[str, ...]] = ("visual",)


@node
class VisualGlobal(TypedElement):
    """Global visualization settings."""

    schema_keys: ClassVar[tuple[str, ...]] = ("visual/global",)
    #: Visualization setting ``azimuth``; see the MuJoCo XML reference.
    azimuth: str | None = text()
    #: Visualization setting ``bvactive``; see the MuJoCo XML reference.
    bvactive: str | None = text()
    #: Visualization setting ``cameraid``; see the MuJoCo XML reference.
    cameraid: str | None = text()
    #: Elevation data.
    elevation: str | None = text()
    #: Visualization setting ``ellipsoidinertia``; see the MuJoCo XML reference.
    ellipsoidinertia: str | None = text()
    #: Vertical field of view in degrees.
    fovy: str | None = text()
    #: Visualization setting ``glow``; see the MuJoCo XML reference.
    glow: str | None = text()
    #: Inter-pupillary distance for stereo rendering.
    ipd: str | None = text()
    #: Visualization setting ``linewidth``; see the MuJoCo XML reference.
    linewidth: str | None = text()
    #: Visualization setting ``offheight``; see the MuJoCo XML reference.
    offheight: str | None = text()
    #: Visualization setting ``offwidth``; see the MuJoCo XML reference.
    offwidth: str | None = text()
    #: Visualization setting ``orthographic``; see the MuJoCo XML reference.
    orthographic: str | None = text()
    #: Visualization setting ``realtime``; see the MuJoCo XML reference.
    realtime: str | None = text()


@node
class VisualQuality(TypedElement):
    """Rendering quality settings."""

    schema_keys: ClassVar[tuple[str, ...]] = ("visual/quality",)
    #: Visualization setting ``numquads``; see the MuJoCo XML reference.
    numquads: str | None = text()
    #: Visualization setting ``numslices``; see the MuJoCo XML reference.
    numslices: str | None = text()
    #: Visualization setting ``numstacks``; see the MuJoCo XML reference.
    numstacks: str | None = text()
    #: Visualization setting ``offsamples``; see the MuJoCo XML reference.
    offsamples: str | None = text()
    #: Visualization setting ``shadowsize``; see the MuJoCo XML reference.
    shadowsize: str | None = text()


@node
class VisualHeadlight(TypedElement):
    """The headlight."""

    schema_keys: ClassVar[tuple[str, ...]] = ("visual/headlight",)
    #: Whether the element is active initially.
    active: str | None = text()
    #: Ambient colour.
    ambient: str | None = text()
    #: Diffuse colour.
    diffuse: str | None = text()
    #: Specular colour or intensity.
    specular: str | None = text()


@node
class VisualMap(TypedElement):
    """Mapping of model quantities to visual ones."""

    schema_keys: ClassVar[tuple[str, ...]] = ("visual/map",)
    #: Visualization setting ``actuatortendon``; see the MuJoCo XML reference.
    actuatortendon: str | None = text()
    #: Visualization setting ``alpha``; see the MuJoCo XML reference.
    alpha: str | None = text()
    #: Visualization setting ``fogend``; see the MuJoCo XML reference.
    fogend: str | None = text()
    #: Visualization setting ``fogstart``; see the MuJoCo XML reference.
    fogstart: str | None = text()
    #: Peak force.
    force: str | None = text()
    #: Visualization setting ``haze``; see the MuJoCo XML reference.
    haze: str | None = text()
    #: Visualization setting ``shadowclip``; see the MuJoCo XML reference.
    shadowclip: str | None = text()
    #: Visualization setting ``shadowscale``; see the MuJoCo XML reference.
    shadowscale: str | None = text()
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: str | None = text()
    #: Visualization setting ``stiffnessrot``; see the MuJoCo XML reference.
    stiffnessrot: str | None = text()
    #: Visualization setting ``torque``; see the MuJoCo XML reference.
    torque: str | None = text()
    #: Visualization setting ``zfar``; see the MuJoCo XML reference.
    zfar: str | None = text()
    #: Visualization setting ``znear``; see the MuJoCo XML reference.
    znear: str | None = text()


@node
class VisualScale(TypedElement):
    """Sizes of decorative elements."""

    schema_keys: ClassVar[tuple[str, ...]] = ("visual/scale",)
    #: Visualization setting ``actuatorlength``; see the MuJoCo XML reference.
    actuatorlength: str | None = text()
    #: Visualization setting ``actuatorwidth``; see the MuJoCo XML reference.
    actuatorwidth: str | None = text()
    #: Name of the camera.
    camera: str | None = text()
    #: Visualization setting ``com``; see the MuJoCo XML reference.
    com: str | None = text()
    #: Visualization setting ``connect``; see the MuJoCo XML reference.
    connect: str | None = text()
    #: Visualization setting ``constraint``; see the MuJoCo XML reference.
    constraint: str | None = text()
    #: Visualization setting ``contactheight``; see the MuJoCo XML reference.
    contactheight: str | None = text()
    #: Visualization setting ``contactwidth``; see the MuJoCo XML reference.
    contactwidth: str | None = text()
    #: Visualization setting ``forcewidth``; see the MuJoCo XML reference.
    forcewidth: str | None = text()
    #: Visualization setting ``framelength``; see the MuJoCo XML reference.
    framelength: str | None = text()
    #: Visualization setting ``framewidth``; see the MuJoCo XML reference.
    framewidth: str | None = text()
    #: Visualization setting ``frustum``; see the MuJoCo XML reference.
    frustum: str | None = text()
    #: Visualization setting ``jointlength``; see the MuJoCo XML reference.
    jointlength: str | None = text()
    #: Visualization setting ``jointwidth``; see the MuJoCo XML reference.
    jointwidth: str | None = text()
    #: Visualization setting ``light``; see the MuJoCo XML reference.
    light: str | None = text()
    #: Visualization setting ``selectpoint``; see the MuJoCo XML reference.
    selectpoint: str | None = text()
    #: Visualization setting ``slidercrank``; see the MuJoCo XML reference.
    slidercrank: str | None = text()


@node
class VisualRgba(TypedElement):
    """Colours of decorative elements."""

    schema_keys: ClassVar[tuple[str, ...]] = ("visual/rgba",)
    #: Name of the actuator.
    actuator: str | None = text()
    #: Visualization setting ``actuatornegative``; see the MuJoCo XML reference.
    actuatornegative: str | None = text()
    #: Visualization setting ``actuatorpositive``; see the MuJoCo XML reference.
    actuatorpositive: str | None = text()
    #: Visualization setting ``bv``; see the MuJoCo XML reference.
    bv: str | None = text()
    #: Visualization setting ``bvactive``; see the MuJoCo XML reference.
    bvactive: str | None = text()
    #: Name of the camera.
    camera: str | None = text()
    #: Visualization setting ``com``; see the MuJoCo XML reference.
    com: str | None = text()
    #: Visualization setting ``connect``; see the MuJoCo XML reference.
    connect: str | None = text()
    #: Visualization setting ``constraint``; see the MuJoCo XML reference.
    constraint: str | None = text()
    #: Visualization setting ``contactforce``; see the MuJoCo XML reference.
    contactforce: str | None = text()
    #: Visualization setting ``contactfriction``; see the MuJoCo XML reference.
    contactfriction: str | None = text()
    #: Visualization setting ``contactgap``; see the MuJoCo XML reference.
    contactgap: str | None = text()
    #: Visualization setting ``contactpoint``; see the MuJoCo XML reference.
    contactpoint: str | None = text()
    #: Visualization setting ``contacttorque``; see the MuJoCo XML reference.
    contacttorque: str | None = text()
    #: Visualization setting ``crankbroken``; see the MuJoCo XML reference.
    crankbroken: str | None = text()
    #: Visualization setting ``fog``; see the MuJoCo XML reference.
    fog: str | None = text()
    #: Peak force.
    force: str | None = text()
    #: Visualization setting ``frustum``; see the MuJoCo XML reference.
    frustum: str | None = text()
    #: Visualization setting ``haze``; see the MuJoCo XML reference.
    haze: str | None = text()
    #: How inertia is computed from the mesh.
    inertia: str | None = text()
    #: Name of the joint.
    joint: str | None = text()
    #: Visualization setting ``light``; see the MuJoCo XML reference.
    light: str | None = text()
    #: Visualization setting ``rangefinder``; see the MuJoCo XML reference.
    rangefinder: str | None = text()
    #: Visualization setting ``selectpoint``; see the MuJoCo XML reference.
    selectpoint: str | None = text()
    #: Visualization setting ``slidercrank``; see the MuJoCo XML reference.
    slidercrank: str | None = text()
