"""A scaled disc flexcomp is refused only where MuJoCo rejects it, at the limit and off it.

MuJoCo requires a disc's spacing to be at least twice its radius plus its contact
margin ("Spacing must be larger than geometry size", equality accepted). Scaling
multiplies the spacing by the square root of the factor and the radius and the
margin by the factor; MuJoCo compiles the disc scaled by hand, and the scaled
model must compile to the same flex.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model.transforms.scaling.transform import scaled
from serializers import dumps, loads

_DISC = """<mujoco><worldbody><body name="b"><flexcomp name="d" type="disc" count="4 4 1"
    spacing="{spacing} {spacing} {depth}" radius="{radius}" mass="1"><edge equality="true"/>
    {contact}</flexcomp></body></worldbody></mujoco>"""


def _disc(spacing: float, radius: float, contact: str) -> str:
    """A disc of ``spacing`` (depth five times it) and ``radius``, with a ``<contact>`` child."""
    return _DISC.format(spacing=spacing, depth=5 * spacing, radius=radius, contact=contact)


def _compiled_flex(text: str) -> tuple[np.ndarray, np.ndarray]:
    """MuJoCo's flex radius and vertex positions (at ``qpos0``) of ``text``."""
    model = mujoco.MjModel.from_xml_string(text)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return model.flex_radius.copy(), data.flexvert_xpos.copy()


@pytest.mark.parametrize(
    ("radius", "margin"),
    [(0.25, None), (0.125, 0.25)],
    ids=["radius", "radius-and-margin"],
)
def test_a_disc_scaled_to_exactly_the_limit_is_accepted_as_mujoco_accepts_it(
    radius: float, margin: float | None
) -> None:
    """Scaled by four, the spacing (1 to 2) equals twice the radius plus the margin.

    Every value is exact in binary, so the scaled disc sits on MuJoCo's limit.
    """
    factor = 4.0
    contact = "" if margin is None else f'<contact margin="{margin}"/>'
    by_hand_contact = "" if margin is None else f'<contact margin="{margin * factor}"/>'
    by_hand = _disc(2.0, radius * factor, by_hand_contact)
    assert 2 * radius * factor + (margin or 0.0) * factor == 2.0
    expected = _compiled_flex(by_hand)  # MuJoCo accepts the limit itself
    result = _compiled_flex(dumps(scaled(loads(_disc(1.0, radius, contact)), factor)))
    assert np.array_equal(result[0], expected[0])
    assert np.allclose(result[1], expected[1], rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("factor", [2.0, 4.0])
def test_a_contact_without_a_margin_adds_none_to_the_disc_limit(factor: float) -> None:
    """A ``<contact>`` child that writes no margin has MuJoCo's zero margin: no refusal."""
    contact = '<contact condim="3"/>'
    by_hand = _disc(0.06 * np.sqrt(factor), 0.01 * factor, contact)
    expected = _compiled_flex(by_hand)  # MuJoCo accepts it
    result = _compiled_flex(dumps(scaled(loads(_disc(0.06, 0.01, contact)), factor)))
    assert np.allclose(result[0], expected[0], rtol=1e-12)
    assert np.allclose(result[1], expected[1], rtol=1e-12, atol=1e-15)
