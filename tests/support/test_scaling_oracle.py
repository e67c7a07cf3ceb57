"""Tests of the helper ``tests.support.scaling_oracle``."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model.bridge.scaled_fields import FLOAT_FIELDS, float_fields
from tests.support.scaling_oracle import compiled_pair, scaled_model_problems

# -- The complete scaling oracle: every float field classified, and the bugs it catches. -------
#
# MuJoCo compiles each model before and after scaling; :func:`scaled_model_problems`
# states the expected change of every field (:mod:`mjcf_model.bridge.scaled_fields`).


def test_every_float_field_of_the_installed_mujoco_is_classified() -> None:
    """A float array MuJoCo adds must be given a kind before scaling can be trusted with it."""
    model = mujoco.MjModel.from_xml_string("<mujoco/>")
    assert [f for f in float_fields(model) if f not in FLOAT_FIELDS] == []
    assert len(float_fields(model)) > 150


def test_an_unclassified_field_is_reported_not_skipped() -> None:
    """The oracle names a float field it has no kind for instead of passing over it."""

    class Extended:
        def __init__(self, model: mujoco.MjModel) -> None:
            self._model = model
            self.geom_novelty = np.ones(3)

        def __dir__(self) -> list[str]:
            return [*dir(self._model), "geom_novelty"]

        def __getattr__(self, name: str) -> object:
            return getattr(self._model, name)

    model = mujoco.MjModel.from_xml_string("<mujoco/>")
    assert "geom_novelty: not classified" in scaled_model_problems(
        Extended(model), Extended(model), 2.0
    )


def test_welds_between_sites_and_spatial_tendons_are_read_as_mujoco_does() -> None:
    """A weld between sites keeps its unread data; a spatial tendon over sites is a length.

    Both were found by the drawn models: the oracle expected a site weld's default
    ``relpose`` to scale, and took a spatial tendon's sites for joints.
    """
    text = """<mujoco><worldbody>
      <body name="a"><joint type="slide"/><geom size=".1"/><site name="s0"/></body>
      <body name="b" pos="0 0 1"><geom size=".1"/><site name="s1"/></body>
    </worldbody>
    <tendon><spatial name="t" springlength=".5"><site site="s0"/><site site="s1"/></spatial>
    </tendon>
    <equality><weld site1="s0" site2="s1"/></equality></mujoco>"""
    original, changed = compiled_pair(text, 2.0)
    assert np.array_equal(changed.eq_data, original.eq_data)
    assert changed.tendon_lengthspring[0, 0] == 2 * original.tendon_lengthspring[0, 0]
    assert scaled_model_problems(original, changed, 2.0) == []


def _offset_frames(offset: float) -> str:
    """A body whose geom and site lie ``offset`` metres from its frame along x."""
    return f"""<mujoco><worldbody><body>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
      <geom size="0.1" pos="{offset} 0 0"/><site pos="{offset} 0 0"/>
    </body></worldbody></mujoco>"""


def test_a_frame_offset_crossing_mujocos_tolerance_when_scaled_is_no_change() -> None:
    """0.7 micrometres is "at the body's frame" to MuJoCo, 1.4 is not: that flip is expected."""
    original, changed = compiled_pair(_offset_frames(7e-7), 2.0)
    assert original.geom_sameframe.tolist() == original.site_sameframe.tolist() == [1]
    assert changed.geom_sameframe.tolist() == changed.site_sameframe.tolist() == [3]
    assert scaled_model_problems(original, changed, 2.0) == []


@pytest.mark.parametrize("offset", [3e-7, 0.01])
def test_a_frame_flag_flip_the_offset_cannot_explain_is_reported(offset: float) -> None:
    """A flag that changes where scaling keeps the offset on one side of the tolerance."""
    original, changed = compiled_pair(_offset_frames(offset), 2.0)
    assert scaled_model_problems(original, changed, 2.0) == []
    changed.site_sameframe[0] = 3 if original.site_sameframe[0] == 1 else 1
    assert scaled_model_problems(original, changed, 2.0) == [
        f"site_sameframe[0]: {original.site_sameframe[0]} became {changed.site_sameframe[0]}"
    ]
