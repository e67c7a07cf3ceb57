"""Merging the keyframes of two models being composed by :func:`mjcf_model.attach`.

A keyframe lists values for every joint (``qpos``, ``qvel``) and actuator
(``ctrl``) of its model, in model order. After attaching, the child's joints sit
at the attach point and its actuators after the parent's, so each key is
spliced: a child key gets the parent's initial values around its own, a parent
key gets the child's initial values at the attach point when later joints
follow (MuJoCo itself completes a key that stops early).

>>> from serializers import loads
>>> parent = loads('<mujoco><worldbody><body><joint type="slide" ref="0.2"/>'
...                '<geom size="1"/></body></worldbody></mujoco>')
>>> child = loads('<mujoco><worldbody><body><joint type="slide"/><geom size="1"/></body>'
...               '</worldbody><keyframe><key name="k" qpos="0.5"/></keyframe></mujoco>')
>>> [key.qpos for key in merged_keyframes(parent, child, None)]
[(0.2, 0.5)]
"""

from __future__ import annotations

from collections.abc import Sequence

import attrs

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import (
    AnyElement,
    GenericElement,
    Node,
    TypedElement,
    get_attribute,
    with_attributes,
)
from mjcf_model.nodes.root import Mujoco
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.joints import joint_type
from mjcf_model.tree.traversal import keyed_walk
from mjcf_model.values import numbers_of

__all__ = ["keys_of", "merged_keyframes"]

_QPOS_SIZE = {"free": 7, "ball": 4, "slide": 1, "hinge": 1}
_QVEL_SIZE = {"free": 6, "ball": 3, "slide": 1, "hinge": 1}
_ROTATIONS = ("euler", "axisangle", "xyaxes", "zaxis")


@attrs.frozen
class _Joint:
    type: str
    #: The initial ``qpos`` values, or why they cannot be known.
    qpos0: tuple[float, ...] | str
    #: Whether the joint comes before the attach point in model order.
    before: bool


def _joints(model: Mujoco, target: AnyElement | None) -> list[_Joint]:
    classes = DefaultClasses.of(model)
    walked = list(keyed_walk(model))
    order = {id(element): index for index, (element, _, _) in enumerate(walked)}
    found: list[_Joint] = []
    for element, key, ancestors in walked:
        kind = joint_type(element, key, ancestors, classes)
        if kind is None:
            continue
        before = (
            target is None
            or any(a is target for a in ancestors)
            or order[id(element)] < order[id(target)]
        )
        found.append(
            _Joint(type=kind, qpos0=_qpos0(element, kind, ancestors, classes), before=before)
        )
    return found


def _qpos0(
    joint: AnyElement, kind: str, ancestors: Sequence[AnyElement], classes: DefaultClasses
) -> tuple[float, ...] | str:
    if kind in ("hinge", "slide"):
        return numbers_of(classes.resolve(joint, ancestors, "ref")) or (0.0,)
    if kind == "ball":
        return (1.0, 0.0, 0.0, 0.0)
    body = ancestors[-1]
    in_world = len(ancestors) >= 2 and ancestors[-2].tag == "worldbody"
    if not in_world or any(get_attribute(body, r) is not None for r in _ROTATIONS):
        return (
            "cannot complete a keyframe: a free joint's initial position is known here only "
            "for a body directly in the world placed with pos and quat"
        )
    pos = numbers_of(get_attribute(body, "pos")) or (0.0, 0.0, 0.0)
    quat = numbers_of(get_attribute(body, "quat")) or (1.0, 0.0, 0.0, 0.0)
    return (*pos, *quat)


def keys_of(model: Mujoco) -> list[AnyElement]:
    """Every ``<key>`` of the model's ``<keyframe>`` sections, in order."""
    return [
        key
        for section in model.children
        if isinstance(section, (TypedElement, GenericElement)) and section.tag == "keyframe"
        for key in section.elements
    ]


def _actuator_count(model: Mujoco) -> int:
    return sum(
        len(section.elements)
        for section in model.children
        if isinstance(section, (TypedElement, GenericElement)) and section.tag == "actuator"
    )


def _flat(joints: list[_Joint], sizes: dict[str, int], initial: bool) -> list[float]:
    values: list[float] = []
    for joint in joints:
        if not initial:
            values.extend((0.0,) * sizes[joint.type])
        elif isinstance(joint.qpos0, str):
            raise MjcfValueError(joint.qpos0)
        else:
            values.extend(joint.qpos0)
    return values


def _completed(given: tuple[float, ...] | None, full: list[float]) -> list[float]:
    values = list(given or ())
    return values + full[len(values) :]


def merged_keyframes(parent: Mujoco, child: Mujoco, target: AnyElement | None) -> list[Node] | None:
    """The keys of the composed model, or ``None`` when the child has none and nothing moves."""
    parent_keys, child_keys = keys_of(parent), keys_of(child)
    parent_joints = _joints(parent, target) if parent_keys or child_keys else []
    before = [j for j in parent_joints if j.before]
    after = [j for j in parent_joints if not j.before]
    if not child_keys and not (parent_keys and after):
        return None
    child_joints = _joints(child, None)
    merged: list[Node] = []
    for key in parent_keys:
        changes: dict[str, tuple[float, ...]] = {}
        for attribute, sizes, initial in (("qpos", _QPOS_SIZE, True), ("qvel", _QVEL_SIZE, False)):
            given = numbers_of(get_attribute(key, attribute))
            split = sum(sizes[j.type] for j in before)
            if given is not None and len(given) > split:
                inserted = _flat(child_joints, sizes, initial)
                changes[attribute] = (*given[:split], *inserted, *given[split:])
        merged.append(_evolved(key, changes))
    for key in child_keys:
        if get_attribute(key, "act") is not None and _actuator_count(parent):
            raise MjcfValueError(
                "cannot merge a child keyframe's 'act' into a parent with actuators"
            )
        if get_attribute(key, "mpos") is not None or get_attribute(key, "mquat") is not None:
            raise MjcfValueError("cannot merge a child keyframe with mocap values yet")
        changes = {}
        for attribute, sizes, initial in (("qpos", _QPOS_SIZE, True), ("qvel", _QVEL_SIZE, False)):
            given = numbers_of(get_attribute(key, attribute))
            if given is None:
                continue
            own = _completed(given, _flat(child_joints, sizes, initial)) if after else list(given)
            changes[attribute] = (
                *_flat(before, sizes, initial),
                *own,
                *_flat(after, sizes, initial),
            )
        ctrl = numbers_of(get_attribute(key, "ctrl"))
        if ctrl is not None:
            changes["ctrl"] = (*(0.0,) * _actuator_count(parent), *ctrl)
        merged.append(_evolved(key, changes))
    return merged


def _evolved(key: AnyElement, changes: dict[str, tuple[float, ...]]) -> AnyElement:
    return with_attributes(key, dict(changes)) if changes else key
