"""Keyframes of composed scenes, refereed by MuJoCo: each part's key, the others' initial state.

Every expected value is read from a part compiled alone (its ``qpos0``, its
``key_*`` arrays, which MuJoCo completes), joint by joint and actuator by
actuator through the names, then moved by the placement with MuJoCo's own
quaternion functions; nothing is read from the composed text.
"""

from __future__ import annotations

import warnings

import mujoco
import numpy as np
import pytest

from mjcf_model import MjcfDroppedSettingWarning, MjcfValueError, attach, compiled
from serializers import loads

#: A parent whose joints come before and after the body ``mount`` (degrees: ``ref`` is 30°).
PARENT = """<mujoco>
  <worldbody>
    <body name="base"><joint name="p0" type="slide" ref="0.1"/><geom size=".1"/>
      <body name="mount" pos="0 0 1"><joint name="p1" ref="30"/><geom size=".1"/></body>
      <body name="later" pos="1 0 0"><joint name="p2" type="ball"/><geom size=".1"/></body>
    </body>
    <body name="last" pos="2 0 0"><joint name="p3"/><geom size=".1"/></body>
  </worldbody>
  <actuator><motor name="pm" joint="p3"/></actuator>
  <keyframe><key name="home" qpos="0.2 0.3 1 0 0 0 0.4" ctrl="0.5"/><key qpos="0.7"/></keyframe>
</mujoco>
"""
#: A fixed-base arm in radians with a filtered actuator (activation) and a short key.
ARM = """<mujoco>
  <compiler angle="radian"/>
  <worldbody><body name="link"><joint name="a0" ref="0.25"/><geom size=".1"/>
    <body name="tip" pos="0 0 .3"><joint name="a1" type="slide"/><geom size=".1"/></body>
  </body></worldbody>
  <actuator><general name="am" joint="a0" dyntype="filter" dynprm="1"/></actuator>
  <keyframe><key name="home" qpos="0.6" ctrl="0.9" act="0.3" time="2"/></keyframe>
</mujoco>
"""
#: A free-floating part with a mocap target and a key setting velocity and mocap pose.
FLOATER = """<mujoco>
  <worldbody>
    <frame pos="0 0 0.5" euler="0 0 30">
      <body name="hull" pos="0.1 0 0"><freejoint name="root"/><geom size=".1"/></body>
    </frame>
    <body name="goal" mocap="true" pos="1 0 0" quat="0 0 0 1"/>
  </worldbody>
  <keyframe>
    <key name="home" qpos="0 1 2 0 1 0 0" qvel="1 0 0 0 0 1" mpos="0 2 0" mquat="0 1 0 0"/>
  </keyframe>
</mujoco>
"""


def _alone(text: str) -> mujoco.MjModel:
    """The part compiled alone by MuJoCo."""
    return mujoco.MjModel.from_xml_string(text)


def _joint_values(model: mujoco.MjModel, row: np.ndarray, joint: str) -> np.ndarray:
    """The ``qpos`` entries of ``joint`` in one row of ``model``'s positions."""
    info = model.joint(joint)
    size = {0: 7, 1: 4, 2: 1, 3: 1}[int(info.type[0])]
    return row[info.qposadr[0] : info.qposadr[0] + size]


def test_key_of_a_part_at_a_body_sits_between_the_parents_joints() -> None:
    """A part attached at a body: its entries go after that body's subtree, as MuJoCo numbers."""
    parent, arm = loads(PARENT), loads(ARM)
    scene = compiled(attach(parent, arm, at="mount", prefix="r_"))
    alone_parent, alone_arm = _alone(PARENT), _alone(ARM)
    assert scene.nkey == 3
    rows = {scene.key(k).name: k for k in range(scene.nkey)}
    for name, own, other, prefix in (
        ("home", alone_parent.key("home"), alone_arm, "r_"),
        ("r_home", alone_arm.key("home"), alone_parent, ""),
    ):
        key = scene.key(rows[name])
        owner = alone_parent if prefix == "r_" else alone_arm
        for joint in range(owner.njnt):
            joint_name = owner.joint(joint).name
            scene_name = ("" if prefix == "r_" else "r_") + joint_name
            assert np.array_equal(
                _joint_values(scene, key.qpos, scene_name),
                _joint_values(owner, own.qpos, joint_name),
            ), (name, joint_name)
        for joint in range(other.njnt):
            joint_name = other.joint(joint).name
            assert np.array_equal(
                _joint_values(scene, key.qpos, prefix + joint_name),
                _joint_values(other, other.qpos0, joint_name),
            ), (name, joint_name)
    home, arm_home = scene.key(rows["home"]), scene.key(rows["r_home"])
    assert home.ctrl.tolist() == [0.5, 0.0] and home.act.tolist() == [0.0]
    assert arm_home.ctrl.tolist() == [0.0, 0.9] and arm_home.act.tolist() == [0.3]
    assert arm_home.time[0] == 2.0 and home.time[0] == 0.0
    unnamed, alone_unnamed = scene.key(rows[""]), alone_parent.key_qpos[1]
    for joint in ("p0", "p1", "p2", "p3"):  # as MuJoCo completes the short key of the parent
        assert np.array_equal(
            _joint_values(scene, unnamed.qpos, joint),
            _joint_values(alone_parent, alone_unnamed, joint),
        ), joint
    for joint in ("a0", "a1"):
        assert np.array_equal(
            _joint_values(scene, unnamed.qpos, "r_" + joint),
            _joint_values(alone_arm, alone_arm.qpos0, joint),
        ), joint


def test_free_joint_and_mocap_move_with_the_placement() -> None:
    """A free body's key pose and velocity and a mocap key pose are moved by the placement."""
    world = loads(
        '<mujoco><worldbody><site name="s" pos="0 1 0" euler="0 0 90"/></worldbody></mujoco>'
    )
    turn = np.array([np.cos(0.4), 0, np.sin(0.4), 0])
    scene = compiled(attach(world, loads(FLOATER), at="s", prefix="f_", pos=[1, 2, 3], quat=turn))
    alone = _alone(FLOATER)
    site = np.zeros(4)
    mujoco.mju_euler2Quat(site, np.radians([0, 0, 90]), "xyz")
    place_quat = np.zeros(4)
    mujoco.mju_mulQuat(place_quat, site, turn)
    place_pos = np.zeros(3)
    mujoco.mju_rotVecQuat(place_pos, np.array([1.0, 2, 3]), site)
    place_pos += [0, 1, 0]

    def moved(pos: np.ndarray, quat: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        new_pos, new_quat = np.zeros(3), np.zeros(4)
        mujoco.mju_rotVecQuat(new_pos, pos, place_quat)
        mujoco.mju_mulQuat(new_quat, place_quat, quat)
        return new_pos + place_pos, new_quat

    key, own = scene.key("f_home"), alone.key("home")
    pos, quat = moved(own.qpos[:3], own.qpos[3:7])
    assert np.allclose(key.qpos[:3], pos, atol=1e-12) and np.allclose(key.qpos[3:7], quat)
    velocity = np.zeros(3)
    mujoco.mju_rotVecQuat(velocity, own.qvel[:3], place_quat)
    assert np.allclose(key.qvel[:3], velocity) and np.array_equal(key.qvel[3:], own.qvel[3:])
    mpos, mquat = moved(own.mpos[:3], own.mquat[:4])
    assert np.allclose(key.mpos, mpos) and np.allclose(key.mquat, mquat)
    placed_pos, placed_quat = moved(alone.qpos0[:3], alone.qpos0[3:7])
    assert np.allclose(scene.qpos0[:3], placed_pos) and np.allclose(scene.qpos0[3:7], placed_quat)


def test_merged_keys_set_every_part_and_unnamed_keys_stay_apart() -> None:
    """``keyframes="merged"``: one ``home`` for parent and two arms; the unnamed key stays."""
    parent, arm = loads(PARENT), loads(ARM)
    scene_model = attach(parent, arm, prefix="a_", keyframes="merged")
    scene_model = attach(scene_model, arm, prefix="b_", pos=[0, 3, 0], keyframes="merged")
    scene = compiled(scene_model)
    assert sorted(scene.key(k).name for k in range(scene.nkey)) == ["", "home"]
    home, alone = scene.key("home"), _alone(ARM).key("home")
    for prefix in ("a_", "b_"):
        assert _joint_values(scene, home.qpos, prefix + "a0")[0] == alone.qpos[0]
        assert scene.actuator(prefix + "am").id is not None
    assert home.ctrl.tolist() == [0.5, 0.9, 0.9] and home.act.tolist() == [0.3, 0.3]
    assert _joint_values(scene, home.qpos, "p3")[0] == 0.4


def test_keyframe_policy_and_free_parts_in_bodies_are_refused_with_the_way_out() -> None:
    """An unknown policy, and a free part with keys attached inside a body, raise clearly."""
    parent, floater = loads(PARENT), loads(FLOATER)
    with pytest.raises(MjcfValueError, match="'separate' or 'merged'"):
        attach(parent, floater, keyframes="joined")  # type: ignore[arg-type]
    with pytest.raises(MjcfValueError, match="at the world, or at a frame or a site"):
        attach(parent, floater, at="mount", prefix="f_")
    home = loads('<mujoco><keyframe><key name="home"/></keyframe></mujoco>')
    with pytest.raises(MjcfValueError, match=r"key: home.*keyframes='merged'"):
        attach(home, home)


def test_dropped_child_settings_warn_by_name() -> None:
    """A child's ``<option>`` the parent's replaces warns, naming it; the parent's holds."""
    parent = loads('<mujoco><option timestep="0.004"/></mujoco>')
    child = loads('<mujoco><option timestep="0.01" density="2"/><size memory="1M"/></mujoco>')
    with pytest.warns(MjcfDroppedSettingWarning) as caught:
        scene = attach(parent, child, prefix="c_")
    message = str(caught[0].message)
    assert 'timestep="0.01"' in message and 'density="2"' in message and "memory" not in message
    assert compiled(scene).opt.timestep == 0.004
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        attach(parent, loads('<mujoco><option timestep="0.004"/></mujoco>'))


def test_keys_that_size_nkey_allocates_are_each_parts_keys() -> None:
    """A part whose keys come only from ``<size nkey>`` brings them, at its placed initial state."""
    part = loads(
        '<mujoco><size nkey="1"/><worldbody><body pos="0 0 1"><freejoint/><geom size=".1"/>'
        "</body></worldbody></mujoco>"
    )
    scene = compiled(
        attach(attach(loads("<mujoco/>"), part, prefix="a_"), part, prefix="b_", pos=[2, 0, 0])
    )
    assert scene.nkey == 2
    for key in range(2):
        assert np.array_equal(scene.key_qpos[key], scene.qpos0)
