"""Tests of ``mjcf_model.strategies.sections``: sections referring to a drawn tree."""

from __future__ import annotations

import mujoco
from hypothesis import given

from mjcf_model import Mujoco
from mjcf_model.serializers import dumps, loads
from mjcf_model.strategies import models
from mjcf_model.strategies.sections import _joint_types

#: Joints in nested bodies, frames and a free body, written out of MuJoCo's order.
TREE = """<mujoco><worldbody>
  <body name="a"><joint type="slide"/><geom size="0.1"/>
    <body name="b"><joint type="ball"/><geom size="0.1"/></body>
    <joint name="late"/>
  </body>
  <frame><body name="c"><freejoint/><geom size="0.1"/></body></frame>
</worldbody></mujoco>"""


def test_joint_types_come_in_mujocos_joint_order() -> None:
    """The types of the tree's joints are listed as MuJoCo numbers the joints."""
    compiled = mujoco.MjModel.from_xml_string(TREE)
    kinds = {"free": 0, "ball": 1, "slide": 2, "hinge": 3}
    assert [kinds[t] for t in _joint_types(loads(TREE).worldbody)] == compiled.jnt_type.tolist()


@given(models())
def test_drawn_keys_have_the_sizes_mujoco_compiles(model: Mujoco) -> None:
    """Every key the sections draw writes full state vectors: MuJoCo's sizes, no padding."""
    compiled = mujoco.MjModel.from_xml_string(dumps(model))
    keyframe = model.keyframe
    for key in () if keyframe is None else keyframe.keys:
        assert key.qpos is None or len(key.qpos) == compiled.nq
        assert key.ctrl is None or len(key.ctrl) == compiled.nu
        assert key.act is None or len(key.act) == compiled.na
