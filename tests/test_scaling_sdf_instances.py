"""SDF plugin instances are found by name among instances only, and only where they are in sight.

A mesh or geom made through ``<plugin instance="..."/>`` scales through the
settings of the instance of that name (as in ``tests/fixtures/scaling/sdf.xml``); an
element of another kind may carry the same name, as MuJoCo allows. Scaling the
``<extension>`` section alone scales the settings as scaling the model does;
where the instance or its plugin is out of sight, nothing is guessed: settings
stay as written, and a mesh whose instance is missing is refused, as MuJoCo
rejects it.
"""

from __future__ import annotations

import re

import mujoco
import pytest

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.plugin import Plugin
from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.plugins import sdf_config, with_sdf_settings
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.traversal import with_children
from serializers import dumps, loads
from tests.support.scaling_oracle import IGNORED, scaled_model_problems

#: A torus made through an instance (one setting written), and a body named like it.
_TORUS = """<mujoco><extension><plugin plugin="mujoco.sdf.torus"><instance name="donut">
  <config key="radius1" value="0.2"/></instance></plugin></extension>
<asset><mesh name="donut_mesh"><plugin instance="donut"/></mesh></asset>
<worldbody><body name="donut" pos="0 0 .5"><freejoint/><geom type="sdf" mesh="donut_mesh">
  <plugin instance="donut"/></geom></body></worldbody></mujoco>"""
#: What the oracle leaves to the SDF tests of ``test_scaling_fixes`` (plugin settings).
_IGNORED = IGNORED["sdf.xml"]

#: What scaling says of a mesh whose plugin instance it cannot find.
_UNKNOWN_INSTANCE = (
    "cannot scale the mesh made by plugin None: mjcf-model does not know which of its "
    "settings are lengths"
)


def test_a_body_named_like_an_instance_leaves_the_instance_found() -> None:
    """A body called ``donut`` after the ``donut`` instance: the torus still scales."""
    original = mujoco.MjModel.from_xml_string(_TORUS)
    assert original.body("donut").id > 0
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(_TORUS), 2.0)))
    assert scaled_model_problems(original, changed, 2.0, ignore=_IGNORED) == []


def test_the_extension_section_scaled_alone_is_the_section_of_the_model_scaled() -> None:
    """Its instances' settings scale, and are completed, as in the whole scaled model.

    Put in place of that model's section, MuJoCo compiles it to the original scaled.
    """
    model = loads(_TORUS)
    whole = scaled(model, 2.0)
    alone = scaled(model.extension, 2.0)
    assert alone == whole.extension
    spliced = with_children(whole, [alone if c is whole.extension else c for c in whole.children])
    original = mujoco.MjModel.from_xml_string(_TORUS)
    changed = mujoco.MjModel.from_xml_string(dumps(spliced))
    assert scaled_model_problems(original, changed, 2.0, ignore=_IGNORED) == []


def test_a_setting_scales_only_when_its_plugin_is_in_sight() -> None:
    """Read under its instance and plugin, a torus radius scales; without them it is kept.

    A lone instance, or a setting read without its owners, names no plugin.
    """
    plugin = loads(_TORUS).extension.elements[0]
    instance = plugin.elements[0]
    assert instance.tag == "instance"
    assert scaled(instance, 2.0) is instance
    context = ScaleContext(factors=(2.0, 2.0, 2.0))
    setting = instance.elements[0]
    assert (setting.key, setting.value) == ("radius1", "0.2")
    assert sdf_config(setting, (plugin, instance), context) == {"value": "0.4"}
    assert sdf_config(setting, (), context) == {}
    assert with_sdf_settings(instance, "extension/plugin/instance", (), context) is instance
    assert sdf_config(setting, (instance,), context) == {}


def test_a_mesh_whose_instance_is_out_of_sight_is_refused_as_mujoco_rejects_it() -> None:
    """The asset section alone (instances elsewhere), or a plugin use read without a model.

    MuJoCo rejects that section compiled alone: the instance is unknown.
    """
    model = loads(_TORUS)
    alone = f"<mujoco>{dumps(model.asset)}</mujoco>"
    with pytest.raises(ValueError, match="unrecognized name 'donut' for plugin instance"):
        mujoco.MjModel.from_xml_string(alone)
    with pytest.raises(MjcfValueError, match=re.escape(_UNKNOWN_INSTANCE)):
        scaled(model.asset, 2.0)
    context = ScaleContext(factors=(2.0, 2.0, 2.0))  # no model
    with pytest.raises(MjcfValueError, match=re.escape(_UNKNOWN_INSTANCE)):
        with_sdf_settings(Plugin(instance="donut"), "asset/mesh/plugin", (), context)


@pytest.mark.parametrize("scale", ["", ' scale="1 1 1"'], ids=["unwritten", "written"])
def test_an_sdf_mesh_with_no_scale_but_mujocos_is_left_shared(scale: str) -> None:
    """A plugin mesh writes no scale, or ``scale="1 1 1"`` (MuJoCo refuses any other).

    Nothing in it changes: the asset section is shared by the scaled model, and
    MuJoCo compiles that model to the original scaled.
    """
    text = _TORUS.replace('<mesh name="donut_mesh">', f'<mesh name="donut_mesh"{scale}>')
    model = loads(text)
    result = scaled(model, 2.0)
    assert result.asset is model.asset
    original = mujoco.MjModel.from_xml_string(text)
    changed = mujoco.MjModel.from_xml_string(dumps(result))
    assert scaled_model_problems(original, changed, 2.0, ignore=_IGNORED) == []
