"""Where :func:`mjcf_model.attach` puts a child: at a body, a frame or a site, placed.

A child attached at a site or a frame goes at the end of the body holding it,
nested in unnamed ``<frame>`` elements that copy the pose of each frame between
that body and the target, the site's own pose (through its default classes),
and the placement asked for. This is where MjSpec's ``attach`` puts it. With
``Where.inside``, a child attached at a frame goes inside that frame instead,
keeping its place in document order, as MuJoCo's ``<attach>`` element does.

>>> from mjcf_model import loads
>>> arm = loads('<mujoco><worldbody><body name="hand"><site name="tip" pos="0 0 0.1"/>'
...             '</body></worldbody></mujoco>')
>>> point = attach_point(arm, Where(at="tip", kind=None, placement=None))
>>> point.holder.name, [frame.pos for frame in point.frames]
('hand', [(0.0, 0.0, 0.1)])
"""

from __future__ import annotations

import functools
from collections.abc import Iterable, Mapping, Sequence
from typing import Literal

import attrs

from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.nodes.base import AnyElement, Node, get_attribute, with_attributes
from mjcf_model.nodes.body import Frame
from mjcf_model.nodes.root import Mujoco
from mjcf_model.transforms.composition.rotations import ORIENTATIONS
from mjcf_model.tree.ancestry import Ancestors
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.traversal import keyed_walk, with_children
from mjcf_model.values import Value, to_vec3, to_vec4

__all__ = ["AttachKind", "AttachPoint", "Where", "attach_point", "placement_frame", "wrapped"]

#: The kinds of parent element a child can be attached at.
AttachKind = Literal["body", "frame", "site"]

#: Schema keys of the elements a child can be attached at.
_ATTACH_KEYS = {"body": "body", "body/frame": "frame", "body/site": "site"}


def placement_frame(
    pos: Iterable[float] | None, quat: Iterable[float] | None, euler: Iterable[float] | None
) -> Frame | None:
    """The frame placing the child's world relative to the attach point, if any is asked for.

    Examples:
        >>> placement_frame([0, 0, 1], None, None).pos, placement_frame(None, None, None)
        ((0.0, 0.0, 1.0), None)

    """
    if quat is not None and euler is not None:
        raise MjcfValueError("give the child's orientation as quat or as euler, not both")
    if pos is None and quat is None and euler is None:
        return None
    return Frame(pos=to_vec3(pos), quat=to_vec4(quat), euler=to_vec3(euler))


@attrs.frozen
class Where:
    """Where :func:`attach` was asked to put the children, as given."""

    #: The name of the body, frame or site (``None``: the world).
    at: str | None
    #: Which kind of element ``at`` names, when it is ambiguous.
    kind: AttachKind | None
    #: The frame with ``pos``/``quat``/``euler``, if any.
    placement: Frame | None
    #: Whether the children go inside the frame ``at`` (where it stands in document
    #: order) rather than at the end of the body holding it.
    inside: bool = False


@attrs.frozen
class AttachPoint:
    """Where the children's worlds go: appended to ``holder``, nested in ``frames``."""

    #: The body whose children the worlds join; ``None`` for the world.
    holder: AnyElement | None
    #: The frames the worlds are nested in, outermost first.
    frames: tuple[Frame, ...]


def _located(parent: Mujoco, at: str, kind: AttachKind | None) -> tuple[AnyElement, Ancestors]:
    """The body, frame or site named ``at`` and its ancestors; errors list what exists."""
    if kind is not None and kind not in _ATTACH_KEYS.values():
        raise MjcfValueError(f"at_kind must be 'body', 'frame' or 'site', not {kind!r}")
    names: dict[str, list[str]] = {k: [] for k in _ATTACH_KEYS.values()}
    found: dict[str, tuple[AnyElement, Ancestors]] = {}
    for element, key, ancestors in keyed_walk(parent):
        name = get_attribute(element, "name")
        if key in _ATTACH_KEYS and isinstance(name, str):
            names[_ATTACH_KEYS[key]].append(name)
            if name == at and kind in (None, _ATTACH_KEYS[key]):
                found.setdefault(_ATTACH_KEYS[key], (element, ancestors))
    if len(found) > 1:
        kinds = " or ".join(repr(k) for k in found)
        raise MjcfLookupError(
            f"the parent has a {' and a '.join(found)} named {at!r}; say which with at_kind={kinds}"
        )
    if not found:
        plural = {"body": "bodies", "frame": "frames", "site": "sites"}
        listed = ", ".join(f"its {plural[k]} are {sorted(n)}" for k, n in names.items())
        what = f"{kind} named {at!r}" if kind else f"body named {at!r} (nor a frame or site)"
        raise MjcfLookupError(f"the parent has no {what}; {listed}")
    return next(iter(found.values()))


def attach_point(parent: Mujoco, where: Where) -> AttachPoint | None:
    """Where the children's worlds go in ``parent`` (``None``: appended to its world).

    Examples:
        >>> from mjcf_model import loads
        >>> arm = loads('<mujoco><worldbody><body name="hand"><frame name="f" pos="1 0 0"/>'
        ...             '</body></worldbody></mujoco>')
        >>> point = attach_point(arm, Where(at="f", kind=None, placement=None))
        >>> point.holder.name, [frame.pos for frame in point.frames]
        ('hand', [(1.0, 0.0, 0.0)])

    """
    frames = [] if where.placement is None else [where.placement]
    if where.at is None:
        return AttachPoint(holder=None, frames=tuple(frames)) if frames else None
    target, ancestors = _located(parent, where.at, where.kind)
    if target.tag == "body" or (where.inside and target.tag == "frame"):
        holder, outer = target, [*ancestors, target]
    else:
        index = max(i for i, a in enumerate(ancestors) if a.tag in ("body", "worldbody"))
        holder, outer = ancestors[index], list(ancestors[: index + 1])
        between = [*ancestors[index + 1 :], *([target] if target.tag == "frame" else [])]
        if any(a.tag != "frame" for a in between):
            raise MjcfValueError(f"cannot attach at {where.at!r}: it is inside a <replicate>")
        copied = [_frame_at(get_attribute(f, "pos"), _written_orientation(f)) for f in between]
        if target.tag == "site":
            classes = DefaultClasses.of(parent)
            if classes.resolve(target, ancestors, "fromto") is not None:
                raise MjcfValueError(
                    f"cannot attach at site {where.at!r}: its pose comes from 'fromto' "
                    "(MjSpec would ignore it); give the site pos and an orientation instead"
                )
            orientation = _site_orientation(classes, target, ancestors)
            copied.append(_frame_at(classes.resolve(target, ancestors, "pos"), orientation))
        frames = [*copied, *frames]
    if any(get_attribute(a, "childclass") is not None for a in outer):
        inner = frames.pop() if frames else Frame()
        frames.append(with_attributes(inner, {"childclass": "main"}))
    return AttachPoint(holder=None if holder.tag == "worldbody" else holder, frames=tuple(frames))


def _frame_at(pos: Value | None, orientation: Mapping[str, Value]) -> Frame:
    """An empty frame with ``pos`` and ``orientation`` (attributes as written)."""
    return with_attributes(Frame(), {"pos": pos, **orientation})


def _written_orientation(element: AnyElement) -> dict[str, Value]:
    """The orientation attribute ``element`` writes itself (empty when none)."""
    found = {attribute: get_attribute(element, attribute) for attribute in ORIENTATIONS}
    return {attribute: value for attribute, value in found.items() if value is not None}


def _site_orientation(
    classes: DefaultClasses, site: AnyElement, ancestors: Sequence[AnyElement]
) -> dict[str, Value]:
    """The orientation attribute ``site`` compiles with: its own or one of its classes'."""
    chain = classes.chain(classes.class_of(site, ancestors))
    levels = [
        site,
        *(classes.settings[c, "site"] for c in chain if (c, "site") in classes.settings),
    ]
    written = [w for w in map(_written_orientation, levels) if w]
    if not _quat_overrides_class_orientation():
        written = [w for w in written if "quat" not in w] + written
    return written[0] if written else {}


@functools.cache
def _quat_overrides_class_orientation() -> bool:
    """Whether the installed MuJoCo lets an element's ``quat`` override its class's ``euler``.

    MuJoCo 4.0 takes the innermost orientation written (the element's, then its
    classes' from the nearest); 3.9 prefers the innermost ``axisangle``,
    ``xyaxes``, ``zaxis`` or ``euler`` anywhere in that chain over any ``quat``.
    Asking MuJoCo once keeps frames at sites exactly where it compiles the site.
    """
    import mujoco

    probe = mujoco.MjModel.from_xml_string(
        '<mujoco><default><site euler="0 0 90"/></default>'
        '<worldbody><site quat="0 1 0 0"/></worldbody></mujoco>'
    )
    return bool(probe.site_quat[0, 1] > 0.5)


def wrapped(frames: Sequence[Frame], nodes: list[Node]) -> list[Node]:
    """``nodes`` nested in ``frames``, the first frame outermost.

    Examples:
        >>> from mjcf_model import Body
        >>> wrapped([Frame(pos=[1, 0, 0])], [Body(name="b")])[0].elements
        (Body(name='b'),)

    """
    for frame in reversed(frames):
        nodes = [with_children(frame, nodes)]
    return nodes
