"""Tests of ``mjcf_model.transforms.scaling.plugins``."""

from __future__ import annotations

import re

import mujoco
import numpy as np
import pytest

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.plugin import Plugin
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.plugins import SDF_LENGTHS, sdf_config, with_sdf_settings
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.traversal import with_children
from tests.support.oracles import friction_problems, scaled_problems
from tests.support.scaling_oracle import (
    IGNORED,
    SCALING_FIXTURES,
    _scaled_copy,
    scaled_model_problems,
)

# -- Scaling on constructs real models use: masses, shells, flexcomps, SDFs, includes, skin
#    files.
#
# The fixtures live in ``tests/fixtures/scaling``; MuJoCo compiles each original and
# each scaled copy, and the oracle compares the compiled arrays.


def test_sdf_settings_are_scaled_instead_of_the_mesh_scale() -> None:
    """No ``scale`` on SDF meshes; the torus's unwritten ``radius2`` is written, scaled."""
    model = scaled(load(SCALING_FIXTURES / "sdf.xml"), 2)
    text = dumps(model)
    assert 'key="radius1" value="0.4"' in text
    assert 'key="radius2" value="0.3"' in text
    mujoco.MjModel.from_xml_string(text)  # MuJoCo refuses a scale on an SDF mesh


@pytest.mark.parametrize("plugin", ["nut", "bolt"])
def test_sdf_plugin_with_fixed_dimensions_is_refused(plugin: str) -> None:
    """MuJoCo's nut and bolt SDFs compile but have no length settings: scaling names them."""
    text = (
        (SCALING_FIXTURES / "sdf_fixed_shape.xml").read_text().replace("sdf.nut", f"sdf.{plugin}")
    )
    assert mujoco.MjModel.from_xml_string(text).nmesh == 1
    with pytest.raises(MjcfValueError) as refused:
        scaled(loads(text), 2)
    assert str(refused.value) == _refusal(
        "mesh", f"mujoco.sdf.{plugin}", "its dimensions are fixed in the plugin's code"
    )


def _refusal(owner: str, plugin: str, why: str) -> str:
    """What scaling says of a shape plugin it cannot scale: why, and what to do."""
    return (
        f"cannot scale the {owner} made by plugin {plugin!r}: {why}; only "
        f"{', '.join(SDF_LENGTHS)} scale. Replace that shape (or scale its settings "
        "yourself and take it out of the model) before scaling"
    )


#: The gear SDF's settings in the order MuJoCo keeps them, with its defaults
#: (``innerdiameter`` below zero: derived from the diameter), and whether each is a length.
_GEAR_SETTINGS = (
    ("alpha", 0.0, False),
    ("diameter", 2.8, True),
    ("teeth", 25.0, False),
    ("thickness", 0.2, True),
    ("innerdiameter", -1.0, True),
)


def _gear_settings(model: mujoco.MjModel) -> np.ndarray:
    """Each gear instance's settings as the plugin reads them, defaults filled in."""
    values = []
    for start in model.plugin_attradr:
        fields = model.plugin_attr[start:].tobytes().decode().split("\0")[: len(_GEAR_SETTINGS)]
        values.append(
            [float(f) if f else d for f, (_, d, _) in zip(fields, _GEAR_SETTINGS, strict=True)]
        )
    return np.array(values)


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_gear_sdf_scales_through_its_length_settings(factor: float) -> None:
    """The gear's diameter, thickness and bore scale, and with them the shape MuJoCo builds.

    Its bounding boxes (the plugin's, and the mesh MuJoCo makes of it) and bounding
    spheres scale exactly. The mesh itself is rebuilt: MuJoCo meshes the gear with a
    numerical gradient, so vertex counts and volumes differ slightly (measured on
    MuJoCo 4.0.0 and 3.9.0: volume within 0.4% of ``factor**3``).
    """
    path = SCALING_FIXTURES / "sdf_gear.xml"
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = _scaled_copy(path, factor)
    lengths = np.array([length for _, _, length in _GEAR_SETTINGS])
    before, after = _gear_settings(original), _gear_settings(changed)
    factors = np.where(lengths & (before >= 0), factor, 1.0)  # a negative bore stays derived
    assert np.allclose(after, factors * before, rtol=1e-12, atol=0)
    assert scaled_problems(original, changed, factor, ["geom_aabb", "geom_rbound"]) == []
    assert np.allclose(_mesh_boxes(changed), factor * _mesh_boxes(original), rtol=1e-6, atol=0)
    assert np.allclose(changed.body_mass, original.body_mass, rtol=5e-3, atol=0)
    assert friction_problems(original, changed, factor) == []


def _mesh_boxes(model: mujoco.MjModel) -> np.ndarray:
    """Each mesh's lowest and highest vertex coordinates."""
    boxes = []
    for start, count in zip(model.mesh_vertadr, model.mesh_vertnum, strict=True):
        vertices = model.mesh_vert[start : start + count]
        boxes.append(np.concatenate([vertices.min(axis=0), vertices.max(axis=0)]))
    return np.array(boxes)


@pytest.mark.parametrize("owner", ["mesh", "geom"])
def test_unknown_shape_plugin_is_refused(owner: str) -> None:
    """A mesh or geom made by a plugin mjcf-model does not know raises an error naming it."""
    use = '<plugin plugin="acme.sdf.blob"><config key="size" value="1"/></plugin>'
    mesh = f'<mesh name="m">{use if owner == "mesh" else ""}</mesh>'
    geom = f'<geom type="sdf" mesh="m">{use if owner == "geom" else ""}</geom>'
    model = loads(
        f"<mujoco><asset>{mesh}</asset><worldbody><body>{geom}</body></worldbody></mujoco>"
    )
    with pytest.raises(MjcfValueError) as refused:
        scaled(model, 2)
    why = "mjcf-model does not know which of its settings are lengths"
    assert str(refused.value) == _refusal(owner, "acme.sdf.blob", why)


# -- SDF plugin instances are found by name among instances only, and only where they are in
#    sight.
#
# A mesh or geom made through ``<plugin instance="..."/>`` scales through the
# settings of the instance of that name (as in ``tests/fixtures/scaling/sdf.xml``); an
# element of another kind may carry the same name, as MuJoCo allows. Scaling the
# ``<extension>`` section alone scales the settings as scaling the model does;
# where the instance or its plugin is out of sight, nothing is guessed: settings
# stay as written, and a mesh whose instance is missing is refused, as MuJoCo
# rejects it.


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
