"""Tests of ``mjcf_model.transforms.composition.part_states``."""

from __future__ import annotations

import re
from typing import Any, cast

import mujoco
import numpy as np
import pytest

from mjcf_model import MjcfCompileError, MjcfValueError, attach, compiled
from mjcf_model.serializers import load, loads
from mjcf_model.transforms.composition.part_states import PartStates
from tests.conftest import FIXTURES, MUJOCO_VERSION
from tests.support.composition_oracle import PlacedPart, composition_problems

# -- Keys of a free part attached inside a frame of a parent written in radians and ``zyx``
#    angles.
#
# The key poses move by the frame's world pose, with the frame's ``euler`` read as
# MuJoCo reads it under the parent's ``<compiler angle eulerseq>``. MuJoCo is the
# referee: the parent compiled alone gives the site's world pose, the part compiled
# alone gives its key (``tests/support/composition_oracle.py``).


#: A parent in radians with ``zyx`` Euler angles, and a site inside a turned frame.
PARENT = """<mujoco>
  <compiler angle="radian" eulerseq="zyx"/>
  <worldbody>
    <frame pos="1 2 3" euler="0.3 0.5 0.7"><site name="s"/></frame>
  </worldbody>
</mujoco>
"""
#: A free body with a key that sets its pose and velocity.
PART_FRAME_ANGLES = """<mujoco>
  <worldbody>
    <body name="box" pos="0.1 0.2 0.3"><freejoint name="free"/><geom size=".1"/></body>
  </worldbody>
  <keyframe><key name="thrown" qpos="1 -2 0.5 0 1 0 0" qvel="1 2 3 0 0 1"/></keyframe>
</mujoco>
"""


def test_keys_move_by_a_frame_read_in_the_parents_angle_units_and_euler_sequence() -> None:
    """A frame's radian ``zyx`` Euler angles place the part's keys where MuJoCo places the site."""
    scene = compiled(attach(loads(PARENT), loads(PART_FRAME_ANGLES), at="s", prefix="c_"))
    parent = mujoco.MjModel.from_xml_string(PARENT)
    site = parent.site("s")
    placed = PlacedPart(
        mujoco.MjModel.from_xml_string(PART_FRAME_ANGLES),
        "c_",
        pos=tuple(float(v) for v in site.pos),
        quat=tuple(float(v) for v in site.quat),
    )
    assert scene.nkey == 1
    assert composition_problems([PlacedPart(parent), placed], scene) == []


# -- Composing keyframes with a part MuJoCo rejects: the error says why the part must compile
#    alone.
#
# Keys are composed from each part compiled on its own, so a part that does not
# compile raises :class:`MjcfCompileError` with MuJoCo's own message, located in
# the part's file, line and element, and told that the part must compile on its own.


#: A free body with no geom (no mass), which MuJoCo rejects, and a key.
MASSLESS = FIXTURES / "part_states" / "massless.xml"


def test_a_part_that_does_not_compile_alone_is_refused_with_its_location() -> None:
    """MuJoCo's message, the part's file, line and element, and that it must compile alone."""
    path = MASSLESS  # MuJoCo reads the same file the part is loaded from
    with pytest.raises(ValueError) as rejected:
        mujoco.MjModel.from_xml_path(str(path))
    first, located = str(rejected.value).splitlines()[:2]
    mujocos = first.removeprefix("Error: ")
    line = re.search(r"line (\d+)", located)
    assert line is not None
    with pytest.raises(MjcfCompileError, match="the part must compile on its own") as caught:
        attach(loads("<mujoco/>"), load(path), prefix="c_")
    error = caught.value
    assert mujocos in error.detail
    assert "composing keyframes reads each part's initial state and keys" in error.detail
    assert error.file == str(path)
    assert error.line == int(line.group(1))
    assert error.path == "/mujoco/worldbody/body[@name='float']"
    assert str(error).startswith(f"{path}:{error.line}: {error.path}: ")


# -- Keys of a part with plastic state are refused; a MuJoCo without plastic state reads as
#    usual.
#
# MuJoCo 4.0 keeps a plastic state per yielding joint (``springyield``) in each key
# (``key_plastic``), which composing does not carry yet: attaching such a part with
# keyframes raises :class:`MjcfValueError` telling the user to remove its keyframes.
# MuJoCo before 4.0 (the oldest supported release is 3.9) compiles models with no
# ``key_plastic`` at all; their states are read from the arrays MuJoCo compiles.
# MuJoCo 3.9 rejects ``springyield``, so there the keyed part is refused as a part
# MuJoCo cannot compile.


#: A hinge that yields (plastic state) and a key.
YIELDING = """<mujoco>
  <worldbody>
    <body><joint name="h" stiffness="10" springyield="1"/><geom size=".1"/></body>
  </worldbody>
  <keyframe><key name="bent" qpos="0.5"/></keyframe>
</mujoco>
"""
#: A free body, a hinge with a reference angle and an actuator, with a key.
PLAIN = """<mujoco>
  <worldbody>
    <body pos="0 0 1"><freejoint/><geom size=".1"/></body>
    <body><joint name="h" ref="20"/><geom size=".1"/></body>
  </worldbody>
  <actuator><motor joint="h"/></actuator>
  <keyframe><key name="k" qpos="1 2 3 1 0 0 0 0.4" ctrl="0.7" time="1.5"/></keyframe>
</mujoco>
"""


class _WithoutPlasticState:
    """A compiled model as MuJoCo before 4.0 gives it: every array but ``key_plastic``."""

    def __init__(self, model: mujoco.MjModel) -> None:
        self._model = model

    def __getattr__(self, name: str) -> Any:
        if name == "key_plastic":
            raise AttributeError(name)
        return getattr(self._model, name)


def test_a_part_with_plastic_state_and_keys_is_refused_with_the_way_out() -> None:
    """A yielding joint's part with keys raises MjcfValueError: remove its keyframes.

    MuJoCo 3.9 has no ``springyield``: the part is refused as MuJoCo rejects it.
    """
    if MUJOCO_VERSION < (4, 0):
        with pytest.raises(ValueError, match="unrecognized attribute: 'springyield'"):
            mujoco.MjModel.from_xml_string(YIELDING)
        with pytest.raises(
            MjcfCompileError,
            match=r"^<string>:3: /mujoco/worldbody/body/joint\[@name='h'\]: MuJoCo rejects the "
            r"model: .*unrecognized attribute: 'springyield'.*the part must compile on its own\)$",
        ):
            attach(loads("<mujoco/>"), loads(YIELDING), prefix="c_")
        return
    assert mujoco.MjModel.from_xml_string(YIELDING).nplastic == 1
    with pytest.raises(
        MjcfValueError,
        match=r"^cannot compose keyframes of a model with plastic state yet; "
        r"remove its keyframes before attaching$",
    ):
        attach(loads("<mujoco/>"), loads(YIELDING), prefix="c_")


def test_states_of_a_model_compiled_without_plastic_state_are_mujocos_arrays() -> None:
    """With no ``key_plastic`` (MuJoCo before 4.0) the states are read, not refused."""
    mj = mujoco.MjModel.from_xml_string(PLAIN)
    states = PartStates.of_compiled(cast(mujoco.MjModel, _WithoutPlasticState(mj)))
    assert np.array_equal(states.initial.qpos, mj.qpos0)
    assert np.array_equal(states.keys[0].qpos, mj.key_qpos[0])
    assert np.array_equal(states.keys[0].ctrl, mj.key_ctrl[0])
    assert states.keys[0].time == mj.key_time[0]
    assert states.free_qpos == (int(mj.jnt_qposadr[0]),)


# -- Keys of a placed part with several mocap bodies and a free joint between other joints. ----
#
# Each mocap body's key pose and the free joint's key pose and linear velocity
# move with the placement, entry by entry, whatever their place in the arrays;
# the other joints' values stay. MuJoCo is the referee: the part compiled alone,
# moved with MuJoCo's quaternion functions (``tests/support/composition_oracle.py``).


#: A hinge, a free body and a slide (the free joint's entries are in the middle of
#: ``qpos`` and ``qvel``), then three mocap bodies, each with its own key pose.
PART_MOCAP_BODIES = """<mujoco>
  <worldbody>
    <body name="first"><joint name="h0"/><geom size=".1"/></body>
    <body name="floater" pos="0 0 1"><freejoint name="free"/><geom size=".1"/></body>
    <body name="last" pos="2 0 0"><joint name="s0" type="slide"/><geom size=".1"/></body>
    <body name="m0" mocap="true" pos="1 0 0"/>
    <body name="m1" mocap="true" pos="0 1 0" quat="0 0 0 1"/>
    <body name="m2" mocap="true" pos="0 0 1" euler="30 0 0"/>
  </worldbody>
  <keyframe>
    <key name="home" qpos="0.3 1 2 3 0 1 0 0 0.2" qvel="0.5 1 2 3 0.1 0.2 0.3 0.4"
         mpos="1 2 3 4 5 6 7 8 9" mquat="1 0 0 0 0 1 0 0 0 0 1 0"/>
  </keyframe>
</mujoco>
"""
#: A placement that turns and shifts (90 degrees about z, then a shift).
PLACE = {"pos": (0.5, -1.0, 2.0), "quat": (0.7071067811865476, 0.0, 0.0, 0.7071067811865476)}


def test_every_mocap_body_and_a_free_joint_among_others_move_with_the_placement() -> None:
    """Each of three mocap bodies and a mid-array free joint are moved; other entries stay."""
    scene = compiled(attach(loads("<mujoco/>"), loads(PART_MOCAP_BODIES), prefix="c_", **PLACE))  # type: ignore[arg-type]
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string("<mujoco/>")),
        PlacedPart(mujoco.MjModel.from_xml_string(PART_MOCAP_BODIES), "c_", **PLACE),  # type: ignore[arg-type]
    ]
    assert scene.nkey == 1
    assert composition_problems(parts, scene) == []


# -- A free or mocap part attached at the world, unmoved, keeps its key values bit for bit. ----
#
# With no placement there is nothing to move: each value of the part's key is the
# one MuJoCo compiles for the part alone, signed zeros included (``-0`` in a key
# stays ``-0``). MuJoCo is the referee: the part compiled alone.


#: A free body and a mocap body whose key writes negative zeros.
PART_UNPLACED_KEYS = """<mujoco>
  <worldbody>
    <body pos="0 0 1"><freejoint/><geom size=".1"/></body>
    <body mocap="true" pos="1 1 0"/>
  </worldbody>
  <keyframe><key name="k" qpos="-0 0 2 1 -0 0 0" mpos="-0 2 0"/></keyframe>
</mujoco>
"""


def test_a_part_attached_unmoved_keeps_its_keys_bit_for_bit() -> None:
    """At the world with no placement, key ``qpos`` and ``mpos`` equal MuJoCo's exactly."""
    alone = mujoco.MjModel.from_xml_string(PART_UNPLACED_KEYS)
    assert np.signbit(alone.key_qpos[0][0]) and np.signbit(alone.key_mpos[0][0])
    scene = compiled(attach(loads("<mujoco/>"), loads(PART_UNPLACED_KEYS), prefix="c_"))
    key = scene.key("c_k")
    assert key.qpos.tobytes() == alone.key_qpos[0].tobytes()
    assert key.mpos.tobytes() == alone.key_mpos[0].tobytes()
    assert key.mquat.tobytes() == alone.key_mquat[0].tobytes()
