"""A site transmission's gear scales its rotational part only where both parts are set.

With a ``refsite`` MuJoCo measures ``gear[:3]`` along the site's offset and
``gear[3:]`` along its rotation. A gear of one part only (written short, the
rest zero, as no class gives a gear here) measures a length or an angle and
stays as written; a gear of both parts measures a length, so its rotational
part is a lever arm and scales. MuJoCo compiles the scaled model to the
original scaled, and measures the actuator's length accordingly.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model.transforms.scaling.transform import scaled
from serializers import dumps, loads
from tests.support.scaling_oracle import scaled_model_problems

_MODEL = """<mujoco><worldbody>
  <site name="ref"/>
  <body name="arm"><joint type="slide"/><geom size=".1"/>
    <site name="tip" pos=".3 .1 0" euler="10 0 28.6"/></body>
</worldbody>
<actuator><general site="tip" refsite="ref" gear="{gear}"/></actuator></mujoco>"""


def _compiled_pair(gear: str) -> tuple[mujoco.MjModel, mujoco.MjModel]:
    """MuJoCo's compilation of the model with ``gear`` and of it scaled by two."""
    text = _MODEL.format(gear=gear)
    original = mujoco.MjModel.from_xml_string(text)
    return original, mujoco.MjModel.from_xml_string(dumps(scaled(loads(text), 2.0)))


@pytest.mark.parametrize(
    ("gear", "length"),
    [("1", 2.0), ("1 0", 2.0), (".5 2", 2.0), ("0 0 0 1 0 0", 1.0), ("0 0 0 0 1 1", 1.0)],
)
def test_a_gear_of_one_part_stays(gear: str, length: float) -> None:
    """A translation's length doubles, a rotation's angle stays; the gear is unchanged."""
    original, changed = _compiled_pair(gear)
    translation, rotation = original.actuator_gear[0, :3], original.actuator_gear[0, 3:]
    assert np.any(translation) != np.any(rotation)
    assert original.actuator_length0[0] != 0
    assert np.array_equal(changed.actuator_gear, original.actuator_gear)
    assert np.isclose(
        changed.actuator_length0[0], length * original.actuator_length0[0], rtol=1e-12
    )
    assert scaled_model_problems(original, changed, 2.0) == []


@pytest.mark.parametrize("gear", ["1 0 0 1 0 0", "0 2 0 0 0 1"])
def test_a_gear_of_both_parts_scales_its_rotation(gear: str) -> None:
    """The rotational part doubles with the length it now contributes to."""
    original, changed = _compiled_pair(gear)
    expected = original.actuator_gear[0] * [1, 1, 1, 2, 2, 2]
    assert np.array_equal(changed.actuator_gear[0], expected)
    assert np.isclose(changed.actuator_length0[0], 2 * original.actuator_length0[0], rtol=1e-12)
    assert scaled_model_problems(original, changed, 2.0) == []


@pytest.mark.parametrize(
    ("own", "of_class"),
    [("1", "0 0 0 0 0 1"), ("1 0", "0 0 0 0 1"), ("2", "1 0 0 0 1 0"), (None, "1 0 0 0 0 1")],
)
def test_a_short_gear_keeps_its_class_trailing_values(own: str | None, of_class: str) -> None:
    """MuJoCo reads ``gear="1"`` over a class's ``0 0 0 0 0 1``: two parts, the rotation scales.

    The scaled model compiles to the original scaled (``actuator_gear`` and the
    actuator's ``length0``, measured by MuJoCo).
    """
    written = "" if own is None else f' gear="{own}"'
    text = (
        f'<mujoco><default><general gear="{of_class}"/></default><worldbody><site name="ref"/>'
        '<body><joint type="slide"/><geom size=".1"/><site name="tip" pos=".3 .1 0" '
        'euler="0 0 28.6"/></body></worldbody><actuator>'
        f'<general site="tip" refsite="ref"{written}/></actuator></mujoco>'
    )
    original = mujoco.MjModel.from_xml_string(text)
    assert np.count_nonzero(original.actuator_gear[0, :3]) and np.count_nonzero(
        original.actuator_gear[0, 3:]
    )
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(text), 2.0)))
    assert scaled_model_problems(original, changed, 2.0) == []
