"""Strategies for the sections that refer to a drawn tree: tendons, actuators, equality, keys."""

from __future__ import annotations

import math
from typing import Any

from hypothesis import strategies as st

from mjcf_model.nodes import (
    Actuator,
    Adhesion,
    Body,
    Connect,
    Contact,
    Equality,
    EqualityJoint,
    EqualityTendon,
    Exclude,
    Fixed,
    FramePos,
    FreeJoint,
    General,
    JointPos,
    Key,
    Keyframe,
    Motor,
    Pair,
    Position,
    Sensor,
    Spatial,
    Tendon,
    TendonGeom,
    TendonJoint,
    TendonPos,
    TendonSite,
    Touch,
    Velocity,
    Weld,
    Worldbody,
)
from mjcf_model.nodes import Frame as FrameNode
from mjcf_model.nodes import Joint as JointNode
from mjcf_model.nodes.base import Node
from mjcf_model.strategies.primitives import (
    _Draw,
    _length,
    _number,
    _optional,
    _position,
    _unit_quat,
    _vec,
)
from mjcf_model.strategies.registry import _Registry
from mjcf_model.values import Floats

__all__ = ["sections"]


#: A weld's relative pose: a position then a unit quaternion, built once.
_RELPOSE = st.tuples(_position(), _unit_quat()).map(lambda p: (*p[0], *p[1]))

#: The sizes of a joint's entries in ``qpos`` and ``qvel``.
_STATE_SIZES = {"free": (7, 6), "ball": (4, 3), "hinge": (1, 1), "slide": (1, 1)}


def _pick(draw: _Draw[Any], names: list[str], count: int = 1) -> list[str]:
    """``count`` distinct names, or none when there are fewer."""
    if count == 0 or len(names) < count:
        return []
    picked: list[str] = draw(
        st.lists(st.sampled_from(names), min_size=count, max_size=count, unique=True)
    )
    return picked


def _tendons(draw: _Draw[Any], reg: _Registry) -> list[Fixed | Spatial]:
    """Fixed tendons over scalar joints, spatial ones between sites, maybe around a geom."""
    found: list[Fixed | Spatial] = []
    joints = _pick(draw, reg.scalar_joints, draw(st.integers(1, 3)))
    if joints and draw(st.integers(0, 3)):
        parts = [TendonJoint(joint=j, coef=draw(_number(-2.0, 2.0))) for j in joints]
        found.append(Fixed(name=reg.names("tendon"), children=parts))
    for _ in range(draw(st.integers(0, 2))):
        ends = _pick(draw, reg.sites, 2)
        if not ends:
            break
        path: list[Node] = [TendonSite(site=ends[0])]
        if reg.wrapping_geoms and draw(st.booleans()):
            side = draw(_optional(st.sampled_from(reg.sites)))
            path.append(TendonGeom(geom=draw(st.sampled_from(reg.wrapping_geoms)), sidesite=side))
        path.append(TendonSite(site=ends[1]))
        found.append(
            Spatial(name=reg.names("tendon"), width=draw(_length(0.001, 0.02)), children=path)
        )
    reg.tendons.extend(str(tendon.name) for tendon in found)
    return found


def _actuators(draw: _Draw[Any], reg: _Registry) -> tuple[list[Node], int]:
    """Actuators of every transmission kind, and how many activations they add."""
    found: list[Node] = []
    activations = 0
    for joint in reg.scalar_joints:
        kind = draw(st.sampled_from([None, Motor, Position, Velocity, General]))
        if kind is General:
            # a first-order filter: one activation state per actuator
            found.append(
                General(
                    name=reg.names("actuator"),
                    jointinparent=joint,
                    dyntype="filter",
                    dynprm=(draw(_length(0.01, 1.0)),),
                    ctrlrange=(-1.0, 1.0),
                )
            )
            activations += 1
        elif kind is not None:
            found.append(kind(name=reg.names("actuator"), joint=joint, ctrlrange=(-1.0, 1.0)))
    for tendon in _pick(draw, reg.tendons, draw(st.integers(0, len(reg.tendons)))):
        found.append(
            Motor(name=reg.names("actuator"), tendon=tendon, gear=(draw(_number(-5.0, 5.0)),))
        )
    for site in _pick(draw, reg.sites, draw(st.integers(0, min(2, len(reg.sites))))):
        refsite = draw(_optional(st.sampled_from(reg.sites)))
        gear = draw(_vec(6, -2.0, 2.0))
        found.append(Motor(name=reg.names("actuator"), site=site, refsite=refsite, gear=gear))
    moving = [body for body in reg.bodies if body not in reg.mocap_bodies]
    if moving and draw(st.booleans()):
        body = draw(st.sampled_from(moving))
        found.append(
            Adhesion(
                name=reg.names("actuator"),
                body=body,
                ctrlrange=(0.0, 1.0),
                gain=draw(_length(0.1, 10.0)),
            )
        )
    return found, activations


def _polycoef(draw: _Draw[Any]) -> Floats:
    coefficients: Floats = draw(_vec(5, -1.0, 1.0))
    return coefficients


def _equalities(draw: _Draw[Any], reg: _Registry) -> list[Node]:
    """Connect and weld (between bodies or sites), joint and tendon couplings."""
    found: list[Node] = []
    kinds = draw(st.lists(st.sampled_from(["connect", "weld", "joint", "tendon"]), max_size=4))
    for kind in kinds:
        name = reg.names("equality")
        on_sites = draw(st.booleans())
        if kind in {"connect", "weld"} and on_sites and len(reg.sites) >= 2:
            site1, site2 = _pick(draw, reg.sites, 2)
            element: Node = (Connect if kind == "connect" else Weld)(
                name=name, site1=site1, site2=site2
            )
        elif kind == "connect" and len(reg.bodies) >= 2:
            body1, body2 = _pick(draw, reg.bodies, 2)
            element = Connect(name=name, body1=body1, body2=body2, anchor=draw(_vec(3)))
        elif kind == "weld":
            welded = _pick(draw, reg.bodies, 2) or reg.bodies[:1]
            other: str | None = welded[1] if len(welded) > 1 else None
            relpose = draw(_optional(_RELPOSE))
            element = Weld(
                name=name,
                body1=welded[0],
                body2=draw(_optional(st.just(other))),
                relpose=relpose,
                anchor=draw(_optional(_vec(3))),
                torquescale=draw(_optional(_length(0.1, 10.0))),
            )
        elif kind == "joint" and reg.scalar_joints:
            pair = _pick(draw, reg.scalar_joints, 2) or reg.scalar_joints[:1]
            second = pair[1] if len(pair) > 1 and draw(st.booleans()) else None
            element = EqualityJoint(
                name=name, joint1=pair[0], joint2=second, polycoef=_polycoef(draw)
            )
        elif kind == "tendon" and reg.tendons:
            pair = _pick(draw, reg.tendons, 2) or reg.tendons[:1]
            second = pair[1] if len(pair) > 1 and draw(st.booleans()) else None
            element = EqualityTendon(
                name=name, tendon1=pair[0], tendon2=second, polycoef=_polycoef(draw)
            )
        else:
            continue
        found.append(element)
    return found


def _sensors(reg: _Registry) -> list[Node]:
    found: list[Node] = [JointPos(name=reg.names("sensor"), joint=j) for j in reg.scalar_joints[:2]]
    for site in reg.sites[:2]:
        found.append(FramePos(name=reg.names("sensor"), objtype="site", objname=site))
        found.append(Touch(name=reg.names("sensor"), site=site))
    found.extend(TendonPos(name=reg.names("sensor"), tendon=t) for t in reg.tendons[:1])
    return found


def _contact(reg: _Registry) -> list[Node]:
    found: list[Node] = []
    if len(reg.bodies) >= 2:
        found.append(Exclude(name=reg.names("exclude"), body1=reg.bodies[0], body2=reg.bodies[-1]))
    if len(reg.geoms) >= 2:
        found.append(Pair(name=reg.names("pair"), geom1=reg.geoms[0], geom2=reg.geoms[-1]))
    return found


def _joint_types(world: Worldbody) -> list[str]:
    """The types of the tree's joints in MuJoCo's order: bodies depth first, in document order."""
    found: list[str] = []

    def visit(children: tuple[Node, ...]) -> None:
        for child in children:
            if isinstance(child, Body):
                for joint in child.children:
                    if isinstance(joint, FreeJoint):
                        found.append("free")
                    elif isinstance(joint, JointNode):
                        found.append(joint.type or "hinge")
                visit(child.children)
            elif isinstance(child, FrameNode):
                visit(child.children)

    visit(world.children)
    return found


def _unit(quat: Floats) -> Floats:
    norm = math.sqrt(sum(v * v for v in quat))
    return tuple(v / norm for v in quat)


def _qpos(draw: _Draw[Any], joint_type: str) -> Floats:
    if joint_type == "free":
        return (*draw(_position()), *_unit(draw(_unit_quat())))
    if joint_type == "ball":
        return _unit(draw(_unit_quat()))
    return (draw(_number(-math.pi, math.pi)),)


def _mocap_poses(draw: _Draw[Any], mocap: int) -> dict[str, Any]:
    """Positions and orientations of ``mocap`` mocap bodies, or nothing."""
    if not mocap or not draw(st.booleans()):
        return {}
    positions = [draw(_position()) for _ in range(mocap)]
    quats = [_unit(draw(_unit_quat())) for _ in range(mocap)]
    return {
        "mpos": tuple(v for p in positions for v in p),
        "mquat": tuple(v for q in quats for v in q),
    }


def _key(draw: _Draw[Any], reg: _Registry, world: Worldbody, nu: int, na: int) -> Key:
    """A key whose every state vector, when written, has the model's size."""
    types = _joint_types(world)
    nv = sum(_STATE_SIZES[t][1] for t in types)

    def maybe(strategy: st.SearchStrategy[Floats], size: int) -> Floats | None:
        # three times in four: a key is where drawn states are checked
        return draw(strategy) if size and draw(st.integers(0, 3)) else None

    return Key(
        name=reg.names("key"),
        time=draw(_optional(_length(0.0, 10.0))),
        qpos=tuple(v for t in types for v in _qpos(draw, t))
        if types and draw(st.integers(0, 3))
        else None,
        qvel=maybe(_vec(nv), nv),
        ctrl=maybe(_vec(nu, 0.0, 1.0), nu),
        act=maybe(_vec(na, -1.0, 1.0), na),
        **_mocap_poses(draw, len(reg.mocap_bodies)),
    )


def sections(draw: _Draw[Any], reg: _Registry, world: Worldbody) -> list[Node]:
    """The sections after ``<worldbody>`` for what ``reg`` says the tree declares."""
    found: list[Node] = []
    tendons = _tendons(draw, reg)
    actuators, activations = _actuators(draw, reg)
    for section, children in (
        (Tendon, tendons),
        (Actuator, actuators),
        (Sensor, _sensors(reg)),
        (Equality, _equalities(draw, reg)),
        (Contact, _contact(reg)),
    ):
        if children:
            found.append(section(children=children))
    # MuJoCo 3.9 checks and copies keys at each <replicate>: no keys beside one
    if not reg.replicates and draw(st.integers(0, 2)):
        keys = [_key(draw, reg, world, len(actuators), activations)]
        found.append(Keyframe(children=keys))
    return found
