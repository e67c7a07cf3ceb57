"""Tests of the keyframe rules: each finding, and what MuJoCo does that makes it a mistake."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import loads
from mjcf_model.tools.lint import lint

ARM = """
<mujoco>
  <compiler angle="radian"/>
  <option gravity="0 0 0"/>
  <worldbody>
    <body><joint name="shoulder" range="-2 2"/><geom size="0.1"/>
      <body pos="0.3 0 0"><joint name="elbow" range="-2 2"/><geom size="0.1"/></body>
    </body>
  </worldbody>
  <actuator>{actuators}</actuator>
  <keyframe><key name="home" {key}/></keyframe>
</mujoco>
"""

SERVOS = '<position name="s" joint="shoulder" kp="50"/><position name="e" joint="elbow" kp="50"/>'


def _codes(text: str) -> list[str]:
    return [finding.rule for finding in lint(loads(text), select=["K"])]


def _settled(text: str, steps: int = 500) -> tuple[np.ndarray, np.ndarray]:
    """The key's qpos, and where MuJoCo has the joints after ``steps`` steps from it."""
    model = mujoco.MjModel.from_xml_string(text)
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    start = data.qpos.copy()
    mujoco.mj_step(model, data, nstep=steps)
    return start, data.qpos.copy()


def test_a_key_outside_a_joints_range_is_found_and_mujoco_pushes_it_back() -> None:
    """K101: MuJoCo starts beyond the limit and the limit moves the joint; inside, it stays."""
    outside = ARM.format(actuators="", key='qpos="2.5 0"')
    inside = ARM.format(actuators="", key='qpos="1.5 0"')
    assert _codes(outside) == ["K101"] and _codes(inside) == []
    start, end = _settled(outside)
    assert start[0] == 2.5 and end[0] < 2.5 - 1e-3
    start, end = _settled(inside)
    assert np.array_equal(start, end)


def test_ranges_in_degrees_and_ball_joints_are_judged_as_mujoco_compiles_them() -> None:
    """A range written in degrees is compared in radians; a ball joint by its angle."""
    text = """<mujoco><worldbody><body><joint name="h" range="-90 90"/><geom size=".1"/>
      <body><joint name="b" type="ball" range="0 30"/><geom size=".1"/></body></body>
      </worldbody><keyframe><key qpos="{h} {w} 0 0 {z}"/></keyframe></mujoco>"""
    ok = text.format(h=1.5, w=np.cos(np.radians(10)), z=np.sin(np.radians(10)))
    assert _codes(ok) == []
    assert _codes(text.format(h=1.6, w=1, z=0)) == ["K101"]
    turned = text.format(h=0, w=np.cos(np.radians(20)), z=np.sin(np.radians(20)))  # 40 degrees
    assert _codes(turned) == ["K101"]


def test_a_written_quaternion_that_is_not_unit_is_found_as_mujoco_normalises_it() -> None:
    """K102: MuJoCo's compiled key holds the normalised quaternion; the finding says which."""
    text = """<mujoco><worldbody><body><freejoint/><geom size=".1"/></body></worldbody>
      <keyframe><key qpos="0 0 1 {q}"/></keyframe></mujoco>"""
    zero = text.format(q="0 0 0 0")
    assert mujoco.MjModel.from_xml_string(zero).key_qpos[0, 3:].tolist() == [1, 0, 0, 0]
    (finding,) = lint(loads(zero), select=["K"])
    assert finding.rule == "K102" and "makes it 1 0 0 0" in finding.message
    assert _codes(text.format(q="0.7071 0 0 0.7071")) == []


def test_a_ctrl_outside_its_range_is_found_and_mujoco_clamps_it() -> None:
    """K103: the motor pushes with the clamped control, not the key's."""
    text = ARM.format(
        actuators='<motor name="m" joint="shoulder" ctrlrange="-1 1"/>', key='ctrl="{c}"'
    )
    assert _codes(text.format(c=2)) == ["K103"] and _codes(text.format(c=1)) == []
    model = mujoco.MjModel.from_xml_string(text.format(c=2))
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    assert data.ctrl[0] == 2 and data.actuator_force[0] == 1


def test_servos_whose_key_ctrl_is_not_their_joints_key_position_are_found() -> None:
    """K104: reordered servos pull the arm off the key's pose; matching ones hold it."""
    reordered = ARM.format(actuators=SERVOS, key='qpos="0.4 1.2" ctrl="1.2 0.4"')
    matching = ARM.format(actuators=SERVOS, key='qpos="0.4 1.2" ctrl="0.4 1.2"')
    (finding,) = lint(loads(reordered), select=["K"])
    assert finding.rule == "K104" and "2 position servos: 's' at 1.2" in finding.message
    assert "(the control of 'e': actuators reordered?)" in finding.message
    assert _codes(matching) == []
    start, end = _settled(reordered)
    assert np.abs(end - start).max() > 0.1
    start, end = _settled(matching)
    assert np.abs(end - start).max() < 1e-9


def test_a_general_actuator_written_like_a_servo_counts_and_a_motor_does_not() -> None:
    """The servo is read from the compiled gain and bias; its gear scales the target."""
    general = (
        '<general joint="shoulder" gear="2" gainprm="30" biastype="affine" biasprm="0 -30 0"/>'
    )
    assert _codes(ARM.format(actuators=general, key='qpos="0.5 0" ctrl="0.5"')) == ["K104"]
    assert _codes(ARM.format(actuators=general, key='qpos="0.5 0" ctrl="1"')) == []
    motor = '<motor joint="shoulder"/>'
    assert _codes(ARM.format(actuators=motor, key='qpos="0.5 0" ctrl="3"')) == []


def test_a_servo_key_without_ctrl_or_qpos_is_not_judged() -> None:
    """Only a key that writes both says where the servo should hold the joint."""
    assert _codes(ARM.format(actuators=SERVOS, key='qpos="0.4 1.2"')) == []
    assert _codes(ARM.format(actuators=SERVOS, key='ctrl="0.4 1.2"')) == []


def test_a_short_key_is_found_and_mujoco_fills_in_the_rest() -> None:
    """K105: the compiled key holds qpos0 (zeros for ctrl) where the key wrote nothing."""
    short = ARM.format(actuators=SERVOS, key='qpos="0.5" ctrl="0.5"')
    findings = lint(loads(short), select=["K105"])
    assert [f.message.split(":")[0] for f in findings] == [
        "key 'home' writes 1 numbers in qpos, but the model has 2",
        "key 'home' writes 1 numbers in ctrl, but the model has 2",
    ]
    model = mujoco.MjModel.from_xml_string(short)
    assert model.key_qpos[0].tolist() == [0.5, 0.0] and model.key_ctrl[0].tolist() == [0.5, 0]
    full = ARM.format(actuators=SERVOS, key='qpos="0.5 0" ctrl="0.5 0"')
    assert _codes(full) == []


def test_a_key_written_to_a_few_digits_at_its_limit_is_not_found() -> None:
    """``1.571`` for a range ending at pi/2 rounds to the limit; ``1.58`` does not."""
    text = ARM.format(actuators="", key='qpos="{q} 0"').replace("-2 2", "-1.5707963 1.5707963")
    assert _codes(text.format(q="1.571")) == []
    assert _codes(text.format(q="1.58")) == ["K101"]


def test_a_servo_offset_that_holds_the_pose_against_gravity_is_not_found() -> None:
    """A key recorded from a simulation: the servo's control sits below the joint to hold it.

    MuJoCo runs the key: with that control the arm stays (within a quarter of the
    offset), so it is no mistake; the same key with the control at zero is found.
    """
    arm = """<mujoco><compiler angle="radian"/><worldbody>
      <body><joint name="j" axis="0 1 0"/><geom type="capsule" fromto="0 0 0 0.5 0 0" size="0.05"/>
      </body></worldbody><actuator><position name="p" joint="j" kp="200" kv="20"/></actuator>
      <keyframe><key qpos="0.3" ctrl="{c}"/></keyframe></mujoco>"""
    model = mujoco.MjModel.from_xml_string(arm.format(c=0.3))
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    holding = 0.3 + data.qfrc_bias[0] / 200  # the control whose servo force meets gravity
    assert abs(holding - 0.3) > 0.01  # a real offset, well beyond the rule's tolerance
    assert _codes(arm.format(c=holding)) == []
    assert _codes(arm.format(c=0)) == ["K104"]
