"""The kinematic tree: world body, bodies, frames, replicates, inertials, joints and attachments.

>>> from mjcf_model.nodes.geom import Geom
>>> arm = Body(name="arm", pos=[0, 0, 1], children=[Joint(name="shoulder"), Geom(size=[0.1])])
>>> [j.name for j in arm.joints], len(arm.geoms)
(['shoulder'], 1)
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import Node, TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import (
    boolean,
    integer,
    keyword,
    number,
    numbers,
    text,
    vec1to2,
    vec1to5,
    vec2,
    vec3,
    vec6,
)
from mjcf_model.nodes.geom import Camera, Geom, Light, Oriented, Site
from mjcf_model.schema.keywords import JOINT_TYPES, LIMITED
from mjcf_model.values import Floats

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


@node
class Inertial(Oriented):
    """Mass and inertia of a body."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/inertial",)
    #: Diagonal of the inertia matrix in the inertial frame.
    diaginertia: Floats | None = vec3()
    #: Full inertia matrix (ixx iyy izz ixy ixz iyz).
    fullinertia: Floats | None = vec6()
    #: Mass.
    mass: float | None = number()


@node
class Joint(TypedElement):
    """A joint: a degree of freedom between a body and its parent."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/joint", "default/joint")
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")
    #: Element type keyword.
    type: str | None = keyword(JOINT_TYPES)
    #: Position (x, y, z) in the parent frame, in length units.
    pos: Floats | None = vec3()
    #: Whether the total actuator force is clamped: ``true``, ``false`` or ``auto``.
    actuatorfrclimited: str | None = keyword(LIMITED)
    #: Range of the total actuator force.
    actuatorfrcrange: Floats | None = vec2()
    #: Whether gravity compensation counts as actuator force.
    actuatorgravcomp: bool | None = boolean()
    #: Armature inertia added to the degree of freedom.
    armature: float | None = number()
    #: Rotation or translation axis.
    axis: Floats | None = vec3()
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
    #: Reference position or angle of the joint.
    ref: float | None = number()
    #: Solver impedance parameters of the friction constraint.
    solimpfriction: Floats | None = vec1to5()
    #: Solver impedance parameters of the limit constraint.
    solimplimit: Floats | None = vec1to5()
    #: Solver reference parameters of the friction constraint.
    solreffriction: Floats | None = vec1to2()
    #: Solver reference parameters of the limit constraint.
    solreflimit: Floats | None = vec1to2()
    #: Spring-damper given as time constant and damping ratio.
    springdamper: Floats | None = vec2()
    #: Joint position at which the spring force is zero.
    springref: float | None = number()
    #: Yield threshold of the spring.
    springyield: float | None = number()
    #: Spring stiffness (coefficients of a polynomial in MuJoCo 4).
    stiffness: Floats | None = numbers()
    #: Custom user data (numbers).
    user: Floats | None = numbers()


@node
class FreeJoint(TypedElement):
    """A free joint: six degrees of freedom."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/freejoint",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Whether the free joint's body frame is aligned with its inertia frame.
    align: str | None = text()
    #: Integer group, used for visualization filters and by convention.
    group: int | None = integer()


@node
class Attach(TypedElement):
    """Attaches a body of a model asset here."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/attach",)
    #: Name of the body.
    body: str | None = text()
    #: Name of the frame to attach.
    frame: str | None = text()
    #: Name of the model asset.
    model: str | None = text()
    #: Prefix added to the names of the attached elements.
    prefix: str | None = text()


@node
class Worldbody(TypedElement, TreeViews):
    """The world body: root of the kinematic tree."""

    schema_keys: ClassVar[tuple[str, ...]] = ("worldbody",)


@node
class Body(Oriented, TreeViews):
    """A rigid body."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class for all descendants that do not set their own ``class``.
    childclass: str | None = text()
    #: Whether this static body may be fused into its parent.
    fuse: str | None = text()
    #: Gravity compensation factor.
    gravcomp: float | None = number()
    #: Whether this is a mocap body.
    mocap: bool | None = boolean()
    #: Simplification hint for the body.
    simple: str | None = text()
    #: Sleep policy of the body's tree.
    sleep: str | None = text()
    #: Custom user data (numbers).
    user: Floats | None = numbers()

    @property
    def inertial(self) -> Inertial | None:
        """The explicit inertial element, if there is one."""
        return self._first(Inertial)


@node
class Frame(Oriented, TreeViews):
    """A coordinate frame that places its children; not a body."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/frame",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Default class for all descendants that do not set their own ``class``.
    childclass: str | None = text()


@node
class Replicate(TypedElement, TreeViews):
    """Repeats its children with an offset and rotation."""

    schema_keys: ClassVar[tuple[str, ...]] = ("body/replicate",)
    #: Orientation as Euler angles in the compiler's ``eulerseq``.
    euler: Floats | None = vec3()
    #: Number of repetitions or grid points.
    count: int | None = integer()
    #: Translation between consecutive copies.
    offset: Floats | None = vec3()
    #: Separator between a name and the copy index.
    sep: str | None = text()
