"""The kinematic tree: world body, bodies, frames, replicates, inertials, joints and attachments.

>>> from mjcf_model.nodes.geom import Geom
>>> arm = Body(name="arm", pos=[0, 0, 1], children=[Joint(name="shoulder"), Geom(size=[0.1])])
>>> [j.name for j in arm.joints], len(arm.geoms)
(['shoulder'], 1)
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import Node, TypedElement
from mjcf_model.keywords import JOINT_TYPES, LIMITED
from mjcf_model.nodes.geom import Camera, Geom, Light, Oriented, Site
from mjcf_model.values import (
    Floats,
    float_key,
    one_of,
    to_bool,
    to_float,
    to_floats,
    to_int,
    to_str,
    to_vec1to2,
    to_vec1to5,
    to_vec2,
    to_vec3,
    to_vec6,
)

__all__ = [
    "Attach",
    "Body",
    "Frame",
    "FreeJoint",
    "Inertial",
    "Joint",
    "Replicate",
    "TreeViews",
    "Worldbody",
]


class TreeViews:
    """Typed views of the children of ``worldbody``, ``body``, ``frame`` and ``replicate``.

    Each view lists the direct children of one type, in document order; elements
    inside a nested ``<frame>`` or ``<replicate>`` belong to that child.
    """

    __slots__ = ()
    children: tuple[Node, ...]

    @property
    def bodies(self) -> tuple[Body, ...]:
        """The child bodies."""
        return tuple(c for c in self.children if isinstance(c, Body))

    @property
    def joints(self) -> tuple[Joint | FreeJoint, ...]:
        """The joints, free joints included."""
        return tuple(c for c in self.children if isinstance(c, (Joint, FreeJoint)))

    @property
    def geoms(self) -> tuple[Geom, ...]:
        """The geoms."""
        return tuple(c for c in self.children if isinstance(c, Geom))

    @property
    def sites(self) -> tuple[Site, ...]:
        """The sites."""
        return tuple(c for c in self.children if isinstance(c, Site))

    @property
    def cameras(self) -> tuple[Camera, ...]:
        """The cameras."""
        return tuple(c for c in self.children if isinstance(c, Camera))

    @property
    def lights(self) -> tuple[Light, ...]:
        """The lights."""
        return tuple(c for c in self.children if isinstance(c, Light))

    @property
    def frames(self) -> tuple[Frame, ...]:
        """The frames."""
        return tuple(c for c in self.children if isinstance(c, Frame))


@attrs.frozen(kw_only=True, repr=False)
class Inertial(Oriented):
    """Mass and inertia of a body."""

    tag: ClassVar[str] = "inertial"
    #: Diagonal of the inertia matrix in the inertial frame.
    diaginertia: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Full inertia matrix (ixx iyy izz ixy ixz iyz).
    fullinertia: Floats | None = attrs.field(default=None, converter=to_vec6)
    #: Mass.
    mass: float | None = attrs.field(default=None, converter=to_float, eq=float_key)


@attrs.frozen(kw_only=True, repr=False)
class Joint(TypedElement):
    """A joint: a degree of freedom between a body and its parent."""

    tag: ClassVar[str] = "joint"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = attrs.field(default=None, converter=to_str, metadata={"xml": "class"})
    #: Element type keyword.
    type: str | None = attrs.field(default=None, converter=to_str, validator=one_of(JOINT_TYPES))
    #: Position (x, y, z) in the parent frame, in length units.
    pos: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Whether the total actuator force is clamped: ``true``, ``false`` or ``auto``.
    actuatorfrclimited: str | None = attrs.field(
        default=None, converter=to_str, validator=one_of(LIMITED)
    )
    #: Range of the total actuator force.
    actuatorfrcrange: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Whether gravity compensation counts as actuator force.
    actuatorgravcomp: bool | None = attrs.field(default=None, converter=to_bool)
    #: Armature inertia added to the degree of freedom.
    armature: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Rotation or translation axis.
    axis: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Damping (coefficients of a polynomial in MuJoCo 4).
    damping: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Dry friction loss.
    frictionloss: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Integer group, used for visualization filters and by convention.
    group: int | None = attrs.field(default=None, converter=to_int)
    #: Whether limits apply: ``true``, ``false`` or ``auto``.
    limited: str | None = attrs.field(default=None, converter=to_str, validator=one_of(LIMITED))
    #: Distance at which contacts (or limits) become active.
    margin: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Lower and upper limits.
    range: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Reference position or angle of the joint.
    ref: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Solver impedance parameters of the friction constraint.
    solimpfriction: Floats | None = attrs.field(default=None, converter=to_vec1to5)
    #: Solver impedance parameters of the limit constraint.
    solimplimit: Floats | None = attrs.field(default=None, converter=to_vec1to5)
    #: Solver reference parameters of the friction constraint.
    solreffriction: Floats | None = attrs.field(default=None, converter=to_vec1to2)
    #: Solver reference parameters of the limit constraint.
    solreflimit: Floats | None = attrs.field(default=None, converter=to_vec1to2)
    #: Spring-damper given as time constant and damping ratio.
    springdamper: Floats | None = attrs.field(default=None, converter=to_vec2)
    #: Joint position at which the spring force is zero.
    springref: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Yield threshold of the spring.
    springyield: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Custom user data (numbers).
    user: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class FreeJoint(TypedElement):
    """A free joint: six degrees of freedom."""

    tag: ClassVar[str] = "freejoint"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Whether the free joint's body frame is aligned with its inertia frame.
    align: str | None = attrs.field(default=None, converter=to_str)
    #: Integer group, used for visualization filters and by convention.
    group: int | None = attrs.field(default=None, converter=to_int)


@attrs.frozen(kw_only=True, repr=False)
class Attach(TypedElement):
    """Attaches a body of a model asset here."""

    tag: ClassVar[str] = "attach"
    #: Name of the body.
    body: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the frame to attach.
    frame: str | None = attrs.field(default=None, converter=to_str)
    #: Name of the model asset.
    model: str | None = attrs.field(default=None, converter=to_str)
    #: Prefix added to the names of the attached elements.
    prefix: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Worldbody(TypedElement, TreeViews):
    """The world body: root of the kinematic tree."""

    tag: ClassVar[str] = "worldbody"


@attrs.frozen(kw_only=True, repr=False)
class Body(Oriented, TreeViews):
    """A rigid body."""

    tag: ClassVar[str] = "body"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class for all descendants that do not set their own ``class``.
    childclass: str | None = attrs.field(default=None, converter=to_str)
    #: Whether this static body may be fused into its parent.
    fuse: str | None = attrs.field(default=None, converter=to_str)
    #: Gravity compensation factor.
    gravcomp: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Whether this is a mocap body.
    mocap: bool | None = attrs.field(default=None, converter=to_bool)
    #: Simplification hint for the body.
    simple: str | None = attrs.field(default=None, converter=to_str)
    #: Sleep policy of the body's tree.
    sleep: str | None = attrs.field(default=None, converter=to_str)
    #: Custom user data (numbers).
    user: Floats | None = attrs.field(default=None, converter=to_floats)

    @property
    def inertial(self) -> Inertial | None:
        """The explicit inertial element, if there is one."""
        return self._first(Inertial)


@attrs.frozen(kw_only=True, repr=False)
class Frame(Oriented, TreeViews):
    """A coordinate frame that places its children; not a body."""

    tag: ClassVar[str] = "frame"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Default class for all descendants that do not set their own ``class``.
    childclass: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Replicate(TypedElement, TreeViews):
    """Repeats its children with an offset and rotation."""

    tag: ClassVar[str] = "replicate"
    #: Orientation as Euler angles in the compiler's ``eulerseq``.
    euler: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Number of repetitions or grid points.
    count: int | None = attrs.field(default=None, converter=to_int)
    #: Translation between consecutive copies.
    offset: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Separator between a name and the copy index.
    sep: str | None = attrs.field(default=None, converter=to_str)
