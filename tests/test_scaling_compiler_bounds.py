"""The compiler's ``boundmass`` and ``boundinertia`` scale as the masses and inertias they bound.

``<compiler>`` keeps both as text (its typed class does not model them); they
scale all the same: ``boundinertia`` with the length squared (times the mass
factor), ``boundmass`` with the mass factor. A body lighter than the bound
compiles to the bound, so MuJoCo's compiled mass and inertia of such a body
are the original's scaled.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model.nodes.base import get_attribute
from mjcf_model.transforms.scaling.transform import MassPolicy, scaled
from serializers import dumps, loads
from tests.support.scaling_oracle import scaled_model_problems

#: A body whose mass and inertia MuJoCo raises to the bounds, and one above them.
_MODEL = """<mujoco><compiler boundmass="0.5" boundinertia="0.01"/><worldbody>
  <body name="tiny"><freejoint/><geom size=".001" density="1"/></body>
  <body name="big" pos="1 0 0"><freejoint/><geom size=".2"/></body>
</worldbody></mujoco>"""


@pytest.mark.parametrize(("mass", "mass_factor"), [("keep", 1.0), ("volume", 8.0)])
def test_compiler_bounds_written_as_text_scale_with_what_they_bound(
    mass: MassPolicy, mass_factor: float
) -> None:
    """Scaled by two, the bounded body weighs the bound times the mass factor."""
    model = loads(_MODEL)
    assert isinstance(get_attribute(model.compiler, "boundinertia"), str)
    original = mujoco.MjModel.from_xml_string(_MODEL)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(model, 2.0, mass=mass)))
    tiny = original.body("tiny").id
    assert original.body_mass[tiny] == 0.5
    assert np.array_equal(original.body_inertia[tiny], [0.01] * 3)
    assert np.isclose(changed.body_mass[tiny], 0.5 * mass_factor, rtol=1e-12)
    np.testing.assert_allclose(changed.body_inertia[tiny], [0.04 * mass_factor] * 3, rtol=1e-12)
    assert scaled_model_problems(original, changed, 2.0, mass=mass) == []
