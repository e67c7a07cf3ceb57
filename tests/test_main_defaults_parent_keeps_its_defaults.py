"""The parent's top-level defaults keep reaching its own elements once a child is attached.

:func:`mjcf_model.attach` moves the parent's top-level ``<default>`` settings into
a class of their own (``main_defaults.with_main_as_class``). MuJoCo is the
referee: the scene's rows for the parent's objects must equal the parent
compiled alone (:func:`tests.support.composition_oracle.composition_problems`), and the
values checked by name are the ones MuJoCo gives the parent alone.
"""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import attach, compiled
from serializers import loads
from tests.support.composition_oracle import PlacedPart, composition_problems

#: A child with a body of its own, whose geom must keep MuJoCo's default colour.
CHILD = (
    '<mujoco><worldbody><body name="cup"><geom name="cup" size=".1"/></body></worldbody></mujoco>'
)


def _scene_and_problems(parent_text: str) -> tuple[mujoco.MjModel, mujoco.MjModel, list[str]]:
    """The parent alone, the scene with ``CHILD`` attached, and what differs from the parts."""
    alone = mujoco.MjModel.from_xml_string(parent_text)
    child = mujoco.MjModel.from_xml_string(CHILD)
    scene = compiled(attach(loads(parent_text), loads(CHILD), prefix="c_"))
    parts = [PlacedPart(alone), PlacedPart(child, prefix="c_")]
    return alone, scene, composition_problems(parts, scene)


def _geom_rgba(model: mujoco.MjModel, name: str) -> list[float]:
    """The compiled colour of the geom ``name``."""
    return [float(v) for v in model.geom(name).rgba]


def test_an_explicit_class_main_keeps_the_parents_top_level_settings() -> None:
    """A parent geom naming ``class="main"`` inside a ``childclass`` keeps the top-level colour."""
    parent = """<mujoco>
      <default>
        <geom rgba="1 0 0 1"/>
        <default class="green"><geom rgba="0 1 0 1"/></default>
      </default>
      <worldbody>
        <body name="b" childclass="green">
          <geom name="named_main" class="main" size=".1"/>
          <geom name="inherits_green" size=".1"/>
        </body>
      </worldbody>
    </mujoco>"""
    alone, scene, problems = _scene_and_problems(parent)
    assert _geom_rgba(alone, "named_main") == [1.0, 0.0, 0.0, 1.0]  # MuJoCo: class main wins
    assert _geom_rgba(alone, "inherits_green") == [0.0, 1.0, 0.0, 1.0]
    assert _geom_rgba(scene, "named_main") == [1.0, 0.0, 0.0, 1.0]
    assert _geom_rgba(scene, "inherits_green") == [0.0, 1.0, 0.0, 1.0]
    assert _geom_rgba(scene, "c_cup") == [0.5, 0.5, 0.5, 1.0]  # MuJoCo's default colour
    assert problems == []


def test_an_explicit_childclass_main_keeps_the_parents_top_level_settings() -> None:
    """A parent body with ``childclass="main"`` in another class gives its geoms the top level."""
    parent = """<mujoco>
      <default>
        <geom rgba="1 0 0 1"/>
        <default class="green"><geom rgba="0 1 0 1"/></default>
      </default>
      <worldbody>
        <body name="outer" childclass="green">
          <geom name="green_geom" size=".1"/>
          <body name="inner" childclass="main"><geom name="main_geom" size=".1"/></body>
        </body>
      </worldbody>
    </mujoco>"""
    alone, scene, problems = _scene_and_problems(parent)
    assert _geom_rgba(alone, "main_geom") == [1.0, 0.0, 0.0, 1.0]
    assert _geom_rgba(scene, "main_geom") == [1.0, 0.0, 0.0, 1.0]
    assert _geom_rgba(scene, "green_geom") == [0.0, 1.0, 0.0, 1.0]
    assert problems == []


def test_several_top_level_default_sections_all_keep_reaching_the_parent() -> None:
    """A parent with two top-level ``<default>`` sections compiles as alone after an attach."""
    parent = """<mujoco>
      <default><geom rgba="1 0 0 1"/></default>
      <default><joint damping="3"/></default>
      <worldbody>
        <body name="b"><joint name="hinge"/><geom name="g" size=".1"/></body>
      </worldbody>
    </mujoco>"""
    alone, scene, problems = _scene_and_problems(parent)
    assert float(alone.joint("hinge").damping[0]) == 3.0  # MuJoCo: both sections set main
    assert float(scene.joint("hinge").damping[0]) == 3.0
    assert _geom_rgba(scene, "g") == [1.0, 0.0, 0.0, 1.0]
    assert problems == []


def test_the_parents_top_level_actuator_defaults_keep_reaching_its_actuators() -> None:
    """A parent's top-level ``<motor gear>`` still sets its motors' gear after an attach."""
    parent = """<mujoco>
      <default><motor gear="7"/></default>
      <worldbody><body name="b"><joint name="hinge"/><geom size=".1"/></body></worldbody>
      <actuator><motor name="drive" joint="hinge"/></actuator>
      <sensor><jointpos name="angle" joint="hinge"/></sensor>
    </mujoco>"""
    alone, scene, problems = _scene_and_problems(parent)
    assert float(alone.actuator("drive").gear[0]) == 7.0
    assert np.array_equal(scene.actuator("drive").gear, alone.actuator("drive").gear)
    assert problems == []
