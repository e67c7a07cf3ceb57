"""Keys of a part with plastic state are refused; a MuJoCo without plastic state reads as usual.

MuJoCo 4.0 keeps a plastic state per yielding joint (``springyield``) in each key
(``key_plastic``), which composing does not carry yet: attaching such a part with
keyframes raises :class:`MjcfValueError` telling the user to remove its keyframes.
MuJoCo before 4.0 (the oldest supported release is 3.9) compiles models with no
``key_plastic`` at all; their states are read from the arrays MuJoCo compiles.
MuJoCo 3.9 rejects ``springyield``, so there the keyed part is refused as a part
MuJoCo cannot compile.
"""

from __future__ import annotations

from typing import Any, cast

import mujoco
import numpy as np
import pytest

from mjcf_model import MjcfValueError, attach
from mjcf_model.errors import MjcfCompileError
from mjcf_model.transforms.composition.part_states import PartStates
from serializers import loads
from tests.conftest import MUJOCO_VERSION

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
