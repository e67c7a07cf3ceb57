"""Tests of ``mjcf_model.nodes.actuator.special``: plugin and ``<adhesion>`` actuators."""

from __future__ import annotations

import mujoco

from mjcf_model import ActuatorPlugin, Adhesion
from mjcf_model.serializers import load, loads
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

MODULE = "mjcf_model.nodes.actuator.special"

#: A PID plugin actuator beside an ordinary motor.
PID = """<mujoco>
  <extension>
    <plugin plugin="mujoco.pid">
      <instance name="pid"><config key="ki" value="4"/><config key="imax" value="5"/></instance>
    </plugin>
  </extension>
  <worldbody><body><joint name="j"/><geom size="0.1"/></body></worldbody>
  <actuator>
    <motor name="m" joint="j"/>
    <plugin name="p" plugin="mujoco.pid" instance="pid" joint="j" actdim="1"/>
  </actuator>
</mujoco>
"""


def test_adhesion_and_plugin_actuators_load_typed_and_compile_as_written() -> None:
    """``<adhesion>``'s gain is MuJoCo's gain; a ``<plugin>`` actuator is MuJoCo's plugin one."""
    mechanics, pid = load(FIXTURES / "mechanics.xml"), loads(PID)
    assert loaded_from(mechanics, MODULE) == {"Adhesion"}
    assert loaded_from(pid, MODULE) == {"ActuatorPlugin"}
    assert {"Adhesion", "ActuatorPlugin"} <= declared_in(MODULE)
    compiled = mujoco.MjModel.from_xml_path(str(FIXTURES / "mechanics.xml"))
    glue = next(a for a in mechanics.actuator.elements if isinstance(a, Adhesion))
    assert glue.gain == compiled.actuator("glue").gainprm[0]
    with_plugin = mujoco.MjModel.from_xml_string(PID)
    kinds = [isinstance(a, ActuatorPlugin) for a in pid.actuator.elements]
    assert kinds == [p >= 0 for p in with_plugin.actuator_plugin] == [False, True]
    assert text_round_trip_differences(PID) == []
    assert text_round_trip_differences((FIXTURES / "mechanics.xml").read_text()) == []
