"""The classes top-level default settings become: ``child_main``, ``parent_main``, numbered.

A child attached without a prefix has its top-level settings made a class
``child_main``; a second one ``child_main_2``: names nobody declares yet. The
parent's top-level settings become ``parent_main``, or ``parent_main_2``
when it already has a class of that name, and a child declaring the class
name given to the parent's settings is a name clash
(the attach docstring in mjcf_model/transforms/composition/attaching.py). MuJoCo
compiling each part alone says what each geom must get from its defaults.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model import MjcfValueError, Mujoco, attach, attach_all, compiled
from mjcf_model.nodes.default import Default
from mjcf_model.tree.queries import find_all
from serializers import loads

RED = """<mujoco>
  <default><geom rgba="1 0 0 1" size=".2"/></default>
  <worldbody><body name="red"><geom name="red_geom"/></body></worldbody>
</mujoco>
"""
BLUE = """<mujoco>
  <default><geom rgba="0 0 1 1" size=".3"/></default>
  <worldbody><body name="blue"><geom name="blue_geom"/></body></worldbody>
</mujoco>
"""
#: A parent with top-level settings that already declares a class named ``parent_main``.
PARENT = """<mujoco>
  <default>
    <geom rgba="1 1 0 1" size=".1"/>
    <default class="parent_main"><geom rgba="0 1 1 1" size=".5"/></default>
  </default>
  <worldbody>
    <body name="base"><geom name="base_geom"/><geom name="classed_geom" class="parent_main"/></body>
  </worldbody>
</mujoco>
"""
#: A parent with top-level settings only, and a child declaring the class they become.
PLAIN_PARENT = """<mujoco>
  <default><geom rgba="1 1 0 1" size=".1"/></default>
  <worldbody><body name="base"><geom name="base_geom"/></body></worldbody>
</mujoco>
"""
CLAIMING = """<mujoco>
  <default><default class="parent_main"><geom size=".3"/></default></default>
  <worldbody><body name="arm"><geom name="arm_geom" class="parent_main"/></body></worldbody>
</mujoco>
"""


def _classes(model: Mujoco) -> list[str]:
    return [d.dclass for d in find_all(model, "default") if isinstance(d, Default) and d.dclass]


def _same_geoms(scene: mujoco.MjModel, texts: list[str], names: list[str]) -> None:
    """Each named geom compiles in the scene as in its own model."""
    for text, name in zip(texts, names, strict=True):
        alone = mujoco.MjModel.from_xml_string(text)
        np.testing.assert_allclose(scene.geom(name).rgba, alone.geom(name).rgba, err_msg=name)
        np.testing.assert_allclose(scene.geom(name).size, alone.geom(name).size, err_msg=name)


def test_an_unprefixed_childs_settings_become_child_main() -> None:
    """Without a prefix the child's top-level settings are the class ``child_main``."""
    scene = attach(Mujoco(), loads(RED))
    assert "child_main" in _classes(scene)
    _same_geoms(compiled(scene), [RED], ["red_geom"])


def test_a_second_unprefixed_child_gets_child_main_2() -> None:
    """Two unprefixed children: ``child_main`` and ``child_main_2``, each its own settings."""
    scene = attach_all(Mujoco(), [(loads(RED), ""), (loads(BLUE), "")])
    assert _classes(scene) == ["child_main", "child_main_2"]
    _same_geoms(compiled(scene), [RED, BLUE], ["red_geom", "blue_geom"])


def test_the_parents_settings_avoid_its_own_class_names() -> None:
    """A parent declaring ``parent_main`` has its top-level settings made ``parent_main_2``."""
    scene = attach(loads(PARENT), loads(RED), prefix="r_")
    assert set(_classes(scene)) >= {"parent_main", "parent_main_2", "r_main"}
    compiled_scene = compiled(scene)
    _same_geoms(compiled_scene, [PARENT, PARENT], ["base_geom", "classed_geom"])
    red = mujoco.MjModel.from_xml_string(RED).geom("red_geom")
    np.testing.assert_allclose(compiled_scene.geom("r_red_geom").rgba, red.rgba)
    np.testing.assert_allclose(compiled_scene.geom("r_red_geom").size, red.size)


def test_a_child_declaring_the_parents_settings_class_clashes() -> None:
    """A child declaring the class the parent's settings became is a clash: attach with a prefix."""
    with pytest.raises(MjcfValueError, match=r"already has \(class: parent_main\).*with a prefix"):
        attach(loads(PLAIN_PARENT), loads(CLAIMING))
