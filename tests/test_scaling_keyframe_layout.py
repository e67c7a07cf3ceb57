"""Scaled keyframes: each ``qpos``, ``qvel`` and ``ctrl`` entry scales as its joint or actuator.

MuJoCo compiles the original and the scaled model; the oracle
(:func:`tests.support.scaling_oracle.scaled_model_problems`) and the compiled ``key_*``
arrays say which entries are lengths: a free joint's position and linear velocity
and a slide joint's coordinate are, wherever the joint stands in ``qpos``; the
control of a position servo on a slide joint is, and a ``<config>`` setting of a
plugin actuator is no actuator of its own.
"""

from __future__ import annotations

from collections.abc import Sequence

import mujoco
import numpy as np
import pytest

from mjcf_model.nodes.base import AnyElement, with_attributes
from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.rules import RULES
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.traversal import map_elements
from serializers import dumps, loads
from tests.support.scaling_oracle import scaled_model_problems

#: A slide joint before a free joint in ``qpos`` (the free joint's entries start at 1).
_SLIDE_THEN_FREE = """<mujoco><worldbody>
  <body name="rail"><joint name="s" type="slide" axis="1 0 0"/><geom size=".1"/></body>
  <body name="ball" pos="0 0 1"><freejoint/><geom size=".1"/></body>
  <body name="arm" pos="1 0 0"><joint name="h" type="hinge"/><geom size=".1"/></body>
</worldbody>
<keyframe><key qpos=".3  1 2 3  1 0 0 0  .7" qvel=".5  1 2 3  .1 .2 .3  .4"/></keyframe>
</mujoco>"""

#: A plugin actuator with a ``<config>`` child, before a position servo on a slide joint.
_PLUGIN_THEN_SERVO = """<mujoco><extension><plugin plugin="mujoco.pid"/></extension>
<worldbody><body><joint name="h" type="hinge"/>
  <joint name="s" type="slide" axis="1 0 0"/><geom size=".1"/></body></worldbody>
<actuator><plugin joint="h" plugin="mujoco.pid"><config key="kp" value="4"/></plugin>
  <position joint="s" kp="10" ctrlrange="-1 1"/></actuator>
<keyframe><key ctrl=".1 .25"/></keyframe></mujoco>"""


def _compiled_pair(text: str, factor: float) -> tuple[mujoco.MjModel, mujoco.MjModel]:
    """MuJoCo's compilation of ``text`` and of it scaled by ``factor``."""
    original = mujoco.MjModel.from_xml_string(text)
    return original, mujoco.MjModel.from_xml_string(dumps(scaled(loads(text), factor)))


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_a_free_joint_after_a_slide_scales_its_key_position_and_velocity(factor: float) -> None:
    """The slide's entry and the free joint's position and linear velocity scale; the rest stay."""
    original, changed = _compiled_pair(_SLIDE_THEN_FREE, factor)
    assert scaled_model_problems(original, changed, factor) == []
    qpos_factors = np.array([factor, factor, factor, factor, 1, 1, 1, 1, 1])
    qvel_factors = np.array([factor, factor, factor, factor, 1, 1, 1, 1])
    assert np.allclose(changed.key_qpos[0], original.key_qpos[0] * qpos_factors, rtol=1e-12)
    assert np.allclose(changed.key_qvel[0], original.key_qvel[0] * qvel_factors, rtol=1e-12)


def test_a_plugin_actuators_config_is_not_counted_among_the_key_controls() -> None:
    """The servo's control is the key's second entry: it scales; the plugin's stays."""
    original, changed = _compiled_pair(_PLUGIN_THEN_SERVO, 2.0)
    assert original.nu == 2
    assert np.allclose(changed.key_ctrl[0], [0.1, 0.5], rtol=1e-12)
    assert np.allclose(changed.actuator_ctrlrange[1], [-2.0, 2.0], rtol=1e-12)
    assert scaled_model_problems(original, changed, 2.0) == []


def test_a_key_scaled_without_its_model_scales_only_its_mocap_positions() -> None:
    """Without the model, the joints and actuators the entries belong to are unknown.

    The key rule then scales ``mpos`` alone, and MuJoCo reads the key so changed
    with every other entry as written.
    """
    text = """<mujoco><worldbody><body name="m" mocap="true" pos="0 0 1"><geom size=".1"
    contype="0" conaffinity="0"/></body><body><joint name="s" type="slide"/><geom size=".1"/>
    </body></worldbody><actuator><position joint="s" kp="1"/></actuator>
    <keyframe><key qpos=".3" ctrl=".2" mpos="1 2 3"/></keyframe></mujoco>"""
    model = loads(text)
    context = ScaleContext(factors=(2.0, 2.0, 2.0))  # no model

    def key_rule(
        element: AnyElement, key: str | None, ancestors: Sequence[AnyElement]
    ) -> AnyElement:
        if key != "keyframe/key":
            return element
        changes = RULES[key](element, ancestors, context)
        assert set(changes) == {"mpos"}
        return with_attributes(element, changes)

    original = mujoco.MjModel.from_xml_string(text)
    changed = mujoco.MjModel.from_xml_string(dumps(map_elements(key_rule, model)))
    assert np.array_equal(changed.key_mpos, 2 * original.key_mpos)
    assert np.array_equal(changed.key_qpos, original.key_qpos)
    assert np.array_equal(changed.key_ctrl, original.key_ctrl)
