"""Tests of ``mjcf_model.nodes.plugin``: the ``<extension>`` section and plugin elements."""

from __future__ import annotations

import mujoco

from mjcf_model import Extension, ExtensionPlugin, Plugin, PluginConfig, PluginInstance
from mjcf_model.bridge.compare import compiled_names
from mjcf_model.serializers import loads
from tests.support.node_classes import loaded_from, text_round_trip_differences

#: A configured PID instance, declared in ``<extension>``, that an actuator uses.
PID = """<mujoco>
  <extension>
    <plugin plugin="mujoco.pid">
      <instance name="pid">
        <config key="kp" value="40"/><config key="ki" value="4"/><config key="imax" value="5"/>
      </instance>
    </plugin>
  </extension>
  <worldbody><body><joint name="j"/><geom size="0.1"/></body></worldbody>
  <actuator><plugin plugin="mujoco.pid" instance="pid" joint="j" actdim="1"/></actuator>
</mujoco>
"""
MODULE = "mjcf_model.nodes.plugin"


def test_an_instance_and_its_settings_are_the_plugin_mujoco_makes() -> None:
    """The declared instance is MuJoCo's plugin; its settings are the values MuJoCo holds."""
    model = loads(PID)
    assert loaded_from(model, MODULE) == {
        "Extension",
        "ExtensionPlugin",
        "PluginInstance",
        "PluginConfig",
    }
    compiled = mujoco.MjModel.from_xml_string(PID)
    extension = next(c for c in model.children if isinstance(c, Extension))
    plugin = extension.children[0]
    assert isinstance(plugin, ExtensionPlugin) and plugin.plugin == "mujoco.pid"
    instance = plugin.children[0]
    assert isinstance(instance, PluginInstance)
    assert compiled_names(compiled)["plugin"] == [instance.name]
    assert compiled.actuator_plugin.tolist() == [0]
    configs = [c for c in instance.children if isinstance(c, PluginConfig)]
    held = [value for value in bytes(compiled.plugin_attr).split(b"\0") if value]
    assert held == [c.value.encode() for c in configs] == [b"40", b"4", b"5"]
    assert text_round_trip_differences(PID) == []


def test_an_element_using_an_instance_is_a_plugin_element() -> None:
    """``<plugin instance=...>`` inside a mesh, a geom or a body is this module's ``Plugin``."""
    model = loads(
        '<mujoco><asset><mesh name="m"><plugin instance="shape"/></mesh></asset>'
        '<worldbody><body><plugin instance="cable"/></body></worldbody></mujoco>'
    )
    used = [model.asset.meshes[0].children[0], model.worldbody.bodies[0].children[0]]
    assert all(isinstance(p, Plugin) for p in used)
    assert [p.instance for p in used] == ["shape", "cable"]
