"""Strategies for bodies and whole models whose names are unique and references resolve."""

from __future__ import annotations

import itertools
from typing import Any

import attrs
from hypothesis import strategies as st

from mjcf_model.nodes import (
    Actuator,
    Asset,
    Body,
    Camera,
    Contact,
    Custom,
    Default,
    Equality,
    EqualityJoint,
    Exclude,
    Fixed,
    FramePos,
    FreeJoint,
    Geom,
    JointPos,
    Key,
    Keyframe,
    Light,
    Motor,
    Mujoco,
    Numeric,
    Pair,
    Position,
    Sensor,
    Tendon,
    TendonJoint,
    Texture,
    Touch,
    Velocity,
    Worldbody,
)
from mjcf_model.nodes import Frame as FrameNode
from mjcf_model.nodes import Joint as JointNode
from mjcf_model.nodes.base import Node
from mjcf_model.strategies.elements import geoms, joints, materials, sites
from mjcf_model.strategies.primitives import (
    _Draw,
    _length,
    _rgba,
    _unit_quat,
    _vec,
    comments,
    names,
)

__all__ = [
    "bodies",
    "models",
]


class _Names:
    """Hands out names unique per namespace (``body0``, ``geom3``...)."""

    def __init__(self) -> None:
        self.counters: dict[str, itertools.count[int]] = {}

    def __call__(self, namespace: str) -> str:
        counter = self.counters.setdefault(namespace, itertools.count())
        return f"{namespace}{next(counter)}"


@attrs.define
class _Registry:
    """What a model being drawn declares, for the sections that refer to it."""

    names: _Names = attrs.field(factory=_Names)
    scalar_joints: list[str] = attrs.field(factory=list)
    joint_sizes: list[int] = attrs.field(factory=list)
    bodies: list[str] = attrs.field(factory=list)
    geoms: list[str] = attrs.field(factory=list)
    sites: list[str] = attrs.field(factory=list)
    materials: list[str] = attrs.field(factory=list)
    classes: list[str] = attrs.field(factory=list)


def _maybe_comment(draw: _Draw[Any], children: list[Node]) -> list[Node]:
    if draw(st.integers(0, 4)) == 0:
        children.insert(draw(st.integers(0, len(children))), draw(comments()))
    return children


@st.composite
def bodies(
    draw: _Draw[Any], depth: int = 2, registry: _Registry | None = None, top: bool = False
) -> Body:
    """A body subtree: every body has a geom, so moving bodies have mass.

    Example:
        >>> len(bodies().example().geoms) >= 1
        True

    """
    reg = registry if registry is not None else _Registry()
    name = reg.names("body")
    reg.bodies.append(name)
    children: list[Node] = []
    if top and draw(st.booleans()):
        children.append(FreeJoint(name=reg.names("joint")))
        reg.joint_sizes.append(7)
    else:
        for index in range(draw(st.integers(0, 2))):
            # MuJoCo allows no rotation after a ball joint: a ball joint stands alone.
            joint = draw(joints(name=reg.names("joint"), scalar=index > 0))
            children.append(joint)
            reg.joint_sizes.append(4 if joint.type == "ball" else 1)
            if joint.type == "ball":
                break
            reg.scalar_joints.append(str(joint.name))
    for _ in range(draw(st.integers(1, 3))):
        geom_name = reg.names("geom") if draw(st.booleans()) else None
        material = draw(st.none() | st.sampled_from(reg.materials)) if reg.materials else None
        geom = draw(geoms(name=geom_name, material=material))
        if reg.classes and draw(st.booleans()):
            geom = attrs.evolve(geom, dclass=draw(st.sampled_from(reg.classes)))
        children.append(geom)
        if geom_name:
            reg.geoms.append(geom_name)
    if draw(st.booleans()):
        site_name = reg.names("site")
        children.append(draw(sites(name=site_name)))
        reg.sites.append(site_name)
    if draw(st.integers(0, 3)) == 0:
        framed = draw(geoms(name=reg.names("geom")))
        reg.geoms.append(str(framed.name))
        frame = FrameNode(pos=draw(_vec(3)), children=[framed])
        children.insert(draw(st.integers(0, len(children))), frame)
    if draw(st.integers(0, 4)) == 0:
        children.append(Camera(name=reg.names("camera"), pos=draw(_vec(3)), fovy=45.0))
    if draw(st.integers(0, 5)) == 0:
        children.append(Light(name=reg.names("light"), pos=draw(_vec(3)), dir=(0.0, 0.0, -1.0)))
    if depth > 0:
        for _ in range(draw(st.integers(0, 2))):
            children.append(draw(bodies(depth=depth - 1, registry=reg)))
    childclass = None
    if reg.classes and draw(st.integers(0, 3)) == 0:
        childclass = draw(st.sampled_from(reg.classes))
    return Body(
        name=name,
        childclass=childclass,
        pos=draw(_vec(3)),
        quat=draw(st.none() | _unit_quat()),
        children=_maybe_comment(draw, children),
    )


def _defaults(draw: _Draw[Any], reg: _Registry) -> Default:
    """Main defaults and up to three classes, each under main or under an earlier class."""
    parents: list[int | None] = []
    settings: list[list[Node]] = []
    for index in range(draw(st.integers(0, 3))):
        reg.classes.append(reg.names("class"))
        parents.append(draw(st.none() | st.integers(0, index - 1)) if index else None)
        own: list[Node] = []
        if draw(st.integers(0, 3)):
            own.append(Geom(rgba=draw(_rgba()), density=draw(_length(100.0, 2000.0))))
        if draw(st.booleans()):
            own.append(JointNode(armature=draw(_length(0.0, 0.5))))
        settings.append(own)
    built: dict[int, Default] = {}
    for index in reversed(range(len(parents))):  # a class is built after the classes in it
        inner = [built[i] for i in range(index + 1, len(parents)) if parents[i] == index]
        built[index] = Default(dclass=reg.classes[index], children=[*settings[index], *inner])
    tops = [built[i] for i in range(len(parents)) if parents[i] is None]
    main: list[Node] = [JointNode(damping=(draw(_length(0.0, 1.0)),)), *tops]
    return Default(children=_maybe_comment(draw, main))


def _assets(draw: _Draw[Any], reg: _Registry) -> Asset:
    children: list[Node] = []
    for _ in range(draw(st.integers(0, 2))):
        texture = None
        if draw(st.booleans()):
            texture = reg.names("texture")
            children.append(
                Texture(
                    name=texture,
                    type="2d",
                    builtin="checker",
                    width=32,
                    height=32,
                    rgb1=draw(_vec(3, 0.0, 1.0)),
                    rgb2=draw(_vec(3, 0.0, 1.0)),
                )
            )
        name = reg.names("material")
        children.append(draw(materials(name=name, texture=texture)))
        reg.materials.append(name)
    return Asset(children=children)


@st.composite
def models(draw: _Draw[Any], max_trees: int = 3) -> Mujoco:
    """A whole model that MuJoCo compiles, with names unique per namespace.

    Example:
        >>> import mujoco
        >>> from serializers import dumps
        >>> model = models().example()
        >>> mujoco.MjModel.from_xml_string(dumps(model)).nbody >= 2
        True

    """
    reg = _Registry()
    defaults = _defaults(draw, reg)
    assets = _assets(draw, reg)
    trees: list[Node] = [
        draw(bodies(registry=reg, top=True)) for _ in range(draw(st.integers(1, max_trees)))
    ]
    world = Worldbody(children=_maybe_comment(draw, trees))
    sections: list[Node] = [defaults, assets, world]
    actuators: list[Node] = []
    for joint in reg.scalar_joints:
        kind = draw(st.sampled_from([None, Motor, Position, Velocity]))
        if kind is not None:
            actuators.append(kind(name=reg.names("actuator"), joint=joint, ctrlrange=(-1.0, 1.0)))
    sensors: list[Node] = [
        JointPos(name=reg.names("sensor"), joint=j) for j in reg.scalar_joints[:2]
    ]
    for site in reg.sites[:2]:
        sensors.append(FramePos(name=reg.names("sensor"), objtype="site", objname=site))
        sensors.append(Touch(name=reg.names("sensor"), site=site))
    if actuators:
        sections.append(Actuator(children=actuators))
    if sensors:
        sections.append(Sensor(children=sensors))
    if len(reg.scalar_joints) >= 2:
        first, second = reg.scalar_joints[:2]
        parts = [TendonJoint(joint=first, coef=1.0), TendonJoint(joint=second, coef=-0.5)]
        sections.append(Tendon(children=[Fixed(name=reg.names("tendon"), children=parts)]))
        sections.append(
            Equality(
                children=[EqualityJoint(name=reg.names("equality"), joint1=first, joint2=second)]
            )
        )
    contact: list[Node] = []
    if len(reg.bodies) >= 2:
        contact.append(
            Exclude(name=reg.names("exclude"), body1=reg.bodies[0], body2=reg.bodies[-1])
        )
    if len(reg.geoms) >= 2:
        contact.append(Pair(name=reg.names("pair"), geom1=reg.geoms[0], geom2=reg.geoms[-1]))
    if contact:
        sections.append(Contact(children=contact))
    nq = sum(reg.joint_sizes)
    if nq and draw(st.booleans()):
        qpos = None if 7 in reg.joint_sizes or 4 in reg.joint_sizes else draw(_vec(nq))
        key = Key(
            name=reg.names("key"),
            time=draw(_length(0.0, 1.0)),
            qpos=qpos,
            ctrl=tuple(0.0 for _ in actuators) or None,
        )
        sections.append(Keyframe(children=[key]))
    if draw(st.booleans()):
        sections.append(Custom(children=[Numeric(name=reg.names("numeric"), data=draw(_vec(2)))]))
    return Mujoco(model=draw(st.none() | names()), children=_maybe_comment(draw, sections))
