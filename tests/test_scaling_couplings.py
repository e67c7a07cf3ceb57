"""Scaled tendons and tendon couplings behave as the original scaled, MuJoCo measuring.

A spatial tendon's length is a length; a fixed one's is a length when a slide
joint is in it and an angle over hinges alone. MuJoCo computes every tendon's
length and every equality's violation at the same configurations of the
original and the scaled model (slide coordinates scaled).
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model.transforms.scaling.transform import scaled
from serializers import dumps, loads
from tests.support.scaling_oracle import scaled_model_problems

#: Slide joints on two axes and a hinge; a spatial tendon whose spring length MuJoCo
#: measures (``-1 -1``); fixed tendons over hinges only, slides only and both; tendon
#: couplings between every kind, and one alone.
_MODEL = """<mujoco><worldbody><body><joint name="x" type="slide" axis="1 0 0" ref="0.1"/>
<joint name="h" type="hinge" axis="0 1 0" ref="0.3"/><geom size="0.1"/><site name="a"/>
<body pos="0 0 1"><joint name="z" type="slide"/><geom size="0.1"/><site name="b" pos="0.2 0 0"/>
</body></body></worldbody><tendon>
<spatial name="rope" springlength="-1 -1" stiffness="1"><site site="a"/><site site="b"/></spatial>
<fixed name="hinges"><joint joint="h" coef="1.5"/></fixed>
<fixed name="slides" range="-1 1" limited="true"><joint joint="x" coef="2"/>
<joint joint="z" coef="-1"/></fixed>
<fixed name="mixed" range="-0.5 0.5" limited="true" springlength="0.2">
<joint joint="x" coef="2"/><joint joint="h" coef="0.25"/></fixed></tendon>
<equality><tendon tendon1="rope" tendon2="hinges" polycoef="0.1 0.2 0.3 0.4 0.5"/>
<tendon tendon1="hinges" tendon2="mixed" polycoef="0.1 0.2 0.3"/>
<tendon tendon1="mixed" tendon2="slides" polycoef="0.05 -1 0.5"/>
<tendon tendon1="slides" tendon2="rope"/><tendon tendon1="mixed" polycoef="0.3"/>
</equality></mujoco>"""

#: Each tendon's length is a length (True) or an angle (False).
_LENGTHS = {"rope": True, "hinges": False, "slides": True, "mixed": True}


def _measured(model: mujoco.MjModel, qpos: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Tendon lengths and equality violations MuJoCo computes at ``qpos``."""
    data = mujoco.MjData(model)
    data.qpos[:] = qpos
    mujoco.mj_forward(model, data)
    rows = data.efc_type[: data.nefc] == mujoco.mjtConstraint.mjCNSTR_EQUALITY
    violations = np.zeros(model.neq)
    violations[data.efc_id[: data.nefc][rows]] = data.efc_pos[: data.nefc][rows]
    return data.ten_length.copy(), violations


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_tendons_and_their_couplings_measure_the_scaled_lengths(factor: float) -> None:
    """At every configuration each tendon measures ``factor`` times (an angle: the same) its length.

    Each tendon coupling's violation is in its first tendon's unit, so it scales with it.
    """
    original = mujoco.MjModel.from_xml_string(_MODEL)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(_MODEL), factor)))
    assert scaled_model_problems(original, changed, factor) == []
    tendons = np.array([factor if _LENGTHS[original.tendon(i).name] else 1.0 for i in range(4)])
    slides = np.where(original.jnt_type == mujoco.mjtJoint.mjJNT_SLIDE, factor, 1.0)
    for qpos in np.random.default_rng(7).uniform(-1, 1, (5, original.nq)):
        lengths, violations = _measured(original, qpos)
        lengths_after, violations_after = _measured(changed, slides * qpos)
        assert np.allclose(lengths_after, tendons * lengths, rtol=1e-9, atol=1e-12)
        first = tendons[original.eq_obj1id]
        assert np.allclose(violations_after, first * violations, rtol=1e-9, atol=1e-12)
