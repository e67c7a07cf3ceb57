"""Inertia rules (``I``): bodies too light for what acts on them at the model's timestep.

A body of tiny mass or inertia is not wrong in itself: MuJoCo integrates a milligram as
it integrates a tonne, and a model in centimetres and grams (dm_control's fruit fly) is
all small numbers. What goes wrong is a light body under a stiff servo, spring or
damper that MuJoCo integrates explicitly: once the joint's frequency times the timestep
passes 2 (for a servo of gain ``kp`` on a joint of inertia ``I``, ``sqrt(kp / I) * h``;
for a damping ``kv`` that the integrator does not treat implicitly, ``kv / I * h``), each
step overshoots more than the last and the simulation diverges.

MuJoCo decides: :func:`divergence` steps the model from ``qpos0`` beside a copy whose
velocities were nudged by a millionth, with contacts and gravity off (so that only the
model's own servos, springs, dampers and constraints act), and reports the joints whose
nudge grew a hundredfold in :data:`STEPS` steps. Growth is a ratio, so the rule does not
depend on the model's units. The message explains the growth from the compiled model:
the servo, spring or damper on the joint and the inertia MuJoCo's mass matrix gives it.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
import numpy.typing as npt

from mjcf_model.tools.lint.findings import Finding, rule
from mjcf_model.tools.lint.subject import Subject

if TYPE_CHECKING:
    import mujoco

__all__ = ["GROWTH", "LIMIT", "STEPS", "Term", "divergence", "stiffest_term"]

#: How many steps of the model's own timestep the nudged copy runs.
STEPS = 60
#: How much a nudge must grow in :data:`STEPS` steps to count as divergence (a step
#: that multiplies it by -1.08 or worse grows it this much; stable joints shrink it).
GROWTH = 100.0
#: The nudge, a fraction of a unit of each velocity.
NUDGE = 1e-6
#: Frequency (or explicit damping rate) times timestep from which explicit integration
#: diverges: 2 for MuJoCo's semi-implicit Euler (its velocities update before positions).
LIMIT = 2.0


def divergence(m: mujoco.MjModel) -> npt.NDArray[np.float64]:
    """How much a nudge to each degree of freedom grew in :data:`STEPS` steps from ``qpos0``.

    Contacts and gravity are switched off for the run (and switched back after). The
    run stops once a nudge has grown :data:`GROWTH`-fold (long before MuJoCo would
    stop it as unstable), so a diverging model costs a few steps.
    """
    import mujoco

    saved = m.opt.disableflags
    m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONTACT) | int(
        mujoco.mjtDisableBit.mjDSBL_GRAVITY
    )
    try:
        still, nudged = mujoco.MjData(m), mujoco.MjData(m)
        nudge = NUDGE * np.random.default_rng(0).uniform(0.5, 1.0, m.nv)
        nudged.qvel[:] += nudge
        growth = np.ones(m.nv)
        for _ in range(STEPS):
            mujoco.mj_step(m, still)
            mujoco.mj_step(m, nudged)
            growth = np.abs(nudged.qvel - still.qvel) / nudge
            if not growth.max() <= GROWTH:  # NaN counts as grown
                break
        return np.asarray(np.nan_to_num(growth, nan=math.inf))
    finally:
        m.opt.disableflags = saved


def _inverse_inertia(
    m: mujoco.MjModel, data: mujoco.MjData, direction: npt.NDArray[np.float64]
) -> float:
    """``direction`` against MuJoCo's inverse mass matrix: 1 / the inertia it moves."""
    import mujoco

    solved = np.zeros((1, m.nv))
    mujoco.mj_solveM(m, data, solved, direction.reshape(1, -1))
    return float(direction @ solved[0])


class Term(NamedTuple):
    """A servo, spring or damper on a joint, against the timestep."""

    #: What it is, in words (``actuator 'a' (kp 100)``).
    what: str
    #: Its frequency (or, for a damper, its damping rate) times the timestep.
    value: float
    #: The inertia the joint needs for :attr:`value` to reach only :data:`LIMIT`.
    needed: float
    #: Whether it is a damper (the integrator could treat it implicitly).
    damping: bool


def stiffest_term(subject: Subject, joint: int) -> Term | None:
    """The servo, spring or explicit damper on ``joint`` nearest to diverging, if any.

    ``None`` when nothing on the joint is integrated explicitly.
    """
    import mujoco

    m = subject.physics
    data = mujoco.MjData(m)
    mujoco.mj_forward(m, data)
    h = float(m.opt.timestep)
    dof = int(m.jnt_dofadr[joint])
    explicit_damping = int(m.opt.integrator) in (
        int(mujoco.mjtIntegrator.mjINT_EULER),
        int(mujoco.mjtIntegrator.mjINT_RK4),
    )
    moments = np.zeros((m.nu, m.nv))
    if m.nu:
        mujoco.mju_sparse2dense(
            moments,
            data.actuator_moment,
            data.moment_rownnz,
            data.moment_rowadr,
            data.moment_colind,
        )
    terms: list[Term] = []
    unit = np.zeros(m.nv)
    unit[dof] = 1.0
    stiffness = float(m.jnt_stiffness[joint])
    if stiffness > 0:
        w = _inverse_inertia(m, data, unit)
        what = f"its stiffness {stiffness:.6g}"
        terms.append(Term(what, math.sqrt(stiffness * w) * h, stiffness * h * h / 4, False))
    for actuator in range(m.nu):
        moment = moments[actuator]
        if not moment[dof] or int(m.actuator_biastype[actuator]) != 1:
            continue
        w = _inverse_inertia(m, data, moment)
        name = f"actuator {subject.name('actuator', actuator)}"
        kp, kv = -float(m.actuator_biasprm[actuator, 1]), -float(m.actuator_biasprm[actuator, 2])
        if kp > 0:
            terms.append(
                Term(f"{name} (kp {kp:.6g})", math.sqrt(kp * w) * h, kp * h * h / 4, False)
            )
        if kv > 0 and explicit_damping:
            terms.append(Term(f"{name} (kv {kv:.6g})", kv * w * h, kv * h / 2, True))
    return max(terms, key=lambda term: term.value) if terms else None


@rule(
    "I101",
    "light-body-diverges",
    "error",
    "a body too light for the servo, spring or damper on its joint: stepping at the "
    "model's timestep diverges",
)
def light_body_diverges(subject: Subject) -> Iterator[Finding]:
    """Joints whose motion MuJoCo's integration amplifies step after step.

    One finding for each joint whose own servo, spring or damper is past the limit
    (the joints it drags along are named in it); one for the joint that grew most
    when no such term explains the growth.
    """
    m = subject.physics
    if not m.nv:
        return
    growth = divergence(m)
    grown = {int(m.dof_jntid[dof]): float(growth[dof]) for dof in np.flatnonzero(growth > GROWTH)}
    if not grown:
        return
    terms = {joint: stiffest_term(subject, joint) for joint in grown}
    causes = [joint for joint, term in terms.items() if term is not None and term.value >= LIMIT]
    for joint in causes or [max(grown, key=grown.__getitem__)]:
        body = int(m.jnt_bodyid[joint])
        how = "without bound" if math.isinf(grown[joint]) else f"{grown[joint]:.3g}-fold"
        message = (
            f"joint {subject.name('joint', joint)} of body {subject.name('body', body)} "
            f"(mass {float(m.body_mass[body]):.3g}): a nudge to it grows {how} within {STEPS} "
            f"steps of the timestep {float(m.opt.timestep):.6g} (contacts and gravity "
            "off): the simulation diverges"
        )
        term = terms[joint]
        if term is not None and term.value >= LIMIT:
            rate = "damping rate" if term.damping else "frequency"
            message += (
                f"; {term.what} gives it a {rate} times timestep of {term.value:.3g}, and "
                f"MuJoCo's integration diverges from {LIMIT:g}: give the joint an inertia "
                f"of at least {term.needed:.3g} (a heavier body, or armature), lower the "
                "gain, or shorten the timestep"
            )
            if term.damping:
                message += " (or integrate damping implicitly: integrator='implicitfast')"
        else:
            message += "; make its body heavier, its servos softer, or the timestep shorter"
        dragged = [subject.name("joint", other) for other in grown if other not in causes]
        if causes and dragged:
            message += f" (it drags {', '.join(dragged)} along)"
        yield subject.finding("I101", ("joint", joint), message)
