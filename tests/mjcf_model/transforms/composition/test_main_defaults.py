"""Tests of ``mjcf_model.transforms.composition.main_defaults``."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from mjcf_model import (
    MjcfValueError,
    Mujoco,
    Node,
    attach,
    attach_all,
    compiled,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.nodes.default import Default
from mjcf_model.serializers import loads
from mjcf_model.tree.queries import find_all
from tests.support.composition_oracle import PlacedPart, composition_problems

# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


# -- memory ----------------------------------------------------------------------------


def test_attach_classes_replicates_nested_deeper_than_the_recursion_limit() -> None:
    """A parent whose world nests replicates 3,000 deep keeps its main defaults when attached to."""
    depth = 3_000
    opened = '<replicate count="1" offset="0 0 0">' * depth
    parent = loads(
        f'<mujoco><default><geom rgba="1 0 0 1"/></default><worldbody>{opened}'
        f'<geom size="0.1"/>{"</replicate>" * depth}</worldbody></mujoco>'
    )
    child = loads(
        '<mujoco><default><geom rgba="0 1 0 1"/></default>'
        '<worldbody><body name="b"><geom size="0.1"/></body></worldbody></mujoco>'
    )
    scene = attach(parent, child, prefix="c_", at=None)
    inner: Node = scene.worldbody.children[0]  # the replicates; the attached body follows
    for _ in range(depth - 1):
        (inner,) = inner.children  # type: ignore[attr-defined]
    (geom,) = inner.children  # type: ignore[attr-defined]
    assert geom.dclass == "parent_main"  # the parent's main class, moved where it applies


# -- The parent's top-level defaults keep reaching its own elements once a child is attached. --
#
# :func:`mjcf_model.attach` moves the parent's top-level ``<default>`` settings into
# a class of their own (``main_defaults.with_main_as_class``). MuJoCo is the
# referee: the scene's rows for the parent's objects must equal the parent
# compiled alone (:func:`tests.support.composition_oracle.composition_problems`), and the
# values checked by name are the ones MuJoCo gives the parent alone.


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


# -- The classes top-level default settings become: ``child_main``, ``parent_main``, numbered. -
#
# A child attached without a prefix has its top-level settings made a class
# ``child_main``; a second one ``child_main_2``: names nobody declares yet. The
# parent's top-level settings become ``parent_main``, or ``parent_main_2``
# when it already has a class of that name, and a child declaring the class
# name given to the parent's settings is a name clash
# (the attach docstring in mjcf_model/transforms/composition/attaching.py). MuJoCo
# compiling each part alone says what each geom must get from its defaults.


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


# -- Expanding ``<attach>``: the expanded model compiles to MuJoCo's own ``<attach>`` result. --
#
# The fixtures in ``tests/fixtures/attachments`` each hold a scene and the models it
# attaches, in folders of their own with their own ``<compiler>``. For each, MuJoCo
# compiles the original (its ``<attach>``) and the expansion; every array must be
# equal (the recorded file paths aside). The expansion is then dumped elsewhere,
# prefixed and scaled, and MuJoCo referees those too.


def test_parent_defaults_do_not_reach_the_child(tmp_path: Path) -> None:
    """``attach`` keeps the parent's top-level defaults off the child, as ``MjSpec`` does."""
    parent_text = (
        '<mujoco><default><geom rgba="1 0 0 1"/><joint damping="3"/></default>'
        '<worldbody><body name="a"><geom size="1"/><site name="s"/></body></worldbody></mujoco>'
    )
    child_text = (
        '<mujoco><worldbody><body name="b"><joint/><geom size="1"/></body></worldbody></mujoco>'
    )
    spec = mujoco.MjSpec.from_string(parent_text)
    spec.attach(mujoco.MjSpec.from_string(child_text), site=spec.site("s"), prefix="c_")
    ours = compiled(attach(loads(parent_text), loads(child_text), at="s", prefix="c_"))
    assert model_differences(spec.compile(), ours) == []
