"""Tendon lengths given by default classes are written, scaled, on the tendons they measure.

The default ``<tendon>`` is shared by spatial and fixed tendons, and a fixed
tendon's length is a length only with a slide joint in it, so a class's
``range``, ``springlength`` and ``margin`` stay in the class; each tendon whose
length is a length writes them scaled. MuJoCo compiles the scaled model to the
original scaled: the fixed tendon over a slide and the spatial tendon measure
twice their ranges, the fixed tendon over a hinge keeps its class's.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model.transforms.scaling.transform import scaled
from serializers import dumps, loads
from tests.support.scaling_oracle import scaled_model_problems

_MODEL = """<mujoco><default><tendon range="-.5 .5" limited="true" margin=".01"/>
  <default class="sprung"><tendon springlength=".2" stiffness="10"/></default></default>
<worldbody><body><joint name="s" type="slide" axis="1 0 0"/><joint name="h" type="hinge"/>
  <geom size=".1"/><site name="a"/><body pos="0 0 1"><joint type="slide"/><geom size=".1"/>
  <site name="b"/></body></body></worldbody>
<tendon><fixed name="slide" class="sprung"><joint joint="s" coef="1"/></fixed>
  <fixed name="hinge" class="sprung"><joint joint="h" coef="1"/></fixed>
  <spatial name="rope"><site site="a"/><site site="b"/></spatial></tendon></mujoco>"""


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_class_tendon_lengths_scale_on_the_tendons_measuring_lengths(factor: float) -> None:
    """The slide and spatial tendons' ranges, margins and spring lengths scale; the hinge's stay."""
    original = mujoco.MjModel.from_xml_string(_MODEL)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(_MODEL), factor)))
    assert scaled_model_problems(original, changed, factor) == []
    lengths = np.array([factor, 1.0, factor])  # slide, hinge, rope
    np.testing.assert_allclose(changed.tendon_range, original.tendon_range * lengths[:, None])
    np.testing.assert_allclose(changed.tendon_margin, original.tendon_margin * lengths)
    np.testing.assert_allclose(
        changed.tendon_lengthspring[:2], original.tendon_lengthspring[:2] * lengths[:2, None]
    )
