"""Tests of ``mjcf_model.tree.joints``."""

from __future__ import annotations

import pytest

from tests.support.scaling_oracle import compiled_pair, scaled_model_problems

# -- The complete scaling oracle: every float field classified, and the bugs it catches. -------
#
# MuJoCo compiles each model before and after scaling; :func:`scaled_model_problems`
# states the expected change of every field (:mod:`mjcf_model.bridge.scaled_fields`).


@pytest.mark.parametrize("wrap", [False, True], ids=["body", "frame"])
def test_a_bodys_joints_come_before_a_child_body_written_above_them(wrap: bool) -> None:
    """MuJoCo numbers a body's own joints before those of a body inside it, wherever written.

    A child body (bare or in a frame) written before its parent's joints: the key's
    slide entry still scales (a drawn model found it unscaled).
    """
    child = '<body name="c"><joint name="c_hinge"/><joint name="c_slide" type="slide"/>'
    child += '<geom size="0.1"/></body>'
    child = f"<frame>{child}</frame>" if wrap else child
    text = f"""<mujoco><worldbody><body name="p">{child}<joint name="p_slide" type="slide"/>
    <joint name="p_hinge"/><geom size="0.1"/></body></worldbody>
    <keyframe><key qpos="0.1 0.2 0.3 0.4" qvel="1 2 3 4"/></keyframe></mujoco>"""
    original, changed = compiled_pair(text, 2.0)
    names = [original.joint(i).name for i in range(original.njnt)]
    assert names == ["p_slide", "p_hinge", "c_hinge", "c_slide"]
    assert scaled_model_problems(original, changed, 2.0) == []
    assert changed.key_qvel[0].tolist() == [2.0, 2.0, 3.0, 8.0]
