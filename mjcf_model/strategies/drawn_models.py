"""Strategies for bodies and whole models whose names are unique and references resolve."""

from __future__ import annotations

from typing import Any

import attrs
from hypothesis import strategies as st

from mjcf_model.nodes import (
    Asset,
    Body,
    Camera,
    Compiler,
    Custom,
    Default,
    FreeJoint,
    Geom,
    Inertial,
    Light,
    Mujoco,
    Numeric,
    Replicate,
    Site,
    Texture,
    Worldbody,
)
from mjcf_model.nodes import Frame as FrameNode
from mjcf_model.nodes import Joint as JointNode
from mjcf_model.nodes.base import Node
from mjcf_model.strategies.drawn_elements import geoms, joints, materials, meshes, sites
from mjcf_model.strategies.primitives import (
    _Draw,
    _euler,
    _length,
    _mass,
    _optional,
    _position,
    _rgba,
    _size,
    _unit_quat,
    _vec,
    comments,
    names,
)
from mjcf_model.strategies.registry import _Registry
from mjcf_model.strategies.sections import sections
from mjcf_model.tree.traversal import map_tree

__all__ = [
    "bodies",
    "models",
]


def _maybe_comment(draw: _Draw[Any], children: list[Node]) -> list[Node]:
    if draw(st.integers(0, 4)) == 0:
        children.insert(draw(st.integers(0, len(children))), draw(comments()))
    return children


def _chance(draw: _Draw[Any], one_in: int) -> bool:
    """True once in ``one_in`` draws (shrinking towards False)."""
    drawn: int = draw(st.integers(0, one_in - 1))
    return drawn == one_in - 1


def _orientation(draw: _Draw[Any], reg: _Registry) -> dict[str, Any]:
    """No orientation, a quaternion, or Euler angles in the model's angle units."""
    kind = draw(st.sampled_from(["none", "quat", "euler"]))
    if kind == "quat":
        return {"quat": draw(_unit_quat())}
    if kind == "euler":
        return {"euler": draw(_euler(reg.angle))}
    return {}


def _geom(draw: _Draw[Any], reg: _Registry, namespace: str = "geom") -> Geom:
    """A primitive or mesh geom, maybe named, maybe of a default class."""
    named = draw(st.booleans())
    name = reg.names(namespace) if named else None
    material = draw(_optional(st.sampled_from(reg.materials))) if reg.materials else None
    geom: Geom = draw(geoms(name=name, material=material))
    if reg.meshes and _chance(draw, 3):
        geom = attrs.evolve(geom, type="mesh", size=None, mesh=draw(st.sampled_from(reg.meshes)))
    if reg.classes and draw(st.booleans()):
        geom = attrs.evolve(geom, dclass=draw(st.sampled_from(reg.classes)))
    if name and namespace == "geom":
        reg.geoms.append(name)
        if geom.type in {"sphere", "cylinder"}:
            reg.wrapping_geoms.append(name)
    return geom


def _site(draw: _Draw[Any], reg: _Registry, namespace: str = "site") -> Site:
    name = reg.names(namespace)
    if namespace == "site":
        reg.sites.append(name)
    site: Site = draw(sites(name=name))
    return site


def _joints(draw: _Draw[Any], reg: _Registry, top: bool) -> list[Node]:
    """A free joint (top-level bodies only), or up to two joints (a ball joint alone)."""
    if top and draw(st.booleans()):
        return [FreeJoint(name=reg.names("joint"))]
    found: list[Node] = []
    for index in range(draw(st.integers(0, 2))):
        # MuJoCo allows no rotation after a ball joint: a ball joint stands alone.
        joint = draw(joints(name=reg.names("joint"), scalar=index > 0, angle=reg.angle))
        found.append(joint)
        if joint.type == "ball":
            break
        reg.scalar_joints.append(str(joint.name))
    return found


def _inertial(draw: _Draw[Any]) -> Inertial:
    """Explicit inertia: principal moments that satisfy the triangle inequality."""
    moment = draw(_size(-4.0, 0.0))
    return Inertial(
        pos=draw(_vec(3, -0.1, 0.1)),
        mass=draw(_mass()),
        diaginertia=draw(st.tuples(*[_length(moment, 1.5 * moment) for _ in range(3)])),
    )


def _tracking(draw: _Draw[Any], reg: _Registry) -> dict[str, Any]:
    """Fixed, or aimed at a body drawn so far (its centre or its centre of mass)."""
    mode = draw(st.sampled_from([None, "targetbody", "targetbodycom"]))
    if mode is None:
        return {}
    return {"mode": mode, "target": draw(st.sampled_from(reg.bodies))}


def _frame(draw: _Draw[Any], reg: _Registry, depth: int, nesting: int = 1) -> FrameNode:
    """A frame placing a geom, a site, a body subtree, or another frame."""
    kinds = ["geom", "site", "body"] + (["frame"] if nesting else [])
    children: list[Node] = []
    for kind in draw(st.lists(st.sampled_from(kinds), min_size=1, max_size=2)):
        if kind == "geom":
            children.append(_geom(draw, reg))
        elif kind == "site":
            children.append(_site(draw, reg))
        elif kind == "body":
            children.append(draw(bodies(depth=max(depth - 1, 0), registry=reg)))
        else:
            children.append(_frame(draw, reg, depth, nesting - 1))
    childclass = draw(_optional(st.sampled_from(reg.classes))) if reg.classes else None
    return FrameNode(
        pos=draw(_optional(_position())),
        childclass=childclass,
        children=children,
        **_orientation(draw, reg),
    )


def _replicate(draw: _Draw[Any], reg: _Registry) -> Replicate:
    """Copies of a small jointless subtree; MuJoCo suffixes each copy's names with its index."""
    reg.replicates = True
    if draw(st.booleans()):
        inner: list[Node] = [_geom(draw, reg, "rgeom")]
        if draw(st.booleans()):
            inner.append(Body(name=reg.names("rbody"), children=[_geom(draw, reg, "rgeom")]))
        content: Node = Body(
            name=reg.names("rbody"),
            pos=draw(_vec(3, -0.2, 0.2)),
            children=[*inner, _site(draw, reg, "rsite")],
        )
    else:
        content = _geom(draw, reg, "rgeom")
    return Replicate(
        count=draw(st.integers(2, 4)),
        offset=draw(_vec(3, -0.5, 0.5)),
        euler=draw(_optional(_euler(reg.angle))),
        children=[content],
    )


def _separated_copies(draw: _Draw[Any], world: Worldbody) -> Worldbody:
    """``world`` whose replicate names its copies with a separator before the index.

    Without one, MuJoCo suffixes the digits straight onto names: a copy of
    ``joint1`` would be ``joint11``, and MuJoCo also copies each element that
    refers to a name whose suffixed form exists (a sensor of ``joint1`` when
    ``joint11`` is declared). Names here end in digits, so from ten names in a
    namespace on, the copies need a separator.
    """
    sep = draw(st.sampled_from(["-", "_"]))

    def separated(node: Node) -> Node:
        return attrs.evolve(node, sep=sep) if isinstance(node, Replicate) else node

    mapped = map_tree(separated, world)
    assert isinstance(mapped, Worldbody)
    return mapped


@st.composite
def bodies(
    draw: _Draw[Any], depth: int = 2, registry: _Registry | None = None, top: bool = False
) -> Body:
    """A body subtree: every body has a geom, so moving bodies have mass.

    Bodies hold joints (a free joint at the top), geoms (meshes among them once
    the model has meshes), sites, frames, replicated copies, and cameras and
    lights that may track a body. A top-level body may be a mocap body instead.

    Examples:
        >>> len(bodies().example().geoms) >= 1
        True

    """
    reg = registry if registry is not None else _Registry()
    name = reg.names("body")
    reg.bodies.append(name)
    if top and _chance(draw, 4):
        reg.mocap_bodies.append(name)
        geom = attrs.evolve(_geom(draw, reg), contype=0, conaffinity=0)
        return Body(name=name, mocap=True, pos=draw(_position()), children=[geom])
    children = _joints(draw, reg, top)
    if _chance(draw, 4):
        children.append(_inertial(draw))
    children.extend(_geom(draw, reg) for _ in range(draw(st.integers(1, 3))))
    children.extend(_site(draw, reg) for _ in range(draw(st.integers(0, 2))))
    if _chance(draw, 3):
        children.insert(draw(st.integers(0, len(children))), _frame(draw, reg, depth))
    # one per model: with two, MuJoCo copies the sections' elements into clashing names
    if not reg.replicates and _chance(draw, 4):
        children.append(_replicate(draw, reg))
    if _chance(draw, 4):
        children.append(
            Camera(
                name=reg.names("camera"), pos=draw(_position()), fovy=45.0, **_tracking(draw, reg)
            )
        )
    if _chance(draw, 5):
        light = Light(name=reg.names("light"), pos=draw(_position()), dir=(0.0, 0.0, -1.0))
        children.append(attrs.evolve(light, **_tracking(draw, reg)))
    if depth > 0:
        for _ in range(draw(st.integers(0, 2))):
            children.append(draw(bodies(depth=depth - 1, registry=reg)))
    childclass = None
    if reg.classes and _chance(draw, 4):
        childclass = draw(st.sampled_from(reg.classes))
    return Body(
        name=name,
        childclass=childclass,
        pos=draw(_position()),
        children=_maybe_comment(draw, children),
        **_orientation(draw, reg),
    )


def _defaults(draw: _Draw[Any], reg: _Registry) -> Default:
    """Main defaults and up to three classes, each under main or under an earlier class."""
    parents: list[int | None] = []
    settings: list[list[Node]] = []
    for index in range(draw(st.integers(0, 3))):
        reg.classes.append(reg.names("class"))
        parents.append(draw(_optional(st.integers(0, index - 1))) if index else None)
        own: list[Node] = []
        if draw(st.integers(0, 3)):
            own.append(Geom(rgba=draw(_rgba()), density=draw(_length(100.0, 2000.0))))
        if draw(st.booleans()):
            own.append(JointNode(armature=draw(_length(0.0, 0.5))))
        if _chance(draw, 3):
            own.append(Site(size=(draw(_size(-3.0, -1.0)),), rgba=draw(_rgba())))
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
    for _ in range(draw(st.integers(0, 2))):
        name = reg.names("mesh")
        children.append(draw(meshes(name=name)))
        reg.meshes.append(name)
    return Asset(children=children)


@st.composite
def models(draw: _Draw[Any], max_trees: int = 3) -> Mujoco:
    """A whole model that MuJoCo compiles, with names unique per namespace.

    Examples:
        >>> import mujoco
        >>> from mjcf_model import dumps
        >>> model = models().example()
        >>> mujoco.MjModel.from_xml_string(dumps(model)).nbody >= 2
        True

    """
    reg = _Registry(angle=draw(st.sampled_from(["degree", "radian"])))
    head: list[Node] = []
    if reg.angle == "radian" or draw(st.booleans()):
        head.append(Compiler(angle=reg.angle))
    defaults = _defaults(draw, reg)
    assets = _assets(draw, reg)
    trees: list[Node] = [
        draw(bodies(registry=reg, top=True)) for _ in range(draw(st.integers(1, max_trees)))
    ]
    world = Worldbody(children=_maybe_comment(draw, trees))
    after = sections(draw, reg, world)
    if reg.names.most() >= 10:
        world = _separated_copies(draw, world)
    parts: list[Node] = [*head, defaults, assets, world, *after]
    if draw(st.booleans()):
        parts.append(Custom(children=[Numeric(name=reg.names("numeric"), data=draw(_vec(2)))]))
    return Mujoco(model=draw(_optional(names())), children=_maybe_comment(draw, parts))
