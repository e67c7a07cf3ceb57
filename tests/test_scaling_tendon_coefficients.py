"""A fixed tendon's ``coef`` changes only where the tendon's unit and its joint's differ.

Over slides alone (or hinges alone) a fixed tendon's length is in its joints'
units, so under a uniform factor no coefficient changes and the tendon section
is shared by the scaled model, unchanged; MuJoCo compiles that model to the
original scaled. A ``coef`` read without its tendon cannot be placed and is kept.
"""

from __future__ import annotations

import mujoco

from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.rules import RULES
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.defaults import DefaultClasses
from serializers import dumps, loads
from tests.support.scaling_oracle import scaled_model_problems

#: Fixed tendons over two slides and over two hinges, no length written.
_MODEL = """<mujoco><worldbody><body>
  <joint name="x" type="slide" axis="1 0 0"/><joint name="z" type="slide"/>
  <joint name="h" type="hinge" axis="0 1 0"/><joint name="k" type="hinge"/><geom size=".1"/>
</body></worldbody>
<tendon><fixed name="slides"><joint joint="x" coef="2"/><joint joint="z" coef="-1"/></fixed>
  <fixed name="hinges"><joint joint="h" coef="1.5"/><joint joint="k" coef="1"/></fixed>
</tendon></mujoco>"""


def test_fixed_tendons_in_their_joints_units_are_shared_unchanged() -> None:
    """Uniform scaling: the tendon section is the original's, and MuJoCo agrees."""
    model = loads(_MODEL)
    result = scaled(model, 2.0)
    assert result.tendon is model.tendon
    original = mujoco.MjModel.from_xml_string(_MODEL)
    changed = mujoco.MjModel.from_xml_string(dumps(result))
    assert scaled_model_problems(original, changed, 2.0) == []


def test_a_coefficient_ruled_without_its_tendon_is_kept() -> None:
    """Without the tendon around it, the coefficient's unit is unknown: nothing changes."""
    model = loads(_MODEL)
    context = ScaleContext(factors=(2.0, 3.0, 5.0), classes=DefaultClasses.of(model), model=model)
    for coefficient in model.tendon.elements[0].elements:
        assert RULES["tendon/fixed/joint"](coefficient, (), context) == {}
