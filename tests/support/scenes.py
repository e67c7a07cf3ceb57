"""The scene check: a floor, a placed free object and one robot attached twice, keys included.

For a robot model (a file, with keys of its own or keys a test adds), the scene is

    floor (tests/fixtures/scenes/floor.xml: a plane, a site and frames to attach at)
    + a free box attached at the world with ``prefix="obj_"`` and ``pos``
    + the robot with ``prefix="a_"`` at the world, moved by ``pos`` and ``quat``
    + the robot with ``prefix="b_"`` at a site or a frame of the floor, ``pos`` and ``euler``

and :func:`scene_problems` reports, stage by stage, what keeps it from being right:

1. ``compiled``: ``compiled(scene)`` works and its counts are the sums of the parts'
   (``nkey`` too: every part keeps its keys, prefixed);
2. ``initial``: at the scene's ``qpos0`` every body of each part is where the part alone
   puts it, moved by that part's placement;
3. ``keys``: resetting to a copy's key puts the copy where the key puts the robot alone,
   moved; every other part stays at its placed initial pose; ``qvel`` (a free joint's
   linear velocity turned by the placement), ``ctrl``, ``act`` and ``time`` as the rule says;
4. ``files``: the scene dumped into a fresh folder, and exported then moved, compile to
   the same model;
5. ``merged``: built with ``keyframes="merged"``, a key name the copies share is one key
   that sets every copy from its own key (the box at its placed initial pose), and the
   copies' unnamed keys are one key per place among them.

MuJoCo on the parts alone is the referee: the placements come from the floor compiled
with probe bodies (``MjSpec``), the poses from each part compiled on its own. Run it
on your own models with ``python -m tests.support.scenes A.xml B.xml ...`` from a checkout (a
model without keys gets a ``home`` key drawn within its joint ranges).
"""

from __future__ import annotations

import shutil
import sys
import tempfile
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import attrs
import mujoco
import numpy as np

from mjcf_model import Mujoco, attach, compiled
from mjcf_model.nodes.keyframe import Key, Keyframe
from mjcf_model.serializers import dump, export, load
from tests.conftest import FIXTURES
from tests.support.composing import same_model

__all__ = [
    "BOX",
    "FLOOR",
    "STAGES",
    "Part",
    "Placement",
    "home_key",
    "scene_layout",
    "scene_problems",
]

#: The stages of the check, in order.
STAGES = ("compiled", "initial", "keys", "files", "merged")
#: The scene fixtures.
SCENES = FIXTURES / "scenes"
#: The parent of every scene, and the free object placed in it.
FLOOR, BOX = SCENES / "floor.xml", SCENES / "box.xml"
#: The counts that add up over the parts.
COUNTS = ("njnt", "ngeom", "nsite", "nu", "na", "nmocap")
#: Positions and quaternions agree this closely.
TOLERANCE = 1e-9
#: Problems kept per stage (the rest are counted).
SHOWN = 12

Attach = Callable[..., Mujoco]
Values = Mapping[str, tuple[float, ...]]


@attrs.frozen
class Placement:
    """Where a part goes: ``attach``'s ``at``, ``prefix`` and pose arguments."""

    prefix: str
    at: str | None = None
    pos: tuple[float, ...] = (0.0, 0.0, 0.0)
    quat: tuple[float, ...] | None = None
    euler: tuple[float, ...] | None = None

    def options(self) -> dict[str, Any]:
        """The keyword arguments of ``attach``."""
        found: dict[str, Any] = {"prefix": self.prefix, "at": self.at, "pos": self.pos}
        if self.quat is not None:
            found["quat"] = self.quat
        if self.euler is not None:
            found["euler"] = self.euler
        return found


@attrs.frozen
class Part:
    """A model file, with keys added to it (name, values) where it has none of its own."""

    path: Path
    added: tuple[tuple[str, Values], ...] = ()

    def reference(self) -> Any:
        """The part compiled by MuJoCo alone, the added keys set through ``MjSpec``."""
        spec = mujoco.MjSpec.from_file(str(self.path))
        for name, values in self.added:
            spec.add_key(name=name, **{k: list(v) for k, v in values.items()})
        return spec.compile()

    def model(self) -> Mujoco:
        """The part loaded, the added keys written into its ``<keyframe>``."""
        model = load(self.path, inline_includes=True)
        if not self.added:
            return model
        keys = [Key(name=name, **dict(values)) for name, values in self.added]
        return attrs.evolve(model, children=[*model.children, Keyframe(children=keys)])


def home_key(alone: Any, seed: int = 0) -> dict[str, tuple[float, ...]]:
    """A state for ``alone`` drawn with ``seed``: joints within range, some velocity and control.

    Free joints are moved a little from their initial pose and turned anywhere.
    """
    rng = np.random.default_rng(seed)
    qpos, qvel = np.array(alone.qpos0, dtype=float), np.zeros(alone.nv)
    for joint in range(alone.njnt):
        kind, q, v = alone.jnt_type[joint], alone.jnt_qposadr[joint], alone.jnt_dofadr[joint]
        if kind == mujoco.mjtJoint.mjJNT_FREE:
            qpos[q : q + 3] += rng.uniform(-0.3, 0.3, 3)
            qpos[q + 3 : q + 7] = _unit(rng.normal(size=4))
            qvel[v : v + 6] = rng.uniform(-1, 1, 6)
        elif kind == mujoco.mjtJoint.mjJNT_BALL:
            qpos[q : q + 4] = _unit(rng.normal(size=4))
            qvel[v : v + 3] = rng.uniform(-1, 1, 3)
        else:
            low, high = alone.jnt_range[joint] if alone.jnt_limited[joint] else (-1.0, 1.0)
            qpos[q] = rng.uniform(low, high) + (0 if alone.jnt_limited[joint] else qpos[q])
            qvel[v] = rng.uniform(-1, 1)
    ranges = [
        tuple(alone.actuator_ctrlrange[a]) if alone.actuator_ctrllimited[a] else (-1.0, 1.0)
        for a in range(alone.nu)
    ]
    key = {
        "qpos": tuple(map(float, qpos)),
        "qvel": tuple(map(float, qvel)),
        "ctrl": tuple(float(rng.uniform(low, high)) for low, high in ranges),
    }
    if alone.na:
        key["act"] = tuple(map(float, rng.uniform(-0.5, 0.5, alone.na)))
    return key


def _unit(values: np.ndarray[Any, Any]) -> np.ndarray[Any, Any]:
    return values / np.linalg.norm(values)


def scene_layout(alone: Any, point: str) -> tuple[Placement, Placement]:
    """The two copies' placements: ``a_`` at the world, ``b_`` at a ``"site"`` or ``"frame"``.

    A robot with free joints or mocap bodies must stay in the world body: its ``b_``
    copy goes to the floor's site or frame there; a fixed-base robot to the table's.
    """
    top_level = alone.nmocap > 0 or any(t == mujoco.mjtJoint.mjJNT_FREE for t in alone.jnt_type)
    at = {
        (True, "site"): "spot",
        (True, "frame"): "dock_inner",
        (False, "site"): "table_site",
        (False, "frame"): "table_frame",
    }[(top_level, point)]
    turn = tuple(map(float, _unit(np.array([0.9, 0.1, -0.2, 0.35]))))
    return (
        Placement("a_", pos=(0.6, 0.2, 0.05), quat=turn),
        Placement("b_", at=at, pos=(0.1, -0.3, 0.2), euler=(10.0, -20.0, 135.0)),
    )


#: The free object of every scene and where it goes.
OBJECT = (Part(BOX), Placement("obj_", pos=(0.3, -0.4, 0.5)))


# --- the referee: MuJoCo on the parts alone ------------------------------------------------


@attrs.frozen
class Pose:
    """A rigid transform: position and unit quaternion (w, x, y, z)."""

    pos: np.ndarray[Any, Any]
    quat: np.ndarray[Any, Any]

    def moved(self, pos: np.ndarray[Any, Any], quat: np.ndarray[Any, Any]) -> Pose:
        """A pose of the part's world moved by this placement: ``R p + t``, ``q_p q``."""
        turned, product = np.zeros(3), np.zeros(4)
        mujoco.mju_rotVecQuat(turned, np.asarray(pos, dtype=float), self.quat)
        mujoco.mju_mulQuat(product, self.quat, np.asarray(quat, dtype=float))
        return Pose(self.pos + turned, product)

    def turned(self, vector: np.ndarray[Any, Any]) -> np.ndarray[Any, Any]:
        """``vector`` rotated by this placement."""
        result = np.zeros(3)
        mujoco.mju_rotVecQuat(result, np.asarray(vector, dtype=float), self.quat)
        return result


IDENTITY = Pose(np.zeros(3), np.array([1.0, 0, 0, 0]))


def placement_pose(parent: Path, place: Placement) -> Pose:
    """Where ``place`` puts a part's world, from MuJoCo compiling the parent with probes.

    A probe body at the world with the placement's ``pos`` and ``quat``/``euler`` gives the
    local pose in the parent's units; the attach point's world pose is its body's
    ``xpos``/``xquat``, its site's ``site_xpos``/``site_xmat``, or a probe body in its frame.
    """
    spec = mujoco.MjSpec.from_file(str(parent))
    local = spec.worldbody.add_body(name="scene_probe_local", pos=list(place.pos))
    if place.quat is not None:
        local.quat = list(place.quat)
    elif place.euler is not None:
        local.alt.type = mujoco.mjtOrientation.mjORIENTATION_EULER
        local.alt.euler = list(place.euler)
    frame = spec.frame(place.at) if place.at is not None else None
    if frame is not None:
        frame.add_body(name="scene_probe_point")
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    local_pose = _body_pose(model, data, "scene_probe_local")
    if place.at is None:
        point = IDENTITY
    elif mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, place.at) >= 0:
        point = _body_pose(model, data, place.at)
    elif (site := mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, place.at)) >= 0:
        quat = np.zeros(4)
        mujoco.mju_mat2Quat(quat, data.site_xmat[site])
        point = Pose(data.site_xpos[site].copy(), quat)
    elif frame is not None:
        point = _body_pose(model, data, "scene_probe_point")
    else:
        raise LookupError(f"the parent has no body, site or frame {place.at!r}")
    return point.moved(local_pose.pos, local_pose.quat)


def _body_pose(model: Any, data: Any, name: str) -> Pose:
    body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, name)
    return Pose(data.xpos[body].copy(), data.xquat[body].copy())


def _name(model: Any, kind: Any, index: int) -> str:
    return mujoco.mj_id2name(model, kind, index) or ""


@attrs.frozen
class _State:
    """What a part's alone model holds in one state: body poses and the key's other values."""

    poses: dict[str, Pose]
    qvel: np.ndarray[Any, Any]
    ctrl: np.ndarray[Any, Any]
    act: np.ndarray[Any, Any]
    time: float


def _state(alone: Any, key: int | None) -> _State:
    """``alone`` at its ``qpos0`` (``key`` None, zero velocity and control) or at a key."""
    data = mujoco.MjData(alone)
    if key is None:
        mujoco.mj_resetData(alone, data)
    else:
        mujoco.mj_resetDataKeyframe(alone, data, key)
    mujoco.mj_kinematics(alone, data)
    poses = {
        _name(alone, mujoco.mjtObj.mjOBJ_BODY, b): Pose(data.xpos[b].copy(), data.xquat[b].copy())
        for b in range(1, alone.nbody)
        if _name(alone, mujoco.mjtObj.mjOBJ_BODY, b)
    }
    return _State(poses, data.qvel.copy(), data.ctrl.copy(), data.act.copy(), float(data.time))


@attrs.define
class _Placed:
    """One part of the scene: its alone model, prefix and placement."""

    label: str
    prefix: str
    alone: Any
    place: Pose
    #: How many actuators the parts before it have (where its unnamed ones are).
    actuators_before: int
    initial: _State = attrs.field(init=False)

    def __attrs_post_init__(self) -> None:
        self.initial = _state(self.alone, None)

    def key_names(self) -> list[str]:
        """The names of its keys, in order (empty for an unnamed one)."""
        return [_name(self.alone, mujoco.mjtObj.mjOBJ_KEY, k) for k in range(self.alone.nkey)]

    def moved(self, state: _State) -> dict[str, Pose]:
        """Where ``state`` puts its bodies in the scene, by scene name."""
        return {
            self.prefix + name: self.place.moved(pose.pos, pose.quat)
            for name, pose in state.poses.items()
        }


# --- the stages ---------------------------------------------------------------------------


def _build(
    robot: Mujoco,
    places: tuple[Placement, ...],
    thing: tuple[Part, Placement] | None,
    attach: Attach,
    **keys: str,
) -> Mujoco:
    scene = load(FLOOR)
    if thing is not None:
        scene = attach(scene, thing[0].model(), **thing[1].options(), **keys)
    for place in places:
        scene = attach(scene, robot, **place.options(), **keys)
    return scene


def scene_problems(
    robot: Part,
    point: str,
    workdir: Path,
    *,
    attach: Attach = attach,
    thing: tuple[Part, Placement] | None = OBJECT,
) -> dict[str, list[str]]:
    """The problems of each stage of the scene check for ``robot`` (every stage is run).

    ``point`` says where the second copy goes (see :func:`scene_layout`); ``attach`` is
    the function under test; ``thing`` the free object placed first (None: none).
    """
    alone = robot.reference()
    places = scene_layout(alone, point)
    parent = mujoco.MjModel.from_xml_path(str(FLOOR))
    placed = [("floor", "", parent, IDENTITY)]
    if thing is not None:
        where = thing[1]
        placed.append(
            (
                f"object {where.prefix}",
                where.prefix,
                thing[0].reference(),
                placement_pose(FLOOR, where),
            )
        )
    placed += [(f"copy {p.prefix}", p.prefix, alone, placement_pose(FLOOR, p)) for p in places]
    parts: list[_Placed] = []
    before = 0
    for label, prefix, model, pose in placed:
        parts.append(_Placed(label, prefix, model, pose, before))
        before += model.nu
    problems: dict[str, list[str]] = {stage: [] for stage in STAGES}
    try:
        scene = _build(robot.model(), places, thing, attach)
        together = compiled(scene)
    except Exception as error:  # the check reports every failure, whatever its kind
        message = f"the scene does not build: {type(error).__name__}: {error}"
        for stage in STAGES[:-1]:
            problems[stage].append(message)
    else:
        problems["compiled"] = _count_problems(parts, together, separate=True)
        problems["initial"] = _initial_problems(parts, together)
        problems["keys"] = _separate_key_problems(parts, together)
        problems["files"] = _file_problems(scene, together, workdir)
    problems["merged"] = _merged_problems(robot, places, thing, parts, attach)
    return {stage: _shortened(found) for stage, found in problems.items()}


def _shortened(problems: list[str]) -> list[str]:
    if len(problems) <= SHOWN:
        return problems
    return [*problems[:SHOWN], f"... and {len(problems) - SHOWN} more"]


def _count_problems(parts: list[_Placed], scene: Any, *, separate: bool) -> list[str]:
    problems = []
    expected = {count: sum(getattr(p.alone, count) for p in parts) for count in COUNTS}
    expected["nbody"] = 1 + sum(p.alone.nbody - 1 for p in parts)
    names = [name for p in parts for name in p.key_names()]
    unnamed = max((p.key_names().count("") for p in parts), default=0)  # merged by place
    expected["nkey"] = len(names) if separate else len({n for n in names if n}) + unnamed
    for count, value in expected.items():
        if getattr(scene, count) != value:
            problems.append(f"{count} is {getattr(scene, count)}, expected {value}")
    return problems


def _pose_problems(scene: Any, data: Any, expected: dict[str, Pose], label: str) -> list[str]:
    problems = []
    for name, want in expected.items():
        body = mujoco.mj_name2id(scene, mujoco.mjtObj.mjOBJ_BODY, name)
        if body < 0:
            problems.append(f"{label}: body {name!r} is missing")
            continue
        pos, quat = data.xpos[body], data.xquat[body]
        if not np.allclose(pos, want.pos, rtol=0, atol=TOLERANCE):
            problems.append(f"{label}: body {name!r} at {_text(pos)}, expected {_text(want.pos)}")
        turned = min(np.abs(quat - want.quat).max(), np.abs(quat + want.quat).max())
        if turned > TOLERANCE:
            problems.append(
                f"{label}: body {name!r} turned {_text(quat)}, expected {_text(want.quat)}"
            )
    return problems


def _text(values: Any) -> str:
    return "[" + " ".join(f"{v:.6g}" for v in np.ravel(values)) + "]"


def _initial_problems(parts: list[_Placed], scene: Any) -> list[str]:
    data = mujoco.MjData(scene)
    mujoco.mj_resetData(scene, data)
    mujoco.mj_kinematics(scene, data)
    problems = []
    for part in parts:
        problems += _pose_problems(scene, data, part.moved(part.initial), part.label)
    return problems


def _joint_in_scene(part: _Placed, scene: Any, joint: int) -> int:
    """The scene's joint for the part's ``joint``: by name, else by its body and rank there."""
    name = _name(part.alone, mujoco.mjtObj.mjOBJ_JOINT, joint)
    if name:
        return int(mujoco.mj_name2id(scene, mujoco.mjtObj.mjOBJ_JOINT, part.prefix + name))
    body = int(part.alone.jnt_bodyid[joint])
    owner = _name(part.alone, mujoco.mjtObj.mjOBJ_BODY, body)
    found = mujoco.mj_name2id(scene, mujoco.mjtObj.mjOBJ_BODY, part.prefix + owner)
    if not owner or found < 0:
        return -1
    return int(scene.body_jntadr[found] + joint - part.alone.body_jntadr[body])


def _actuator_in_scene(part: _Placed, scene: Any, actuator: int) -> int:
    """The scene's actuator for the part's: by name, else by order after the earlier parts'."""
    name = _name(part.alone, mujoco.mjtObj.mjOBJ_ACTUATOR, actuator)
    if name:
        return int(mujoco.mj_name2id(scene, mujoco.mjtObj.mjOBJ_ACTUATOR, part.prefix + name))
    return part.actuators_before + actuator


def _expected_values(
    parts: list[_Placed], scene: Any, states: list[_State]
) -> tuple[dict[str, np.ndarray[Any, Any]], list[str]]:
    """The scene's ``qvel``, ``ctrl`` and ``act`` when each part is in its state."""
    values = {"qvel": np.zeros(scene.nv), "ctrl": np.zeros(scene.nu), "act": np.zeros(scene.na)}
    problems = []
    for part, state in zip(parts, states, strict=True):
        alone = part.alone
        for joint in range(alone.njnt):
            there = _joint_in_scene(part, scene, joint)
            if there < 0:
                problems.append(f"{part.label}: joint #{joint} is missing")
                continue
            dof, size = alone.jnt_dofadr[joint], {0: 6, 1: 3}.get(int(alone.jnt_type[joint]), 1)
            own = state.qvel[dof : dof + size].copy()
            if size == 6:  # linear velocity in the world frame, angular in the body's
                own[:3] = part.place.turned(own[:3])
            start = scene.jnt_dofadr[there]
            values["qvel"][start : start + size] = own
        for actuator in range(alone.nu):
            there = _actuator_in_scene(part, scene, actuator)
            if there < 0:
                problems.append(f"{part.label}: actuator #{actuator} is missing")
                continue
            values["ctrl"][there] = state.ctrl[actuator]
            own_act, scene_act = alone.actuator_actadr[actuator], scene.actuator_actadr[there]
            if own_act >= 0 and scene_act >= 0:
                count = alone.actuator_actnum[actuator]
                values["act"][scene_act : scene_act + count] = state.act[own_act : own_act + count]
    return values, problems


def _state_problems(
    parts: list[_Placed], scene: Any, key: int, chosen: list[int | None], label: str
) -> list[str]:
    """Problems of the scene reset to ``key``, where part i is at its key ``chosen[i]``."""
    data = mujoco.MjData(scene)
    mujoco.mj_resetDataKeyframe(scene, data, key)
    mujoco.mj_kinematics(scene, data)
    states = [
        part.initial if own is None else _state(part.alone, own)
        for part, own in zip(parts, chosen, strict=True)
    ]
    problems = []
    for part, state in zip(parts, states, strict=True):
        problems += _pose_problems(scene, data, part.moved(state), f"{label}, {part.label}")
    expected, missing = _expected_values(parts, scene, states)
    problems += [f"{label}, {text}" for text in missing]
    for field, want in expected.items():
        got = getattr(data, field)
        for index in np.flatnonzero(~np.isclose(got, want, rtol=0, atol=TOLERANCE)):
            problems.append(
                f"{label}: {field}[{index}] is {got[index]:.6g}, expected {want[index]:.6g}"
            )
    times = {state.time for own, state in zip(chosen, states, strict=True) if own is not None}
    if len(times) == 1 and data.time != (time := times.pop()):
        problems.append(f"{label}: time is {data.time}, expected {time}")
    return problems


def _separate_key_problems(parts: list[_Placed], scene: Any) -> list[str]:
    """Each part's keys, under their prefixed names (unnamed ones in order), set that part."""
    problems = []
    unnamed = [k for k in range(scene.nkey) if not _name(scene, mujoco.mjtObj.mjOBJ_KEY, k)]
    for index, part in enumerate(parts):
        for own, name in enumerate(part.key_names()):
            if name:
                key = mujoco.mj_name2id(scene, mujoco.mjtObj.mjOBJ_KEY, part.prefix + name)
                label = f"key {part.prefix + name!r}"
            else:
                key = unnamed.pop(0) if unnamed else -1
                label = f"{part.label}'s unnamed key #{own}"
            if key < 0:
                problems.append(f"{label} is missing")
                continue
            chosen: list[int | None] = [None] * len(parts)
            chosen[index] = own
            problems += _state_problems(parts, scene, key, chosen, label)
    return problems


def _file_problems(scene: Mujoco, together: Any, workdir: Path) -> list[str]:
    dumped = workdir / "dumped" / "scene.xml"
    dumped.parent.mkdir(parents=True)
    dump(scene, dumped)
    problems = [f"dumped: {p}" for p in same_model(dumped, together)]
    exported = export(scene, workdir / "exported")
    shutil.move(workdir / "exported", workdir / "moved")
    problems += [f"exported: {p}" for p in same_model(workdir / "moved" / exported.name, together)]
    return problems


def _merged_problems(
    robot: Part,
    places: tuple[Placement, ...],
    thing: tuple[Part, Placement] | None,
    parts: list[_Placed],
    attach: Attach,
) -> list[str]:
    """With ``keyframes="merged"``, a key name sets every part from its own key of that name.

    Unnamed keys go by place: the scene's n-th unnamed key sets each part from the
    part's n-th unnamed key, or its placed initial state where it has fewer.
    """
    try:
        together = compiled(_build(robot.model(), places, thing, attach, keyframes="merged"))
    except Exception as error:  # the check reports every failure, whatever its kind
        return [f"the merged scene does not build: {type(error).__name__}: {error}"]
    problems = _count_problems(parts, together, separate=False)
    names = sorted({name for part in parts for name in part.key_names() if name})
    for name in names:
        key = mujoco.mj_name2id(together, mujoco.mjtObj.mjOBJ_KEY, name)
        if key < 0:
            problems.append(f"merged key {name!r} is missing")
            continue
        chosen = [
            part.key_names().index(name) if name in part.key_names() else None for part in parts
        ]
        problems += _state_problems(parts, together, key, chosen, f"merged key {name!r}")
    unnamed = [k for k in range(together.nkey) if together.key(k).name == ""]
    for place, key in enumerate(unnamed):  # each part's unnamed keys, by their place
        chosen = [
            ([i for i, n in enumerate(part.key_names()) if not n][place:] or [None])[0]
            for part in parts
        ]
        problems += _state_problems(parts, together, key, chosen, f"merged unnamed key {place}")
    return problems


def main(arguments: list[str]) -> int:
    """Check each file given (a ``home`` key added to those without keys); print a summary."""
    passed = dict.fromkeys(STAGES, 0)
    for index, argument in enumerate(arguments):
        path = Path(argument).resolve()
        alone = mujoco.MjModel.from_xml_path(str(path))
        part = Part(path, () if alone.nkey else (("home", home_key(alone, index)),))
        point = ("site", "frame")[index % 2]
        with tempfile.TemporaryDirectory() as workdir:
            problems = scene_problems(part, point, Path(workdir))
        for stage, found in problems.items():
            passed[stage] += not found
            status = "ok" if not found else "FAILED"
            print(f"{status} {path.name} ({point}) {stage}: {'; '.join(found[:3])}")
    print(f"models {len(arguments)}; passed per stage: {passed}")
    return 0 if all(count == len(arguments) for count in passed.values()) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
