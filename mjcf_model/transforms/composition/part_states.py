"""The states a part's keyframes set, as MuJoCo compiles them, and moving them with a placement.

A keyframe of a model lists a value for every joint (``qpos``, ``qvel``), every
actuator (``ctrl``, ``act``) and every mocap body (``mpos``, ``mquat``); MuJoCo
completes what a ``<key>`` leaves out from the model's initial state. A
:class:`PartStates` holds those complete states of one part, read from the part
compiled alone, and :meth:`PartStates.placed` moves them with the pose the part
is attached at: a free joint's position and orientation and a mocap body's pose
are world coordinates, so they move; a free joint's linear velocity (world
frame) turns with the placement; everything else is relative and stays.

>>> from mjcf_model import loads
>>> cube = loads('<mujoco><worldbody><body pos="0 0 1"><freejoint/><geom size=".1"/></body>'
...              '</worldbody><keyframe><key name="up" qpos="0 0 2 1 0 0 0"/></keyframe></mujoco>')
>>> states = PartStates.of(cube)
>>> moved = states.placed(Pose(pos=(1.0, 0.0, 0.0), quat=(1.0, 0.0, 0.0, 0.0)))
>>> moved.initial.qpos.tolist(), moved.keys[0].qpos.tolist()
([1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0], [1.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0])
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import attrs
import numpy as np
import numpy.typing as npt

from mjcf_model.bridge.compiling import compiled
from mjcf_model.errors import MjcfCompileError, MjcfValueError
from mjcf_model.nodes.base import Node, get_attribute, with_attributes
from mjcf_model.nodes.body import Body, Frame, Worldbody
from mjcf_model.nodes.compiler import Compiler
from mjcf_model.nodes.root import Mujoco
from mjcf_model.transforms.composition.compiler_settings import compiler_settings
from mjcf_model.transforms.composition.rotations import ORIENTATIONS
from mjcf_model.tree.traversal import with_children

if TYPE_CHECKING:
    import mujoco

__all__ = [
    "IDENTITY",
    "KEY_ATTRIBUTES",
    "PartStates",
    "Pose",
    "State",
    "Vector",
    "pose_of_frames",
]

#: A state array.
Vector = npt.NDArray[np.float64]

#: The ``<key>`` attributes that hold a part's state, in the order they are written.
KEY_ATTRIBUTES = ("qpos", "qvel", "act", "ctrl", "mpos", "mquat")


@attrs.frozen
class Pose:
    """A rigid placement: a position and a unit quaternion (w, x, y, z) in world coordinates."""

    #: The position.
    pos: tuple[float, float, float]
    #: The orientation.
    quat: tuple[float, float, float, float]

    @property
    def is_identity(self) -> bool:
        """Whether the pose moves nothing."""
        return self.pos == (0.0, 0.0, 0.0) and self.quat == (1.0, 0.0, 0.0, 0.0)


#: The pose that moves nothing.
IDENTITY = Pose(pos=(0.0, 0.0, 0.0), quat=(1.0, 0.0, 0.0, 0.0))


@attrs.frozen
class State:
    """One complete state a keyframe sets: every array full length, as MuJoCo completes it."""

    #: Joint positions.
    qpos: Vector
    #: Joint velocities.
    qvel: Vector
    #: Actuator activations.
    act: Vector
    #: Controls.
    ctrl: Vector
    #: Mocap body positions, flattened (three per body).
    mpos: Vector
    #: Mocap body orientations, flattened (four per body).
    mquat: Vector
    #: The simulation time.
    time: float = 0.0

    def array(self, attribute: str) -> Vector:
        """The array written to the ``<key>`` attribute ``attribute``."""
        value: Vector = getattr(self, attribute)
        return value


@attrs.frozen
class PartStates:
    """A part's initial state and the states its keys set, with where its free joints are."""

    #: The state MuJoCo starts the part in (``qpos0``, nothing moving, mocap bodies placed).
    initial: State
    #: The state each ``<key>`` sets, in document order.
    keys: tuple[State, ...]
    #: The ``qpos`` addresses of its free joints.
    free_qpos: tuple[int, ...]
    #: The ``qvel`` addresses of its free joints.
    free_qvel: tuple[int, ...]

    @property
    def moves_with_placement(self) -> bool:
        """Whether a placement changes its states: it has free joints or mocap bodies."""
        return bool(self.free_qpos) or bool(self.initial.mpos.size)

    @classmethod
    def of(cls, model: Mujoco) -> PartStates:
        """The states of ``model`` compiled alone (:func:`mjcf_model.compiled`).

        Raises:
            MjcfCompileError: The part does not compile alone; the message says
                that its keyframes need it to.

        """
        try:
            mj = compiled(model)
        except MjcfCompileError as error:
            raise MjcfCompileError(
                f"{error.detail} (composing keyframes reads each part's initial state and "
                "keys from the part compiled alone, so the part must compile on its own)",
                file=error.file,
                line=error.line,
                path=error.path,
            ) from None
        return cls.of_compiled(mj)

    @classmethod
    def of_compiled(cls, mj: mujoco.MjModel) -> PartStates:
        """The states of a compiled model."""
        if mj.key_plastic.shape[1] if hasattr(mj, "key_plastic") else 0:
            raise MjcfValueError(
                "cannot compose keyframes of a model with plastic state yet; "
                "remove its keyframes before attaching"
            )
        mocap = sorted(
            (int(mj.body_mocapid[b]), b) for b in range(mj.nbody) if mj.body_mocapid[b] >= 0
        )
        bodies = [b for _, b in mocap]
        initial = State(
            qpos=np.array(mj.qpos0, dtype=float),
            qvel=np.zeros(mj.nv),
            act=np.zeros(mj.na),
            ctrl=np.zeros(mj.nu),
            mpos=np.array(mj.body_pos[bodies], dtype=float).reshape(-1),
            mquat=np.array(mj.body_quat[bodies], dtype=float).reshape(-1),
        )
        keys = tuple(
            State(
                time=float(mj.key_time[k]),
                **{a: np.array(getattr(mj, f"key_{a}")[k], dtype=float) for a in KEY_ATTRIBUTES},
            )
            for k in range(mj.nkey)
        )
        free = [j for j in range(mj.njnt) if int(mj.jnt_type[j]) == 0]  # mjJNT_FREE
        return cls(
            initial=initial,
            keys=keys,
            free_qpos=tuple(int(mj.jnt_qposadr[j]) for j in free),
            free_qvel=tuple(int(mj.jnt_dofadr[j]) for j in free),
        )

    def placed(self, pose: Pose) -> PartStates:
        """The states with the part attached at ``pose``.

        Examples:
            >>> from mjcf_model import loads
            >>> ball = loads('<mujoco><worldbody><body mocap="true" pos="1 0 0"/></worldbody>'
            ...              '</mujoco>')
            >>> turn = Pose(pos=(0.0, 0.0, 0.0), quat=(0.0, 0.0, 0.0, 1.0))
            >>> [round(v, 12) + 0 for v in PartStates.of(ball).placed(turn).initial.mpos]
            [-1.0, 0.0, 0.0]

        """
        if pose.is_identity or not self.moves_with_placement:
            return self
        return attrs.evolve(
            self,
            initial=self._moved(self.initial, pose),
            keys=tuple(self._moved(state, pose) for state in self.keys),
        )

    def _moved(self, state: State, pose: Pose) -> State:
        import mujoco

        turn = np.array(pose.quat, dtype=float)
        shift = np.array(pose.pos, dtype=float)

        def moved_point(point: Vector) -> Vector:
            result: Vector = np.zeros(3)
            mujoco.mju_rotVecQuat(result, np.array(point, dtype=float), turn)
            result += shift
            return result

        def turned(quat: Vector) -> Vector:
            result = np.zeros(4)
            mujoco.mju_mulQuat(result, turn, np.array(quat, dtype=float))
            return result

        qpos, qvel = state.qpos.copy(), state.qvel.copy()
        for address in self.free_qpos:
            qpos[address : address + 3] = moved_point(qpos[address : address + 3])
            qpos[address + 3 : address + 7] = turned(qpos[address + 3 : address + 7])
        for address in self.free_qvel:
            velocity = np.zeros(3)
            mujoco.mju_rotVecQuat(velocity, qvel[address : address + 3].copy(), turn)
            qvel[address : address + 3] = velocity
        mpos, mquat = state.mpos.copy(), state.mquat.copy()
        for index in range(mpos.size // 3):
            mpos[3 * index : 3 * index + 3] = moved_point(mpos[3 * index : 3 * index + 3])
            mquat[4 * index : 4 * index + 4] = turned(mquat[4 * index : 4 * index + 4])
        return attrs.evolve(state, qpos=qpos, qvel=qvel, mpos=mpos, mquat=mquat)


def pose_of_frames(model: Mujoco, frames: Sequence[Frame]) -> Pose:
    """The world pose of the inside of ``frames`` (outermost first) in ``model``'s world.

    The frames' attributes are read as MuJoCo reads them under ``model``'s
    ``<compiler>`` (``angle`` units, ``eulerseq``): a body placed inside them is
    compiled alone and its pose read back.

    Examples:
        >>> from mjcf_model import loads
        >>> world = loads("<mujoco/>")
        >>> pose_of_frames(world, [Frame(pos=[1, 0, 0]), Frame(pos=[0, 2, 0])]).pos
        (1.0, 2.0, 0.0)

    """
    if not frames:
        return IDENTITY
    settings = compiler_settings(model)
    inside: list[Node] = [Body(name="placed")]
    for frame in reversed(frames):
        pose = {a: get_attribute(frame, a) for a in ("pos", *ORIENTATIONS)}
        written = with_attributes(Frame(), {a: v for a, v in pose.items() if v is not None})
        inside = [with_children(written, inside)]
    probe = Mujoco(
        children=[
            Compiler(angle=settings["angle"], eulerseq=settings["eulerseq"]),
            Worldbody(children=inside),
        ]
    )
    mj = compiled(probe)
    pos = tuple(float(v) for v in mj.body_pos[1])
    quat = tuple(float(v) for v in mj.body_quat[1])
    return Pose(pos=pos, quat=quat)  # type: ignore[arg-type]
