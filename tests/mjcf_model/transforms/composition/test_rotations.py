"""Euler angles, quaternions and angle units against MuJoCo's own conversions.

MuJoCo is the referee: ``mujoco.mju_euler2Quat`` turns Euler angles into the
quaternion MuJoCo compiles, and a compiled ``<compiler angle="degree">`` model
shows the radians MuJoCo reads from a number of degrees.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import mujoco
import numpy as np
import pytest

from mjcf_model.transforms.composition.rotations import (
    euler_angles,
    euler_product,
    euler_quat,
    in_unit,
    joint_radians,
    quat_distance,
)


def _mujoco_quat(angles: Sequence[float], sequence: str) -> np.ndarray[Any, Any]:
    """The quaternion MuJoCo makes of Euler angles (radians) in ``sequence``."""
    quat = np.zeros(4)
    mujoco.mju_euler2Quat(quat, np.array(angles, dtype=float), sequence)
    return quat


#: Angles whose first turn is beyond half a turn (but within one), and a sequence.
BEYOND_HALF_A_TURN = [
    ((3.5, 0.2, 0.3), "xyz"),
    ((-3.5, 0.2, 0.3), "xyz"),
    ((0.5 - 2 * math.pi, 0.2, 0.3), "xyz"),
    ((0.3, -0.4, -3.5), "XYZ"),
    ((0.5 - 2 * math.pi, 0.4, 0.3), "zxz"),
]


@pytest.mark.parametrize(("angles", "sequence"), BEYOND_HALF_A_TURN, ids=str)
def test_angles_within_a_turn_come_back_from_their_quaternion(
    angles: tuple[float, float, float], sequence: str
) -> None:
    """Angles whose quaternion needs the first turn beyond half a turn come back as given."""
    found = euler_angles(tuple(_mujoco_quat(angles, sequence)), sequence)
    assert found is not None
    assert found == pytest.approx(angles, abs=1e-12)


@pytest.mark.parametrize("sequence", ["xyz", "XYZ", "zyx", "yxz"])
@pytest.mark.parametrize(
    "quat", [(0.5, 0.5, 0.5, 0.5), (0.5, -0.5, 0.5, -0.5), (0.5, 0.5, -0.5, 0.5)], ids=str
)
def test_angles_at_gimbal_lock_give_the_quaternion_itself(
    quat: tuple[float, float, float, float], sequence: str
) -> None:
    """At exact gimbal lock (120 degrees about a diagonal) MuJoCo turns the angles into quat."""
    found = euler_angles(quat, sequence)
    assert found is not None
    assert np.allclose(_mujoco_quat(found, sequence), quat, rtol=0, atol=1e-12)


@pytest.mark.parametrize("sequence", ["xxy", "xyy", "XXz", "zYY"])
def test_a_sequence_repeating_an_axis_has_no_angles(sequence: str) -> None:
    """Two turns in a row about one axis cannot express a general turn: no angles."""
    quat = tuple(_mujoco_quat((0.3, 0.4, 0.5), "xyz"))
    assert euler_angles(quat, sequence) is None


def test_the_quaternion_is_mujocos_normalized_to_the_last_bit() -> None:
    """euler_quat is MuJoCo's quaternion for the angles divided by its norm."""
    angles, sequence = (0.7635438273251482, 1.782534912938453, -2.27193618296932), "xyz"
    expected = _mujoco_quat(angles, sequence)
    expected = expected / np.linalg.norm(expected)
    assert np.allclose(euler_quat(angles, sequence), expected, rtol=0, atol=2.3e-16)


def test_angles_and_axes_of_other_counts_are_refused() -> None:
    """Two angles for a three-axis sequence, or quaternions of other lengths, are refused."""
    with pytest.raises(ValueError, match="longer"):
        euler_product([0.1, 0.2], "xyz")
    with pytest.raises(ValueError, match="shorter"):
        quat_distance((1.0, 0.0, 0.0, 0.0), (1.0, 0.0, 0.0))


def test_degrees_read_back_as_exactly_the_radians_when_rounding_down_is_needed() -> None:
    """The degrees given for radians MuJoCo reads back exactly, found one step below the guess."""
    radians = 0.26506228457592496
    guess = radians * 180 / math.pi
    assert joint_radians(guess) != radians  # the plain conversion misses by a bit
    degrees = in_unit(radians, True, joint_radians)
    model = mujoco.MjModel.from_xml_string(
        '<mujoco><compiler angle="degree"/><worldbody><body><joint limited="true" '
        f'range="0 {degrees!r}"/><geom size="1"/></body></worldbody></mujoco>'
    )
    assert model.jnt_range[0, 1] == radians


@pytest.mark.parametrize("radians", [2.0, -1.0472, 0.5236, 2.8973, 1.57])
def test_degrees_are_written_with_the_fewest_digits_that_compile_to_the_radians(
    radians: float,
) -> None:
    """The degrees written are as short as the identical model allows.

    The text written (Python's shortest ``repr`` of the double found) compiles to exactly
    the radians, and every text with fewer significant digits compiles to other radians:
    MuJoCo keeps joint ranges as doubles, so ``-60.0001403060998`` stands for ``-1.0472``.
    """
    degrees = in_unit(radians, True, joint_radians)
    written = repr(degrees)
    digits = len(written.lstrip("-").replace(".", "").lstrip("0"))

    def compiled_range(text: str) -> float:
        model = mujoco.MjModel.from_xml_string(
            '<mujoco><compiler angle="degree"/><worldbody><body><joint limited="true" '
            f'range="{text} 1000"/><geom size="1"/></body></worldbody></mujoco>'
        )
        return float(model.jnt_range[0, 0])

    assert compiled_range(written) == radians
    shorter = {f"{degrees:.{count}g}" for count in range(1, digits)}
    assert shorter and all(compiled_range(text) != radians for text in shorter)
