"""Tests of ``mjcf_model.nodes.visual``: the ``<visual>`` section, kept as text."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Visual
from mjcf_model.nodes.base import attribute_text
from mjcf_model.serializers import loads
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

#: Every ``<visual>`` child, each with a value MuJoCo's defaults do not have.
VISUAL = """<mujoco>
  <visual>
    <global fovy="50" offwidth="800"/>
    <quality shadowsize="1024"/>
    <headlight ambient="0.2 0.2 0.2"/>
    <map znear="0.02"/>
    <scale forcewidth="0.2"/>
    <rgba haze="1 0 0 1"/>
  </visual>
</mujoco>
"""
MODULE = "mjcf_model.nodes.visual"


def test_visual_settings_load_typed_and_are_what_mujoco_compiles() -> None:
    """Each child is this module's class, and the text it keeps is the value MuJoCo reads."""
    model = loads(VISUAL)
    assert loaded_from(model, MODULE) == declared_in(MODULE)
    visual = next(c for c in model.children if isinstance(c, Visual))
    compiled = mujoco.MjModel.from_xml_string(VISUAL)
    settings = {child.tag: child for child in visual.children}
    assert float(attribute_text(settings["global"], "fovy")) == compiled.vis.global_.fovy
    assert int(attribute_text(settings["global"], "offwidth")) == compiled.vis.global_.offwidth
    assert int(attribute_text(settings["quality"], "shadowsize")) == compiled.vis.quality.shadowsize
    ambient = np.float32(attribute_text(settings["headlight"], "ambient").split())
    assert np.array_equal(ambient, compiled.vis.headlight.ambient)
    assert np.float32(attribute_text(settings["map"], "znear")) == compiled.vis.map.znear
    assert (
        np.float32(attribute_text(settings["scale"], "forcewidth")) == compiled.vis.scale.forcewidth
    )
    haze = np.float32(attribute_text(settings["rgba"], "haze").split())
    assert np.array_equal(haze, compiled.vis.rgba.haze)
    assert text_round_trip_differences(VISUAL) == []
