"""The keyframes of a composed scene: every part's keys follow the part's placement.

A ``<key>`` lists a value for every joint (``qpos``, ``qvel``), actuator
(``ctrl``, ``act``) and mocap body (``mpos``, ``mquat``) of its model. When
:func:`mjcf_model.attach` places a part in a scene, each key of the scene is
written whole, part by part:

* a part's own key holds the part's state as the part itself defines it (read
  from the part compiled alone, so MuJoCo's completion of a short key holds),
  moved by the pose the part is attached at: a free joint's position and
  orientation and a mocap body's pose are world coordinates and move with the
  placement (every enclosing frame, the site and ``pos``/``quat``/``euler``), a
  free joint's linear velocity turns with it; hinge, slide and ball values,
  angular velocities, ``ctrl``, ``act`` and ``time`` are kept;
* every other part's entries are that part's initial state as placed: its
  ``qpos0`` (a free body where it was placed, joints at their reference
  values), no velocity, no control or activation, mocap bodies where they
  were placed.

With ``keyframes="separate"`` (the default) each part's keys keep their
(prefixed) names; with ``keyframes="merged"`` a child's key whose name (before
prefixing) a key of the parent has becomes part of that key, so one ``home``
can set a whole fleet, and unnamed keys (no name, or an empty one) merge by their
place among the unnamed keys: the child's first unnamed key joins the parent's first,
and so on (MuJoCo names keys by name or index). A merged key's ``time`` is the
parent's, unless the parent's is zero: then the child's.

>>> from mjcf_model import loads
>>> world = loads('<mujoco><worldbody><body><joint type="slide" ref="0.2"/>'
...               '<geom size="1"/></body></worldbody></mujoco>')
>>> robot = loads('<mujoco><worldbody><body><joint type="slide"/><geom size="1"/></body>'
...               '</worldbody><keyframe><key name="k" qpos="0.5"/></keyframe></mujoco>')
>>> scene = SceneKeys.of(world, holder=None)
>>> scene.add(PartStates.of(robot), keys_of(robot), keys_of(robot), IDENTITY, "separate")
>>> [key.qpos for key in scene.nodes()]
[(0.2, 0.5)]
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Literal, get_args

import attrs
import numpy as np

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, Node, get_attribute, with_attributes
from mjcf_model.nodes.keyframe import Key
from mjcf_model.nodes.root import Mujoco
from mjcf_model.transforms.composition.part_states import (
    IDENTITY,
    KEY_ATTRIBUTES,
    PartStates,
    Pose,
    State,
    Vector,
    pose_of_frames,
)
from mjcf_model.transforms.composition.places import AttachPoint
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.joints import joint_type
from mjcf_model.tree.traversal import keyed_walk
from mjcf_model.values import Value, numbers_of

__all__ = [
    "IDENTITY",
    "KeyframePolicy",
    "PartStates",
    "SceneKeys",
    "adds_state",
    "attach_pose",
    "check_policy",
    "has_keys",
    "keys_of",
]

#: How :func:`mjcf_model.attach` treats keys of the same name in parent and child.
KeyframePolicy = Literal["separate", "merged"]

#: The ``qpos`` and ``qvel`` sizes of each joint type.
_SIZES = {"free": (7, 6), "ball": (4, 3), "slide": (1, 1), "hinge": (1, 1)}
#: Schema keys of joints.
_JOINTS = frozenset({"body/joint", "body/freejoint"})
#: Schema keys of elements that make joints or bodies the tree does not show.
_HIDDEN = frozenset({"body/replicate", "body/flexcomp", "body/attach"})


def check_policy(policy: str) -> KeyframePolicy:
    """``policy`` if it is a keyframe policy, else an error listing them."""
    if policy not in get_args(KeyframePolicy):
        raise MjcfValueError(f"keyframes must be 'separate' or 'merged', not {policy!r}")
    return policy  # type: ignore[return-value]


def keys_of(model: Mujoco) -> list[AnyElement]:
    """Every ``<key>`` of the model's ``<keyframe>`` sections, in order."""
    return [
        key for section in model.elements if section.tag == "keyframe" for key in section.elements
    ]


def has_keys(model: Mujoco) -> bool:
    """Whether MuJoCo gives ``model`` keyframes: ``<key>`` elements or ``<size nkey>``.

    Examples:
        >>> from mjcf_model import loads
        >>> has_keys(loads('<mujoco><size nkey="1"/></mujoco>')), has_keys(loads("<mujoco/>"))
        (True, False)

    """
    if keys_of(model):
        return True
    sizes = [numbers_of(get_attribute(s, "nkey")) for s in model.elements if s.tag == "size"]
    return any(size and size[0] > 0 for size in sizes)


def adds_state(model: Mujoco) -> bool:
    """Whether ``model`` has anything a key sets: joints, mocap bodies, actuators or keys."""
    for element, key, _ in keyed_walk(model):
        if key in _JOINTS or key in _HIDDEN or key == "keyframe/key":
            return True
        if key == "size" and get_attribute(element, "nkey") is not None:
            return True
        if key == "body" and get_attribute(element, "mocap") in (True, "true"):
            return True
        if key is not None and key.startswith("actuator/"):
            return True
    return False


@attrs.define
class _Keyed:
    """A key of the scene: the node it is written to, the name it merges by, its state."""

    #: The ``<key>`` node (its other attributes and its layout are kept).
    node: AnyElement
    #: The name it is merged by (a child key's name before prefixing), or ``None``.
    name: str | None
    #: The complete state it sets.
    state: State


@attrs.define
class SceneKeys:
    """The keys of a scene being composed, complete, and where the next part's entries go."""

    #: The scene's keys, in order.
    keys: list[_Keyed]
    #: The scene's initial state (what MuJoCo fills a key's missing values with).
    initial: State
    #: Where the next part's ``qpos``, ``qvel`` and mocap entries are inserted.
    at: tuple[int, int, int]

    @classmethod
    def of(cls, parent: Mujoco, holder: AnyElement | None) -> SceneKeys:
        """The keys of ``parent``, ready for parts attached at ``holder`` (``None``: the world)."""
        states = PartStates.of(parent)
        nodes = _padded(keys_of(parent), len(states.keys))
        keys = [
            _Keyed(node=node, name=_name(node), state=state)
            for node, state in zip(nodes, states.keys, strict=True)
        ]
        initial = states.initial
        if holder is None:
            at = (initial.qpos.size, initial.qvel.size, initial.mpos.size // 3)
        else:
            at = _entries_before(parent, holder, initial)
        return cls(keys=keys, initial=initial, at=at)

    def add(
        self,
        part: PartStates,
        names: Sequence[AnyElement],
        nodes: Sequence[AnyElement],
        pose: Pose,
        policy: KeyframePolicy,
    ) -> None:
        """Add a part's entries to every key, and the part's own keys.

        Args:
            part: The part's states, compiled alone.
            names: The part's ``<key>`` elements as the part names them (merging reads these).
            nodes: The same keys as they are written into the scene (prefixed).
            pose: Where the part is attached, in world coordinates.
            policy: ``"separate"`` or ``"merged"`` (see the module's docstring).

        """
        part = part.placed(pose)
        names, nodes = _padded(names, len(part.keys)), _padded(nodes, len(part.keys))
        own = [_name(key) for key in names]
        taken: set[int] = set()
        unnamed = iter([i for i, n in enumerate(own) if n is None])
        for keyed in self.keys:
            match = None
            if policy == "merged" and keyed.name is None:  # by place among the unnamed
                match = next(unnamed, None)
            elif policy == "merged" and keyed.name in own:
                match = next(i for i, n in enumerate(own) if n == keyed.name and i not in taken)
            if match is not None:
                taken.add(match)
            theirs = part.initial if match is None else part.keys[match]
            keyed.state = self._spliced(keyed.state, theirs)
        for index, (node, state) in enumerate(zip(nodes, part.keys, strict=True)):
            if index in taken:
                continue
            name = own[index]
            if policy == "merged":
                node = with_attributes(node, {"name": name})
            self.keys.append(_Keyed(node=node, name=name, state=self._spliced(self.initial, state)))
        self.initial = self._spliced(self.initial, part.initial)
        q, v, m = self.at
        self.at = (
            q + part.initial.qpos.size,
            v + part.initial.qvel.size,
            m + part.initial.mpos.size // 3,
        )

    def _spliced(self, scene: State, part: State) -> State:
        """``scene``'s state with ``part``'s entries where the part goes."""
        q, v, m = self.at

        def insert(ours: Vector, theirs: Vector, at: int) -> Vector:
            return np.concatenate([ours[:at], theirs, ours[at:]])

        return State(
            qpos=insert(scene.qpos, part.qpos, q),
            qvel=insert(scene.qvel, part.qvel, v),
            act=np.concatenate([scene.act, part.act]),
            ctrl=np.concatenate([scene.ctrl, part.ctrl]),
            mpos=insert(scene.mpos, part.mpos, 3 * m),
            mquat=insert(scene.mquat, part.mquat, 4 * m),
            time=scene.time or part.time,
        )

    @property
    def names(self) -> set[str]:
        """The names of the scene's keys."""
        return {name for k in self.keys if (name := _name(k.node)) is not None}

    def nodes(self) -> list[Node]:
        """The scene's ``<key>`` elements, each setting its whole state.

        ``qpos`` is written whole; velocities, activations and controls only
        where one is not zero, mocap poses only where they differ from the
        scene's initial ones, ``time`` only when it is not zero: MuJoCo fills
        what is left out with exactly those values.
        """
        written: list[Node] = []
        for keyed in self.keys:
            state = keyed.state
            changes: dict[str, Value | None] = {}
            for attribute in KEY_ATTRIBUTES:
                values = state.array(attribute)
                if attribute == "qpos":
                    keep = bool(values.size)
                elif attribute in ("mpos", "mquat"):
                    keep = not np.array_equal(values, self.initial.array(attribute))
                else:
                    keep = bool(np.any(values))
                changes[attribute] = tuple(float(v) for v in values) if keep else None
            changes["time"] = state.time or None
            written.append(with_attributes(keyed.node, changes))
        return written


def attach_pose(
    parent: Mujoco, point: AttachPoint | None, at: str | None, part: PartStates
) -> Pose:
    """The world pose a part is attached at, where the part has something it moves.

    Raises:
        MjcfValueError: The part has free joints or mocap bodies and the attach
            point is inside a body (MuJoCo allows those only at the top level).

    """
    if not part.moves_with_placement or point is None:
        return IDENTITY
    if point.holder is not None:
        raise MjcfValueError(
            f"cannot attach a part with free joints or mocap bodies at {at!r}: it is inside "
            f"the <{point.holder.tag}> {get_attribute(point.holder, 'name')!r}, and MuJoCo "
            "allows those only at the top level; attach the part at the world, or at a frame "
            "or a site of the world body"
        )
    return pose_of_frames(parent, point.frames)


def _padded(keys: Sequence[AnyElement], count: int) -> list[AnyElement]:
    """``keys``, then an empty ``<key>`` for each key MuJoCo adds (``<size nkey>``)."""
    return [*keys, *(Key() for _ in range(count - len(keys)))]


def _name(key: AnyElement) -> str | None:
    name = get_attribute(key, "name")
    return name if isinstance(name, str) and name else None


def _entries_before(parent: Mujoco, holder: AnyElement, initial: State) -> tuple[int, int, int]:
    """How many ``qpos``, ``qvel`` and mocap entries of ``parent`` come before parts at ``holder``.

    A part attached at a body goes after that body's own subtree, so the
    joints and mocap bodies before it are those above or inside ``holder`` and
    those earlier in document order, as MuJoCo numbers them.
    """
    classes = DefaultClasses.of(parent)
    walked = list(keyed_walk(parent))
    order = {id(element): index for index, (element, _, _) in enumerate(walked)}
    totals, before = [0, 0, 0], [0, 0, 0]
    for element, key, ancestors in walked:
        if key in _HIDDEN:
            raise MjcfValueError(
                f"cannot place keyframe entries inside a model whose <{element.tag}> makes "
                "joints or bodies: attach at the world, or inline them first "
                "(mjcf_model.inlined_attachments)"
            )
        kind = joint_type(element, key, ancestors, classes)
        sizes = (0, 0, 0)
        if kind is not None:
            sizes = (*_SIZES[kind], 0)
        elif key == "body" and get_attribute(element, "mocap") in (True, "true"):
            sizes = (0, 0, 1)
        is_before = any(a is holder for a in ancestors) or order[id(element)] < order[id(holder)]
        for index, size in enumerate(sizes):
            totals[index] += size
            before[index] += size if is_before else 0
    compiled = (initial.qpos.size, initial.qvel.size, initial.mpos.size // 3)
    if tuple(totals) != compiled:
        raise MjcfValueError(
            f"cannot place keyframe entries: the tree shows {totals[0]} qpos, {totals[1]} qvel "
            f"and {totals[2]} mocap entries where MuJoCo compiles {compiled[0]}, {compiled[1]} "
            f"and {compiled[2]}; attach at the world instead"
        )
    return before[0], before[1], before[2]
