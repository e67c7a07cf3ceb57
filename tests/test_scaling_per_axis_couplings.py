"""Per-axis factors: a joint coupling's coefficients follow each slide's own axis.

A slide's coordinate scales by the factor along its axis (MuJoCo's kinematics
show it: ``test_per_axis_factors_scale_axis_aligned_slides_exactly``), so in
``y1 = a0 + a1 y2 + ... + a4 y2**4`` each ``a_k`` scales by ``f1 / f2**k``, where
``f1`` and ``f2`` are the factors along the two joints' axes (MuJoCo's default
axis is ``z``, a class may give another). MuJoCo compiles the coefficients into
``eq_data``.
"""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model.transforms.scaling.transform import scaled
from serializers import dumps, loads
from tests.support.scaling_oracle import ALIGNED_SLIDES

#: Couplings between the x, y (axis from its class) and z slides, and of x alone.
_COUPLINGS = """<equality><joint joint1="x" joint2="z" polycoef=".1 .5 .2 0 0"/>
  <joint joint1="z" joint2="y" polycoef=".2 2 0 .3 0"/><joint joint1="x" polycoef=".3"/>
</equality>"""


def test_joint_couplings_scale_by_the_factors_along_each_slide() -> None:
    """The slide x scales by 2, y by 3, z by 5: each coefficient by ``f1 / f2**k``."""
    text = ALIGNED_SLIDES.replace("<keyframe>", f"{_COUPLINGS}<keyframe>")
    factors = np.array([2.0, 3.0, 5.0])
    original = mujoco.MjModel.from_xml_string(text)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(text), factors)))
    along = dict(zip(("x", "z", "y"), np.abs(original.jnt_axis) @ factors, strict=True))
    assert along == {"x": 2.0, "z": 5.0, "y": 3.0}
    powers = np.arange(5)
    expected = [
        along["x"] / along["z"] ** powers,
        along["z"] / along["y"] ** powers,
        [along["x"], 1, 1, 1, 1],  # alone: only a0, the position it holds x at, is read
    ]
    np.testing.assert_allclose(
        changed.eq_data[:, :5], original.eq_data[:, :5] * np.array(expected), rtol=1e-12
    )
