"""Tests of ``mjcf_model.transforms.composition.keyframes``."""

from __future__ import annotations

import warnings

import mujoco
import numpy as np
import pytest

from mjcf_model import (
    GenericElement,
    MjcfDroppedSettingWarning,
    MjcfValueError,
    Mujoco,
    Worldbody,
    attach,
    attach_all,
    compiled,
)
from mjcf_model.nodes.base import get_attribute
from mjcf_model.serializers import loads
from mjcf_model.tree.traversal import with_children
from tests.conftest import MUJOCO_VERSION
from tests.support.composition_oracle import PlacedPart, composition_problems

# -- Keyframes of composed scenes, refereed by MuJoCo: each part's key, the others' initial
#    state.
#
# Every expected value is read from a part compiled alone (its ``qpos0``, its
# ``key_*`` arrays, which MuJoCo completes), joint by joint and actuator by
# actuator through the names, then moved by the placement with MuJoCo's own
# quaternion functions; nothing is read from the composed text.


#: A parent whose joints come before and after the body ``mount`` (degrees: ``ref`` is 30°).
PARENT_KEYFRAMES = """<mujoco>
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
ARM_KEYFRAMES = """<mujoco>
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


def _alone_keyframes(text: str) -> mujoco.MjModel:
    """The part compiled alone by MuJoCo."""
    return mujoco.MjModel.from_xml_string(text)


def _joint_values(model: mujoco.MjModel, row: np.ndarray, joint: str) -> np.ndarray:
    """The ``qpos`` entries of ``joint`` in one row of ``model``'s positions."""
    info = model.joint(joint)
    size = {0: 7, 1: 4, 2: 1, 3: 1}[int(info.type[0])]
    return row[info.qposadr[0] : info.qposadr[0] + size]


def test_key_of_a_part_at_a_body_sits_between_the_parents_joints() -> None:
    """A part attached at a body: its entries go after that body's subtree, as MuJoCo numbers."""
    parent, arm = loads(PARENT_KEYFRAMES), loads(ARM_KEYFRAMES)
    scene = compiled(attach(parent, arm, at="mount", prefix="r_"))
    alone_parent, alone_arm = _alone_keyframes(PARENT_KEYFRAMES), _alone_keyframes(ARM_KEYFRAMES)
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
    alone = _alone_keyframes(FLOATER)
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


def test_merged_keys_set_every_part() -> None:
    """``keyframes="merged"``: one ``home`` for parent and two arms; the unnamed key stays."""
    parent, arm = loads(PARENT_KEYFRAMES), loads(ARM_KEYFRAMES)
    scene_model = attach(parent, arm, prefix="a_", keyframes="merged")
    scene_model = attach(scene_model, arm, prefix="b_", pos=[0, 3, 0], keyframes="merged")
    scene = compiled(scene_model)
    assert sorted(scene.key(k).name for k in range(scene.nkey)) == ["", "home"]
    home, alone = scene.key("home"), _alone_keyframes(ARM_KEYFRAMES).key("home")
    for prefix in ("a_", "b_"):
        assert _joint_values(scene, home.qpos, prefix + "a0")[0] == alone.qpos[0]
        assert scene.actuator(prefix + "am").id is not None
    assert home.ctrl.tolist() == [0.5, 0.9, 0.9] and home.act.tolist() == [0.3, 0.3]
    assert _joint_values(scene, home.qpos, "p3")[0] == 0.4


def test_keyframe_policy_and_free_parts_in_bodies_are_refused_with_the_way_out() -> None:
    """An unknown policy, and a free part with keys attached inside a body, raise clearly."""
    parent, floater = loads(PARENT_KEYFRAMES), loads(FLOATER)
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


# -- ``keyframes="merged"``: keys of one name become one key; the others keep their own names. -
#
# A child's key whose name (before prefixing) a scene key has joins that key,
# whatever its place among the child's keys; a child key no scene key names is
# added under its own unprefixed name, so a second child attached in the same
# call joins it; keys without a name, even written ``name=""``, are never merged
# (mjcf_model/transforms/composition/keyframes.py). Expected values are the
# parts compiled alone by MuJoCo: the owner's key, every other part at its
# ``qpos0`` with no control.


PARENT_MERGED_NAMES = """<mujoco>
  <worldbody><body name="base"><joint name="yaw"/><geom size=".1"/></body></worldbody>
  <actuator><motor name="turn" joint="yaw"/></actuator>
  <keyframe><key name="home" qpos="0.5" ctrl="1"/><key name="" qpos="0.25"/></keyframe>
</mujoco>
"""
#: An arm whose ``home`` is neither its first nor its last key.
ARM_MERGED_NAMES = """<mujoco>
  <worldbody>
    <body name="link"><joint name="shoulder" type="slide" ref="0.05"/><geom size=".1"/></body>
  </worldbody>
  <actuator><motor name="lift" joint="shoulder"/></actuator>
  <keyframe>
    <key name="solo" qpos="0.1" ctrl="0.2"/>
    <key name="home" qpos="0.3" ctrl="0.4"/>
    <key name="extra" qpos="0.6" ctrl="0.7"/>
    <key name="" qpos="0.9"/>
  </keyframe>
</mujoco>
"""


def _check(
    scene: mujoco.MjModel, row: int, owners: dict[str, tuple[mujoco.MjModel, str, int | None]]
) -> None:
    """Key ``row`` sets each part (prefix -> model alone, joint, its key or None) as expected."""
    for prefix, (alone, joint, key) in owners.items():
        at, own = scene.joint(prefix + joint).qposadr[0], alone.joint(joint).qposadr[0]
        qpos = alone.qpos0 if key is None else alone.key_qpos[key]
        ctrl = [0.0] * alone.nu if key is None else alone.key_ctrl[key].tolist()
        assert scene.key_qpos[row][at] == qpos[own], (row, prefix)
        actuator = scene.actuator(prefix + alone.actuator(0).name).id
        assert scene.key_ctrl[row][actuator] == ctrl[0], (row, prefix)


def _two_arms_merged() -> tuple[mujoco.MjModel, mujoco.MjModel, mujoco.MjModel]:
    """The parent with two arms attached in one call, keys merged; the parent and arm alone."""
    arm = loads(ARM_MERGED_NAMES)
    scene = compiled(
        attach_all(loads(PARENT_MERGED_NAMES), [(arm, "a_"), (arm, "b_")], keyframes="merged")
    )
    parent = mujoco.MjModel.from_xml_string(PARENT_MERGED_NAMES)
    return scene, parent, mujoco.MjModel.from_xml_string(ARM_MERGED_NAMES)


def test_merged_keys_match_by_name_and_new_names_stay_unprefixed() -> None:
    """Two arms in one call: ``home`` joins the parent's, ``solo``/``extra`` join each other."""
    scene, parent, alone = _two_arms_merged()
    names = [scene.key(k).name for k in range(scene.nkey)]
    assert sorted(names) == ["", "extra", "home", "solo"]
    for name in ("home", "solo", "extra"):
        own = alone.key(name).id
        theirs = parent.key(name).id if name == "home" else None
        _check(
            scene,
            scene.key(name).id,
            {
                "": (parent, "yaw", theirs),
                "a_": (alone, "shoulder", own),
                "b_": (alone, "shoulder", own),
            },
        )


def test_unnamed_keys_merge_by_their_place_among_the_unnamed() -> None:
    """The ``name=""`` keys of parent and arms become one key.

    It sets every part by the part's own unnamed key (MuJoCo names keys by name or index).
    """
    scene, parent, alone = _two_arms_merged()
    unnamed = [k for k in range(scene.nkey) if scene.key(k).name == ""]
    assert len(unnamed) == 1
    _check(
        scene,
        unnamed[0],
        {
            "": (parent, "yaw", _unnamed(parent)),
            "a_": (alone, "shoulder", _unnamed(alone)),
            "b_": (alone, "shoulder", _unnamed(alone)),
        },
    )


def test_a_fleet_of_a_robot_whose_only_key_has_no_name_gets_one_key() -> None:
    """Two copies of an arm whose one key is unnamed, merged into an empty world: one key.

    It sets both copies as the arm's key sets the arm (a held-out Menagerie arm's case);
    separate keys give one key per copy, each leaving the other copy at ``qpos0``.
    """
    arm_text = ARM_KEYFRAMES.replace('<key name="home"', "<key")
    arm, world = loads(arm_text), loads("<mujoco/>")
    alone = mujoco.MjModel.from_xml_string(arm_text)
    pair = [(arm, "a_"), (arm, "b_")]
    merged = compiled(attach_all(world, pair, keyframes="merged"))
    assert merged.nkey == 1
    for prefix in ("a_", "b_"):
        assert _joint_values(merged, merged.key(0).qpos, prefix + "a0")[0] == alone.key(0).qpos[0]
    assert merged.key(0).ctrl.tolist() == [0.9, 0.9] and merged.key(0).time[0] == 2.0
    separate = compiled(attach_all(world, pair))
    assert separate.nkey == 2
    assert _joint_values(separate, separate.key(0).qpos, "b_a0")[0] == alone.qpos0[0]


@pytest.mark.parametrize(("parent_time", "expected"), [("1.5", 1.5), ("0", 2.0)])
def test_a_merged_key_keeps_the_parents_time_unless_it_is_zero(
    parent_time: str, expected: float
) -> None:
    """Parent and child both set ``time`` on ``home``: the parent's wins; a zero gives way."""
    parent_text = PARENT_KEYFRAMES.replace(
        '<key name="home" qpos', f'<key name="home" time="{parent_time}" qpos'
    )
    scene = compiled(
        attach(loads(parent_text), loads(ARM_KEYFRAMES), prefix="a_", keyframes="merged")
    )
    assert scene.key("home").time[0] == expected


def _unnamed(model: mujoco.MjModel) -> int:
    """The id of ``model``'s one unnamed key."""
    (key,) = (k for k in range(model.nkey) if model.key(k).name == "")
    return key


# -- Keys of parts attached inside a body: their entries sit where MuJoCo numbers them. --------
#
# MuJoCo numbers joints (and mocap bodies) in document order, so parts appended
# to a body come after everything above or inside that body and before what
# comes later. The parent below has, before the ``mount`` body's end, a mocap
# body, a slide and a ball joint (``qpos`` and ``qvel`` counts differ) and the
# hinge of ``mount``; after it, a slide joint and a second mocap body. Every key
# is checked, joint by joint, against the parts compiled alone by MuJoCo.
# Parents whose tree does not show where the entries go, and parts MuJoCo
# allows only at the top level, are refused with the way out.


PARENT_PARTS_INSIDE_A_BODY = """<mujoco>
  <worldbody>
    <body name="marker" mocap="true" pos="0 0 2">
      <geom size=".05" contype="0" conaffinity="0"/>
    </body>
    <body name="base">
      <joint name="rail" type="slide"/><geom size=".1"/>
      <body name="wrist" pos="0 0 .5"><joint name="knob" type="ball"/><geom size=".1"/></body>
      <body name="mount" pos="0 0 1"><joint name="elbow"/><geom size=".1"/></body>
      <body name="after" pos="1 0 0"><joint name="late" type="slide"/><geom size=".1"/></body>
    </body>
    <body name="flag" mocap="true" pos="1 1 1"><geom size=".05" contype="0" conaffinity="0"/></body>
  </worldbody>
  <keyframe>
    <key name="pose" qpos="0.1 0.7 0 0.7 0 0.3 0.2" qvel="1 2 3 4 5 6" mpos="0 0 3 1 1 2"/>
  </keyframe>
</mujoco>
"""
#: A finger whose key sets its slide's position and velocity.
FINGER = """<mujoco>
  <worldbody>
    <body name="finger"><joint name="pinch" type="slide" ref="0.05"/><geom size=".02"/></body>
  </worldbody>
  <keyframe><key name="closed" qpos="0.04" qvel="0.5"/></keyframe>
</mujoco>
"""


def _alone_parts_inside_a_body(text: str) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(text)


def _sizes(model: mujoco.MjModel, joint: str) -> tuple[int, int, int, int]:
    """Where ``joint``'s ``qpos`` and ``qvel`` entries start, and how many there are."""
    info = model.joint(joint)
    q, v = {0: (7, 6), 1: (4, 3), 2: (1, 1), 3: (1, 1)}[int(info.type[0])]
    return int(info.qposadr[0]), q, int(info.dofadr[0]), v


def _entries(model: mujoco.MjModel, key: str, joint: str) -> tuple[list[float], list[float]]:
    """The ``qpos`` and ``qvel`` entries of ``joint`` in the key named ``key``."""
    q, nq, v, nv = _sizes(model, joint)
    row = model.key(key)
    return row.qpos[q : q + nq].tolist(), row.qvel[v : v + nv].tolist()


def _initial(model: mujoco.MjModel, joint: str) -> tuple[list[float], list[float]]:
    """``joint``'s entries in the initial state: its ``qpos0``, no velocity."""
    q, nq, _, nv = _sizes(model, joint)
    return model.qpos0[q : q + nq].tolist(), [0.0] * nv


def _with_generic_flag(model: Mujoco) -> Mujoco:
    """``model`` with its last world body, ``flag``, as a generic element (``mocap`` as text)."""
    geom = GenericElement(
        tag="geom", attributes={"size": ".05", "contype": "0", "conaffinity": "0"}
    )
    attributes = {"name": "flag", "mocap": "true", "pos": "1 1 1"}
    flag = GenericElement(tag="body", attributes=attributes, children=[geom])
    world = model.worldbody
    children = [
        with_children(world, [*world.children[:-1], flag]) if c is world else c
        for c in model.children
    ]
    return with_children(model, children)


@pytest.mark.parametrize("generic", [False, True], ids=["typed", "generic_mocap_body"])
def test_two_fingers_at_a_body_sit_between_its_joints_and_the_later_ones(generic: bool) -> None:
    """Each finger's key sets it, every other part is at its own key or ``qpos0``, by name."""
    fingers = [(loads(FINGER), "l_"), (loads(FINGER), "r_")]
    model = (
        _with_generic_flag(loads(PARENT_PARTS_INSIDE_A_BODY))
        if generic
        else loads(PARENT_PARTS_INSIDE_A_BODY)
    )
    scene = compiled(attach_all(model, fingers, at="mount"))
    parent, finger = (
        _alone_parts_inside_a_body(PARENT_PARTS_INSIDE_A_BODY),
        _alone_parts_inside_a_body(FINGER),
    )
    assert scene.nkey == 3
    for key in ("pose", "l_closed", "r_closed"):
        for joint in ("rail", "knob", "elbow", "late"):
            own = _entries(parent, "pose", joint) if key == "pose" else _initial(parent, joint)
            assert _entries(scene, key, joint) == own, (key, joint)
        for prefix in ("l_", "r_"):
            mine = key == f"{prefix}closed"
            own = _entries(finger, "closed", "pinch") if mine else _initial(finger, "pinch")
            assert _entries(scene, key, prefix + "pinch") == own, (key, prefix)
    assert np.array_equal(scene.key("pose").mpos, parent.key("pose").mpos)


def test_a_parent_whose_replicate_hides_joints_is_refused_with_the_way_out() -> None:
    """A ``<replicate>`` in the parent: attach at the world or inline first, the error says."""
    replicated = loads(
        '<mujoco><worldbody><body name="shelf"><joint type="slide"/><geom size=".1"/></body>'
        '<replicate count="2" offset="1 0 0"><geom size=".1"/></replicate></worldbody>'
        '<keyframe><key qpos="0.2"/></keyframe></mujoco>'
    )
    with pytest.raises(
        MjcfValueError,
        match=r"whose <replicate> makes joints or bodies: attach at the world, or inline them "
        r"first \(mjcf_model\.inlined_attachments\)",
    ):
        attach(replicated, loads(FINGER), at="shelf", prefix="f_")


def test_a_mocap_part_inside_a_body_is_refused_naming_the_body() -> None:
    """A part with a mocap body attached at ``mount``: the error names the body it is inside."""
    target = loads(
        '<mujoco><worldbody><body name="t" mocap="true"><geom size=".1" contype="0" '
        'conaffinity="0"/></body></worldbody></mujoco>'
    )
    with pytest.raises(MjcfValueError, match=r"it is inside the <body> 'mount', and MuJoCo"):
        attach(loads(PARENT_PARTS_INSIDE_A_BODY), target, at="mount", prefix="t_")


# -- Which attached parts bring keyframe entries, refereed by MuJoCo compiling each part alone.
#
# A part brings entries to the scene's keys when it has anything a key sets: a
# joint, an actuator, a mocap body, a ``<key>`` or a ``<size nkey>``
# (mjcf_model/transforms/composition/keyframes.py). When one such part is
# attached between two others in one :func:`mjcf_model.attach_all`, the later
# part's entries must land after its own, so every key is checked, object by
# object, against the parts compiled alone (tests/support/composition_oracle.py). A part
# with nothing a key sets leaves the parent's keys alone, even a parent whose
# ``<replicate>`` hides where entries would go.


#: A part with every kind of entry: a mocap body, a joint, an actuator and a key setting all.
FULL = """<mujoco>
  <worldbody>
    <body name="goal" mocap="true" pos="0.5 0 0">
      <geom size=".05" contype="0" conaffinity="0"/>
    </body>
    <body name="link"><joint name="hinge" ref="10"/><geom size=".1"/></body>
  </worldbody>
  <actuator><motor name="drive" joint="hinge"/></actuator>
  <keyframe>
    <key name="home" qpos="0.7" qvel="0.3" ctrl="0.4" mpos="0.5 1 0" mquat="0 0 0 1"/>
  </keyframe>
</mujoco>
"""
#: Parts that each have one kind of entry only, and no key of their own (but ``ONLY_KEY``).
ONLY_ACTUATOR = """<mujoco>
  <worldbody><site name="spot"/></worldbody>
  <actuator><motor name="push" site="spot"/></actuator>
</mujoco>
"""
ONLY_MOCAP = """<mujoco>
  <worldbody>
    <body name="target" mocap="true" pos="0 1 0" quat="0 1 0 0">
      <geom size=".05" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>
"""
ONLY_JOINT = """<mujoco>
  <worldbody><body name="arm"><joint name="swing" type="slide" ref="0.1"/><geom size=".1"/></body>
  </worldbody>
</mujoco>
"""
ONLY_NKEY = '<mujoco><size nkey="1"/></mujoco>'
ONLY_KEY = '<mujoco><keyframe><key name="later" time="1.5"/></keyframe></mujoco>'
#: A parent with a key and a ``<replicate>`` (its copies' place in the keys is not in the tree).
REPLICATED = """<mujoco>
  <worldbody>
    <body name="shelf"><joint name="lift" type="slide"/><geom size=".1"/></body>
    <replicate count="2" offset="0.3 0 0"><geom size=".05" pos="0 1 0"/></replicate>
  </worldbody>
  <keyframe><key name="up" qpos="0.2"/></keyframe>
</mujoco>
"""
#: A part with nothing a key sets: a plain body (``mocap="false"``), a sensor, a ``<size>``.
STATELESS = """<mujoco>
  <size memory="1M"/>
  <worldbody><body name="box" mocap="false" pos="0 0 1"><geom size=".1"/></body></worldbody>
  <sensor><framepos name="where" objtype="body" objname="box"/></sensor>
</mujoco>
"""


def _alone_entries(text: str) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(text)


def _generic_mocap() -> Mujoco:
    """``ONLY_MOCAP`` with its body as a generic element (``mocap`` held as the text "true")."""
    geom = GenericElement(
        tag="geom", attributes={"size": ".05", "contype": "0", "conaffinity": "0"}
    )
    attributes = {"name": "target", "mocap": "true", "pos": "0 1 0", "quat": "0 1 0 0"}
    body = GenericElement(tag="body", attributes=attributes, children=[geom])
    return Mujoco(children=[Worldbody(children=[body])])


@pytest.mark.parametrize("generic", [False, True], ids=["typed", "generic_mocap_body"])
def test_every_part_with_something_a_key_sets_brings_its_entries(generic: bool) -> None:
    """An actuator, a mocap body, a joint, a key or ``<size nkey>`` alone each bring entries."""
    middle = [
        (ONLY_ACTUATOR, "u_"),
        (ONLY_MOCAP, "m_"),
        (ONLY_JOINT, "j_"),
        (ONLY_NKEY, "n_"),
        (ONLY_KEY, "k_"),
    ]
    parts = [(FULL, "a_"), *middle, (FULL, "b_")]
    models = [(loads(text), prefix) for text, prefix in parts]
    if generic:
        models[2] = (_generic_mocap(), "m_")
    scene = compiled(attach_all(loads(FULL), models))
    placed = [
        PlacedPart(_alone_entries(FULL)),
        *(PlacedPart(_alone_entries(t), p) for t, p in parts),
    ]
    assert scene.nkey == sum(part.alone.nkey for part in placed) == 5
    assert composition_problems(placed, scene) == []


def test_a_part_without_state_leaves_the_parents_keys_as_they_are() -> None:
    """Nothing to place (no joint, mocap, actuator or key): attaching inside a body just works.

    MuJoCo 3.9 copies the key at each ``<replicate>`` copy (``up0``, ``up1``, then ``up``).
    """
    scene = compiled(attach(loads(REPLICATED), loads(STATELESS), at="shelf", prefix="c_"))
    alone = _alone_entries(REPLICATED)
    assert scene.nkey == alone.nkey == (1 if MUJOCO_VERSION >= (4, 0) else 3)
    assert [scene.key(i).name for i in range(scene.nkey)] == [
        alone.key(i).name for i in range(alone.nkey)
    ]
    lift, own = scene.joint("lift").qposadr[0], alone.joint("lift").qposadr[0]
    assert scene.key("up").qpos[lift] == alone.key("up").qpos[own]
    assert scene.body("c_box").mocapid[0] == -1


# -- The values a composed key writes: zeros that are not the initial state, and nothing MuJoCo
#    fills.
#
# A key sets the whole state: ``qpos`` is always written, so a key holding every
# joint at zero is not completed to ``qpos0``; a mocap pose differing from the
# initial one is written even when it is all zeros (MuJoCo keeps a key's
# ``mquat`` as written). What MuJoCo would fill with the same value is left
# out: velocities, controls, activations and ``time`` that are zero, and mocap
# poses equal to the initial ones (``SceneKeys.nodes`` in
# mjcf_model/transforms/composition/keyframes.py). Expected values come from
# MuJoCo compiling each part alone (tests/support/composition_oracle.py).


#: A parent with no mocap body, whose hinge starts at zero.
PARENT_WRITTEN_VALUES = """<mujoco>
  <worldbody><body name="base"><joint name="yaw"/><geom size=".1"/></body></worldbody>
  <keyframe><key name="home" qpos="0.5"/></keyframe>
</mujoco>
"""
#: A part whose key sets its hinge to zero (``qpos0`` is 20 degrees) and its mocap pose to zeros.
CHILD_WRITTEN_VALUES = """<mujoco>
  <worldbody>
    <body name="arm"><joint name="bend" ref="20"/><geom size=".1"/></body>
    <body name="target" mocap="true" pos="0 1 0"><geom size=".05" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
  <keyframe><key name="zero" qpos="0" mpos="0 0 0" mquat="0 0 0 0"/></keyframe>
</mujoco>
"""


def _scene() -> Mujoco:
    return attach(loads(PARENT_WRITTEN_VALUES), loads(CHILD_WRITTEN_VALUES), prefix="c_")


def test_a_key_of_zeros_stays_zeros_in_the_scene() -> None:
    """The child's all-zero ``qpos``, ``mpos`` and ``mquat`` key is not completed to the initial."""
    scene = compiled(_scene())
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string(PARENT_WRITTEN_VALUES)),
        PlacedPart(mujoco.MjModel.from_xml_string(CHILD_WRITTEN_VALUES), "c_"),
    ]
    assert composition_problems(parts, scene) == []
    zero = scene.key("c_zero")
    assert zero.qpos.tolist() == [0.0, 0.0] and scene.qpos0[1] != 0.0
    assert zero.mpos.tolist() == [0.0] * 3 and zero.mquat.tolist() == [0.0] * 4


def test_the_parents_key_leaves_out_what_mujoco_fills_with_the_same_values() -> None:
    """The parent's ``home``: ``qpos`` written; no zero velocity, control or time, no mocap pose."""
    keyframe = _scene().keyframe
    assert keyframe is not None
    keys = {get_attribute(key, "name"): key for key in keyframe.keys}
    home, zero = keys["home"], keys["c_zero"]
    assert get_attribute(home, "qpos") is not None
    for attribute in ("qvel", "act", "ctrl", "mpos", "mquat", "time"):
        assert get_attribute(home, attribute) is None, attribute
    assert get_attribute(zero, "mpos") is not None and get_attribute(zero, "mquat") is not None


# -- keyframes='merged': a child key of the parent's key name joins it, with or without a
#    prefix.
#
# Under the merged policy keys of one name are one key, so a child attached
# without a prefix whose key has the parent's key name is not a name clash; a
# child without keys, or a parent without named keys, are composed as usual.
# Expected values come from MuJoCo compiling each part alone.


PARENT_MERGED_WITHOUT_PREFIX = """<mujoco>
  <worldbody><body name="base"><joint name="yaw"/><geom size=".1"/></body></worldbody>
  <keyframe><key name="home" qpos="0.5"/></keyframe>
</mujoco>
"""
#: A part whose hinge starts away from zero (``ref``), with a key named like the parent's.
CHILD_MERGED_WITHOUT_PREFIX = """<mujoco>
  <worldbody><body name="arm"><joint name="bend" ref="20"/><geom size=".1"/></body></worldbody>
  <keyframe><key name="home" qpos="0.25"/></keyframe>
</mujoco>
"""
KEYLESS = """<mujoco>
  <worldbody><body name="arm"><joint name="bend" ref="20"/><geom size=".1"/></body></worldbody>
</mujoco>
"""
#: A parent with a joint and no keyframes.
UNKEYED = """<mujoco>
  <worldbody><body name="base"><joint name="yaw" ref="10"/><geom size=".1"/></body></worldbody>
</mujoco>
"""


def _alone_merged_without_prefix(text: str) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(text)


def test_a_child_key_of_the_parents_name_joins_it_without_a_prefix() -> None:
    """Without a prefix, the child's ``home`` and the parent's are one key holding both."""
    scene = compiled(
        attach(
            loads(PARENT_MERGED_WITHOUT_PREFIX),
            loads(CHILD_MERGED_WITHOUT_PREFIX),
            keyframes="merged",
        )
    )
    assert scene.nkey == 1
    expected = np.concatenate(
        [
            _alone_merged_without_prefix(PARENT_MERGED_WITHOUT_PREFIX).key("home").qpos,
            _alone_merged_without_prefix(CHILD_MERGED_WITHOUT_PREFIX).key("home").qpos,
        ]
    )
    np.testing.assert_allclose(scene.key("home").qpos, expected)


def test_a_child_without_keys_is_merged_into_the_parents_keys() -> None:
    """Under the merged policy a keyless child adds its initial state to the parent's key."""
    scene = compiled(
        attach(loads(PARENT_MERGED_WITHOUT_PREFIX), loads(KEYLESS), keyframes="merged")
    )
    assert scene.nkey == 1
    expected = np.concatenate(
        [
            _alone_merged_without_prefix(PARENT_MERGED_WITHOUT_PREFIX).key("home").qpos,
            _alone_merged_without_prefix(KEYLESS).qpos0,
        ]
    )
    np.testing.assert_allclose(scene.key("home").qpos, expected)


def test_a_child_key_joins_a_parent_without_keys() -> None:
    """Into a parent without keys, the child's key is kept, the parent's entries at ``qpos0``."""
    scene = compiled(
        attach(loads(UNKEYED), loads(CHILD_MERGED_WITHOUT_PREFIX), prefix="c_", keyframes="merged")
    )
    assert scene.nkey == 1
    expected = np.concatenate(
        [
            _alone_merged_without_prefix(UNKEYED).qpos0,
            _alone_merged_without_prefix(CHILD_MERGED_WITHOUT_PREFIX).key("home").qpos,
        ]
    )
    np.testing.assert_allclose(scene.key_qpos[0], expected)


# -- A parent's keys get a keyless child's entries: its initial state, where MuJoCo numbers
#    them.
#
# When only the parent has keyframes, the child still adds joints, so every
# parent key is written whole again with the child's initial state spliced in
# where the child's joints go. Attached inside a body that comes before another
# jointed body, the child's joints sit between the parent's in ``qpos``: a key
# left as the parent wrote it would hand the parent's values to the wrong
# joints. MuJoCo compiling each part alone is the referee.


PARENT_KEYS_ONLY = """<mujoco>
  <worldbody>
    <body name="table"><joint name="lift" type="slide"/><geom size=".1"/></body>
    <body name="lamp" pos="1 0 0"><joint name="swing"/><geom size=".1"/></body>
  </worldbody>
  <keyframe><key name="home" qpos="0.3 0.7"/><key name="away" qpos="-0.2 0.4"/></keyframe>
</mujoco>
"""
#: A part without keys whose hinge starts away from zero (``ref``), so its initial state shows.
CHILD_KEYS_ONLY = """<mujoco>
  <worldbody><body name="arm"><joint name="bend" ref="20"/><geom size=".05"/></body></worldbody>
</mujoco>
"""
FREE = (
    '<mujoco><worldbody><body name="ball"><freejoint/><geom size=".1"/></body></worldbody></mujoco>'
)


def test_a_keyless_child_inside_a_body_gets_its_initial_state_in_the_parents_keys() -> None:
    """Each parent key keeps its values joint by joint; the child's hinge is at its ``qpos0``."""
    scene = compiled(
        attach(loads(PARENT_KEYS_ONLY), loads(CHILD_KEYS_ONLY), at="table", prefix="c_")
    )
    parent = mujoco.MjModel.from_xml_string(PARENT_KEYS_ONLY)
    child = mujoco.MjModel.from_xml_string(CHILD_KEYS_ONLY)
    assert scene.nkey == parent.nkey
    for key in ("home", "away"):
        for joint in ("lift", "swing"):
            got = scene.key(key).qpos[scene.joint(joint).qposadr[0]]
            assert got == parent.key(key).qpos[parent.joint(joint).qposadr[0]], (key, joint)
        bend = scene.key(key).qpos[scene.joint("c_bend").qposadr[0]]
        assert bend == pytest.approx(child.qpos0[child.joint("bend").qposadr[0]]), key


def test_a_free_part_inside_a_body_names_the_attach_point() -> None:
    """A free-jointed part attached inside a body is refused, naming where it was to go."""
    with pytest.raises(
        MjcfValueError, match=r"free joints or mocap bodies at 'table': it is inside"
    ):
        attach(loads(PARENT_KEYS_ONLY), loads(FREE), at="table", prefix="c_")
