"""The joints of a model in ``qpos`` order, with the type and axis each compiles to.

Scaling (slide ranges, keyframes, actuators) and composition (keyframes) read
joints this way: a joint's type and axis are its own or its default class's.

>>> from mjcf_model import Body, Joint
>>> body = Body(children=[Joint(name="j", type="slide")])
>>> joint_layout(body, DefaultClasses.empty())
(JointInfo(name='j', type='slide', axis=(0.0, 0.0, 1.0)),)
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

import attrs

from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.traversal import keyed_walk, walk
from mjcf_model.values import numbers_of

__all__ = ["JointInfo", "joint_layout", "joint_type"]


@attrs.frozen(kw_only=True)
class JointInfo:
    """A joint as the scaling of keyframes and actuators needs it."""

    #: Its name, or ``None``.
    name: str | None
    #: ``free``, ``ball``, ``slide`` or ``hinge`` (its own or its class's).
    type: str
    #: Its axis (its own, its class's, or MuJoCo's default ``0 0 1``).
    axis: tuple[float, ...]


def joint_layout(node: AnyElement, classes: DefaultClasses) -> tuple[JointInfo, ...] | None:
    """The joints of ``node`` in ``qpos`` order; ``None`` when replicate or flexcomp hide some.

    Examples:
        >>> from mjcf_model import Body, Joint
        >>> body = Body(children=[Joint(type="slide")])
        >>> [j.type for j in joint_layout(body, DefaultClasses.empty())]
        ['slide']

    """
    # MuJoCo numbers a body's joints (its frames' included) before any body inside it:
    # each joint is filed under the innermost body around it, bodies in the order they open
    joints: list[tuple[int, JointInfo]] = []
    around: list[tuple[int, int]] = []  # (depth, order opened) of the bodies around
    opened = 0
    for element, key, ancestors in _body_walk(node):
        if key == "body/replicate" and not _holds_joints(element):
            continue  # copies of geoms, sites...: no joints to count
        if key in ("body/replicate", "body/flexcomp", "body/attach"):
            return None
        while around and around[-1][0] >= len(ancestors):
            around.pop()  # a body closed before this element
        if element.tag == "body":
            around.append((len(ancestors), opened))
            opened += 1
        elif key in ("body/freejoint", "body/joint"):
            joints.append(
                (around[-1][1] if around else -1, _info(element, key, ancestors, classes))
            )
    return tuple(info for _, info in sorted(joints, key=lambda pair: pair[0]))


def _info(
    element: AnyElement, key: str, ancestors: Sequence[AnyElement], classes: DefaultClasses
) -> JointInfo:
    """A body's joint or free joint, its type and axis completed from its classes."""
    if key == "body/freejoint":
        return JointInfo(name=_name(element), type="free", axis=(0.0, 0.0, 1.0))
    kind, axis = classes.resolve_many(element, ancestors, ("type", "axis"))
    kind = str(kind or "hinge")
    direction = numbers_of(axis) if kind != "free" else None
    return JointInfo(name=_name(element), type=kind, axis=direction or (0.0, 0.0, 1.0))


def _holds_joints(element: AnyElement) -> bool:
    """Whether a joint stands anywhere below ``element``."""
    return any(e.tag in ("joint", "freejoint") for _, e in walk(element))


def _body_walk(node: AnyElement) -> Iterator[tuple[AnyElement, str | None, Sequence[AnyElement]]]:
    """:func:`keyed_walk` of the bodies: of a whole model, only its ``<worldbody>`` sections."""
    if node.tag != "mujoco":
        yield from keyed_walk(node)
        return
    for section in node.elements:
        if section.tag == "worldbody":
            yield from keyed_walk(section, "mujoco")


def joint_type(
    element: AnyElement, key: str | None, ancestors: Sequence[AnyElement], classes: DefaultClasses
) -> str | None:
    """The type of a body's joint: ``free``, ``ball``, ``slide`` or ``hinge``.

    Its own type or its class's (MuJoCo's default is ``hinge``); ``None`` for an
    element that is not a body's joint.

    Examples:
        >>> from mjcf_model import Joint
        >>> joint_type(Joint(type="slide"), "body/joint", (), DefaultClasses.empty())
        'slide'

    """
    if key == "body/freejoint":
        return "free"
    if key != "body/joint":
        return None
    return str(classes.resolve(element, ancestors, "type") or "hinge")


def _name(element: AnyElement) -> str | None:
    name = get_attribute(element, "name")
    return name if isinstance(name, str) else None
