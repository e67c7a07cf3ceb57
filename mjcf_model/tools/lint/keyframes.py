"""Keyframe rules (``K``): keys MuJoCo loads without a word, though they cannot be meant.

Each reads the compiled keys (``key_qpos``, ``key_ctrl``) against the compiled joints
and actuators, so default classes, ``autolimits`` and degrees are as MuJoCo has them.
A key is checked for what it writes: a key without ``qpos`` starts from ``qpos0``,
which these rules do not judge.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
from numpy.typing import NDArray

from mjcf_model.nodes.base import get_attribute
from mjcf_model.serializers.parsed_elements import written_text
from mjcf_model.tools.lint.findings import Finding, rule
from mjcf_model.tools.lint.subject import Subject
from mjcf_model.values import numbers_of

__all__ = ["SERVO_TOLERANCE", "keys_writing", "servo_target"]

#: How far (relative to a joint's range, or to 1 for an unlimited one) a value may stand
#: outside a range before it counts: text rounded to six digits stays inside.
_RANGE_TOLERANCE = 1e-6
#: The most a value's written rounding may excuse, relative to the range (a thousandth:
#: ``1.571`` for pi/2 is at its limit, ``1.6`` is not).
_ROUNDING = 1e-3
#: How far a quaternion's length may be from 1 (four written digits reach 1e-4).
_UNIT_TOLERANCE = 1e-3
#: How far a position servo's key ``ctrl`` may be from its joint's key position, relative
#: to its control range (or to 1): a thousandth, 0.06 degrees on a hinge without a range.
SERVO_TOLERANCE = 1e-3


def keys_writing(subject: Subject, attribute: str) -> Iterator[int]:
    """The rows of the keys whose element writes ``attribute`` (``qpos``, ``ctrl``...)."""
    for key in range(subject.physics.nkey):
        found = subject.element(("key", key))
        if found is not None and get_attribute(found[0], attribute) is not None:
            yield key


def _unit(joint_type: int) -> str:
    import mujoco

    if joint_type == mujoco.mjtJoint.mjJNT_BALL:
        return " rad (its rotation angle)"
    return " rad" if joint_type == mujoco.mjtJoint.mjJNT_HINGE else " m"


def _rotation_angle(quaternion: NDArray[np.float64]) -> float:
    """The angle a (not necessarily unit) quaternion turns by, in radians."""
    length = max(float(np.linalg.norm(quaternion)), 1e-300)
    return 2 * math.acos(min(1.0, abs(float(quaternion[0])) / length))


@rule(
    "K101",
    "key-qpos-out-of-range",
    "error",
    "a key puts a limited joint outside its range",
)
def qpos_out_of_range(subject: Subject) -> Iterator[Finding]:
    """A hinge, slide or ball joint a key's ``qpos`` puts beyond its limits.

    MuJoCo starts the simulation there, and the limit constraint pushes the joint back
    at the first step. A value counts as at its limit when it rounds there as written
    (``1.571`` for a limit of pi/2): the slack is half a unit of its last written digit,
    at most :data:`_ROUNDING` of the range.
    One finding a key, naming each joint.
    """
    import mujoco

    m = subject.physics
    for key in keys_writing(subject, "qpos"):
        qpos = m.key_qpos[key]
        digits = _written_digits(subject, key, "qpos")
        outside = []
        for joint in np.flatnonzero(m.jnt_limited):
            kind, address = int(m.jnt_type[joint]), int(m.jnt_qposadr[joint])
            low, high = (float(v) for v in m.jnt_range[joint])
            if kind == mujoco.mjtJoint.mjJNT_BALL:
                value, low = _rotation_angle(qpos[address : address + 4]), 0.0
            elif kind in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE):
                value = float(qpos[address])
            else:
                continue
            scale = max(1.0, high - low)
            rounded = min(digits.get(address, 0.0), _ROUNDING * scale)
            slack = max(_RANGE_TOLERANCE * scale, rounded)
            if low - slack <= value <= high + slack:
                continue
            outside.append(
                f"{subject.name('joint', int(joint))} at {value:.6g}{_unit(kind)} "
                f"(range {low:.6g} to {high:.6g})"
            )
        if outside:
            yield subject.finding(
                "K101",
                ("key", key),
                f"key {subject.name('key', key)} puts {_listed(outside, 'joint')} outside "
                "its range: MuJoCo starts there and the limit pushes the joint back at the "
                "first step; move the values into the ranges (or widen the ranges)",
            )


def _listed(items: list[str], noun: str) -> str:
    """``items`` in a sentence: ``joint a`` or ``3 joints: a, b, c``.

    Examples:
        >>> _listed(["'a' at 1"], "joint"), _listed(["'a' at 1", "'b' at 2"], "joint")
        ("joint 'a' at 1", "2 joints: 'a' at 1, 'b' at 2")

    """
    if len(items) == 1:
        return f"{noun} {items[0]}"
    shown = ", ".join(items[:6]) + (f" and {len(items) - 6} more" if len(items) > 6 else "")
    return f"{len(items)} {noun}s: {shown}"


def _written_digits(subject: Subject, key: int, attribute: str) -> dict[int, float]:
    """Half a unit of the last digit each number of the key's ``attribute`` is written to.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads("<mujoco><worldbody><body><joint/><joint/><geom size='1'/></body>"
        ...     "</worldbody><keyframe><key qpos='1.571 2'/></keyframe></mujoco>")
        >>> _written_digits(Subject(model), 0, "qpos")
        {0: 0.0005, 1: 0.5}

    """
    found = subject.element(("key", key))
    text = written_text(found[0], attribute) if found is not None else None
    if text is None:
        return {}
    slack = {}
    for index, token in enumerate(text.split()):
        mantissa, _, exponent = token.lower().partition("e")
        decimals = len(mantissa.partition(".")[2])
        try:
            power = int(exponent) if exponent else 0
        except ValueError:
            continue
        slack[index] = 0.5 * 10.0 ** (power - decimals)
    return slack


@rule(
    "K102",
    "key-quaternion-not-unit",
    "error",
    "a key writes a free or ball joint's quaternion that is not of unit length",
)
def quaternion_not_unit(subject: Subject) -> Iterator[Finding]:
    """A free or ball joint's quaternion written in a key's ``qpos`` whose length is not 1.

    MuJoCo's compiler normalises it without a word (the compiled ``key_qpos`` holds the
    unit quaternion; a quaternion of zeros becomes the identity): a value that was not
    meant as written, such as a position shifted into the quaternion, turns the body.
    """
    import mujoco

    m = subject.physics
    for key in keys_writing(subject, "qpos"):
        written = _written(subject, key, "qpos")
        for joint in range(m.njnt):
            kind, address = int(m.jnt_type[joint]), int(m.jnt_qposadr[joint])
            if kind == mujoco.mjtJoint.mjJNT_FREE:
                address += 3
            elif kind != mujoco.mjtJoint.mjJNT_BALL:
                continue
            if address + 4 > len(written):
                continue
            quaternion = written[address : address + 4]
            length = math.sqrt(sum(v * v for v in quaternion))
            if abs(length - 1) <= _UNIT_TOLERANCE:
                continue
            text = " ".join(f"{v:.6g}" for v in quaternion)
            made = " ".join(f"{v:.6g}" for v in m.key_qpos[key, address : address + 4])
            yield subject.finding(
                "K102",
                ("key", key),
                f"key {subject.name('key', key)} gives joint {subject.name('joint', joint)} the "
                f"quaternion {text}, of length {length:.6g}: MuJoCo makes it {made} without "
                "a word; write the unit quaternion meant (w x y z; the identity is 1 0 0 0)",
            )


def _written(subject: Subject, key: int, attribute: str) -> list[float]:
    """The numbers the element of key ``key`` writes in ``attribute`` (none: ``[]``)."""
    found = subject.element(("key", key))
    values = numbers_of(get_attribute(found[0], attribute)) if found is not None else None
    return [float(v) for v in values] if values else []


#: Each array a key writes, and the compiled size it has per key.
_KEY_SIZES = (
    ("qpos", "nq"),
    ("qvel", "nv"),
    ("act", "na"),
    ("ctrl", "nu"),
    ("mpos", "nmocap", 3),
    ("mquat", "nmocap", 4),
)


#: What MuJoCo fills a short key's array with.
_FILLED = {
    "qpos": "qpos0",
    "qvel": "zeros",
    "act": "zeros",
    "ctrl": "zeros",
    "mpos": "the mocap bodies' own positions",
    "mquat": "the mocap bodies' own orientations",
}


@rule(
    "K105",
    "key-too-short",
    "error",
    "a key writes fewer numbers than the model has, and MuJoCo fills in the rest",
)
def key_too_short(subject: Subject) -> Iterator[Finding]:
    """A key's ``qpos`` (``qvel``, ``act``, ``ctrl``, ``mpos``, ``mquat``) shorter than the model's.

    MuJoCo fills the rest from ``qpos0`` (zeros for velocities and controls) without a
    word: the key was written before joints or actuators were added, and its values now
    land on the wrong ones wherever the new ones came first.
    """
    m = subject.physics
    for key in range(m.nkey):
        for attribute, count, *width in _KEY_SIZES:
            size = int(getattr(m, count)) * (width[0] if width else 1)
            written = len(_written(subject, key, attribute))
            if 0 < written < size:
                yield subject.finding(
                    "K105",
                    ("key", key),
                    f"key {subject.name('key', key)} writes {written} numbers in {attribute}, "
                    f"but the model has {size}: MuJoCo fills in the last {size - written} "
                    f"with {_FILLED[attribute]}; write all {size} (were joints or actuators "
                    "added after the key was written?)",
                )


@rule(
    "K103",
    "key-ctrl-out-of-range",
    "error",
    "a key sets a control outside its actuator's ctrlrange",
)
def ctrl_out_of_range(subject: Subject) -> Iterator[Finding]:
    """A key's ``ctrl`` outside a control-limited actuator's ``ctrlrange``: MuJoCo clamps it."""
    m = subject.physics
    for key in keys_writing(subject, "ctrl"):
        for actuator in np.flatnonzero(m.actuator_ctrllimited):
            low, high = (float(v) for v in m.actuator_ctrlrange[actuator])
            value = float(m.key_ctrl[key, actuator])
            slack = _RANGE_TOLERANCE * max(1.0, high - low)
            if low - slack <= value <= high + slack:
                continue
            yield subject.finding(
                "K103",
                ("key", key),
                f"key {subject.name('key', key)} sets actuator "
                f"{subject.name('actuator', int(actuator))} to {value:.6g}, outside its "
                f"ctrlrange [{low:.6g}, {high:.6g}]: MuJoCo clamps it to "
                f"{min(max(value, low), high):.6g}; write a value in the range",
            )


def servo_target(subject: Subject, actuator: int, qpos: NDArray[np.float64]) -> float | None:
    """The control that holds a position servo's joint where ``qpos`` has it; ``None``: no servo.

    A position servo (``<position>``, or a ``<general>`` written like one) pulls
    ``gear * q`` towards its control: its gain is fixed at ``kp > 0``, its bias affine
    with ``-kp`` on the length and none on its own, on a hinge or slide joint. The
    target is clamped into ``ctrlrange`` where the control is limited.
    """
    import mujoco

    m = subject.physics
    if (
        int(m.actuator_trntype[actuator]) != mujoco.mjtTrn.mjTRN_JOINT
        or int(m.actuator_gaintype[actuator]) != mujoco.mjtGain.mjGAIN_FIXED
        or int(m.actuator_biastype[actuator]) != mujoco.mjtBias.mjBIAS_AFFINE
    ):
        return None
    kp = float(m.actuator_gainprm[actuator, 0])
    bias = m.actuator_biasprm[actuator]
    if kp <= 0 or bias[0] != 0 or not math.isclose(float(bias[1]), -kp, rel_tol=1e-9):
        return None
    joint = int(m.actuator_trnid[actuator, 0])
    if int(m.jnt_type[joint]) not in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE):
        return None
    target = float(m.actuator_gear[actuator, 0]) * float(qpos[m.jnt_qposadr[joint]])
    if m.actuator_ctrllimited[actuator]:
        low, high = (float(v) for v in m.actuator_ctrlrange[actuator])
        target = min(max(target, low), high)
    return target


@rule(
    "K104",
    "key-ctrl-servo-mismatch",
    "error",
    "a key's control for a position servo differs from where the key puts its joint",
)
def ctrl_servo_mismatch(subject: Subject) -> Iterator[Finding]:
    """Position servos whose key ``ctrl`` is not their joint's key position, and pull it away.

    A servo's control may differ from its joint's position on purpose: a key recorded
    from a simulation holds an arm against gravity with the servo's steady offset. So
    MuJoCo decides: it runs the key with its own controls for two natural periods of
    the slowest mismatched servo (:func:`_reach`), and a servo counts only where its
    joint moves towards the key's control by more than half the mismatch (an offset that
    holds the arm barely moves it; a control left at zero, or another joint's, pulls it
    all the way). One finding a key.
    """
    m = subject.physics
    writing_ctrl = set(keys_writing(subject, "ctrl"))
    for key in keys_writing(subject, "qpos"):
        if key not in writing_ctrl:
            continue
        targets = {a: servo_target(subject, a, m.key_qpos[key]) for a in range(m.nu)}
        mismatched = []
        for actuator, target in targets.items():
            if target is None:
                continue
            value = float(m.key_ctrl[key, actuator])
            limited = bool(m.actuator_ctrllimited[actuator])
            span = float(np.ptp(m.actuator_ctrlrange[actuator])) if limited else 1.0
            if abs(value - target) > SERVO_TOLERANCE * max(1.0, span):
                mismatched.append((actuator, value, target))
        if not mismatched:
            continue
        reach = _reach(subject, key, mismatched)
        pulled = [
            (actuator, value, target)
            for (actuator, value, target), toward in zip(mismatched, reach, strict=True)
            if toward > 0.5 * abs(value - target)
        ]
        if not pulled:
            continue
        described = [
            f"{subject.name('actuator', a)} at {v:.6g}, its joint where the control is "
            f"{t:.6g}{_hint(subject, targets, a, v)}"
            for a, v, t in pulled
        ]
        yield subject.finding(
            "K104",
            ("key", key),
            f"key {subject.name('key', key)} sets {_listed(described, 'position servo')}: "
            "run from the key, MuJoCo moves each servo's joint away from the key's pose "
            "towards the key's control; set each ctrl to its joint's control (or the pose "
            "to the controls)",
        )


def _reach(subject: Subject, key: int, servos: list[tuple[int, float, float]]) -> list[float]:
    """How far each servo's length goes towards the key's control, run from the key.

    MuJoCo steps the key with its own controls for two natural periods of the slowest
    servo (``2 pi sqrt(M / (kp gear^2))``, ``M`` its joint's inertia at ``qpos0``,
    MuJoCo's ``dof_M0``; between 0.2 and 5 s): each entry is the furthest the servo's
    length (gear times joint position) went from the key towards the servo's control,
    in control units.
    """
    import mujoco

    m = subject.physics
    data = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, data, key)
    gear = [float(m.actuator_gear[a, 0]) for a, _, _ in servos]
    joints = [int(m.actuator_trnid[a, 0]) for a, _, _ in servos]
    periods = []
    for (actuator, _, _), g, joint in zip(servos, gear, joints, strict=True):
        dof = int(m.jnt_dofadr[joint])
        inertia = float(m.dof_M0[dof])
        stiffness = float(m.actuator_gainprm[actuator, 0]) * g * g
        periods.append(2 * math.pi * math.sqrt(inertia / stiffness))
    duration = min(max(2 * max(periods), 0.2), 5.0)
    address = [int(m.jnt_qposadr[joint]) for joint in joints]
    start = [g * float(data.qpos[i]) for g, i in zip(gear, address, strict=True)]
    sign = [float(np.sign(value - target)) for _, value, target in servos]
    furthest = [0.0] * len(servos)
    for _ in range(max(1, min(10_000, round(duration / m.opt.timestep)))):
        mujoco.mj_step(m, data)
        for index, (g, i) in enumerate(zip(gear, address, strict=True)):
            toward = sign[index] * (g * float(data.qpos[i]) - start[index])
            furthest[index] = max(furthest[index], toward)
    return furthest


def _hint(subject: Subject, targets: dict[int, float | None], actuator: int, value: float) -> str:
    """Why a servo's control may be wrong: left at zero, or another servo's target."""
    if value == 0:
        return " (its ctrl left at zero?)"
    for other, target in targets.items():
        if other != actuator and target is not None and math.isclose(value, target, abs_tol=1e-6):
            return f" (the control of {subject.name('actuator', other)}: actuators reordered?)"
    return ""
