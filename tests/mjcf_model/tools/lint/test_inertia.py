"""Tests of the inertia rule: a body too light for its servo is found, and MuJoCo diverges.

The referee is MuJoCo stepping the model as a user does (gravity and contacts on, the
servo asked to move): what the rule finds blows up there, and the fix its message
gives (an inertia of at least the number it prints, as armature) runs steadily and is
not found.
"""

from __future__ import annotations

import math
import re

import mujoco
import numpy as np
import pytest

from mjcf_model import loads
from mjcf_model.tools.lint import lint
from mjcf_model.tools.lint.inertia import GROWTH, divergence, stiffest_term
from mjcf_model.tools.lint.subject import Subject

#: A palm with one finger: the finger's mass, the servo and the integrator are filled in.
FINGER = """
<mujoco>
  <option timestep="0.002" integrator="{integrator}"/>
  <worldbody>
    <geom type="plane" size="1 1 .1"/>
    <body name="palm" pos="0 0 .5">
      <geom size=".05" mass="1"/>
      <body name="finger" pos="0 0 .06">
        <joint name="knuckle" axis="0 1 0" armature="{armature}"/>
        <geom type="capsule" fromto="0 0 0 0 0 .04" size=".005" mass="{mass}"/>
      </body>
    </body>
  </worldbody>
  <actuator><position name="servo" joint="knuckle" {gains}/></actuator>
</mujoco>
"""


def finger(
    mass: float = 1e-4,
    gains: str = 'kp="50"',
    integrator: str = "Euler",
    armature: float = 0.0,
) -> str:
    """The finger model's text."""
    return FINGER.format(mass=mass, gains=gains, integrator=integrator, armature=armature)


def diverges_as_a_user_runs_it(text: str, seconds: float = 1.0) -> bool:
    """Whether MuJoCo gives up on the model (a huge or invalid acceleration) within ``seconds``.

    Gravity and contacts on, the servo asked to a new angle, as a user runs it.
    """
    m = mujoco.MjModel.from_xml_string(text)
    data = mujoco.MjData(m)
    data.ctrl[:] = 0.3
    for _ in range(round(seconds / m.opt.timestep)):
        mujoco.mj_step(m, data)
        if data.warning[mujoco.mjtWarning.mjWARN_BADQACC].number:
            return True
    return not np.isfinite(data.qpos).all()


@pytest.mark.parametrize(
    "gains, integrator",
    [('kp="50"', "Euler"), ('kp="50"', "implicitfast"), ('kp="1" kv="1"', "Euler")],
)
def test_a_light_finger_under_a_stiff_servo_is_found_and_diverges(
    gains: str, integrator: str
) -> None:
    """I101 at the joint; MuJoCo's run blows up; the armature the message asks for cures both."""
    text = finger(gains=gains, integrator=integrator)
    (found,) = lint(loads(text), select=["I"])
    assert found.rule == "I101" and found.severity == "error"
    assert found.path == (
        "/mujoco/worldbody/body[@name='palm']/body[@name='finger']/joint[@name='knuckle']"
    )
    assert "actuator 'servo'" in found.message and "finger" in found.message
    assert diverges_as_a_user_runs_it(text)
    match = re.search(r"an inertia of at least ([0-9.e+-]+)", found.message)
    assert match is not None, found.message
    cured = finger(gains=gains, integrator=integrator, armature=1.5 * float(match.group(1)))
    assert lint(loads(cured), select=["I"]) == []
    assert not diverges_as_a_user_runs_it(cured)


def test_damping_integrated_implicitly_is_not_found() -> None:
    """The damper that diverges under Euler runs steadily under implicitfast, found only there."""
    euler, implicit = (
        finger(gains='kp="1" kv="1"', integrator=i) for i in ("Euler", "implicitfast")
    )
    assert [f.rule for f in lint(loads(euler), select=["I"])] == ["I101"]
    assert lint(loads(implicit), select=["I"]) == []
    assert diverges_as_a_user_runs_it(euler) and not diverges_as_a_user_runs_it(implicit)


@pytest.mark.parametrize("mass", [1e-9, 1e-2, 10.0])
def test_a_light_body_that_nothing_stiff_acts_on_is_not_found(mass: float) -> None:
    """Lightness alone is no mistake: a milligram under a soft servo runs as a kilogram does."""
    text = finger(mass=mass, gains=f'kp="{mass * 1e-3}"')
    assert lint(loads(text), select=["I"]) == []
    assert not diverges_as_a_user_runs_it(text)


def test_divergence_is_a_ratio_and_leaves_the_options_as_they_were() -> None:
    """The nudge grows past the bar only where the rule finds; the model's flags are restored."""
    m = mujoco.MjModel.from_xml_string(finger())
    flags = int(m.opt.disableflags)
    assert divergence(m).max() > GROWTH
    assert int(m.opt.disableflags) == flags
    assert divergence(mujoco.MjModel.from_xml_string(finger(mass=1.0))).max() < GROWTH


def test_the_stiffest_term_is_the_servo_with_its_frequency_times_timestep() -> None:
    """``sqrt(kp / I) * h`` with the inertia MuJoCo's mass matrix gives the joint."""
    subject = Subject(loads(finger()))
    inertia = 1 / subject.physics.dof_invweight0[0]
    term = stiffest_term(subject, 0)
    assert term is not None
    assert term.what == "actuator 'servo' (kp 50)" and not term.damping
    assert term.value == pytest.approx(math.sqrt(50 / inertia) * 0.002)
    assert term.needed == pytest.approx(50 * 0.002**2 / 4)
    damper = stiffest_term(Subject(loads(finger(gains='kp="1" kv="1"'))), 0)
    assert damper is not None and damper.what == "actuator 'servo' (kv 1)" and damper.damping
    assert stiffest_term(Subject(loads(finger(gains='kp="0"'))), 0) is None
