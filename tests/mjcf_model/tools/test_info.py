"""``model_summary`` and ``effective_attributes``, refereed by what MuJoCo compiles."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
from hypothesis import given, settings

from mjcf_model import MjcfLookupError, Mujoco
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.strategies import models
from mjcf_model.tools.info import effective_attributes, model_summary
from mjcf_model.tree.traversal import keyed_walk, walk
from tests.conftest import compiling_corpus, corpus_id

#: MuJoCo's built-in values of the attributes the property test reads.
_BUILT_IN = {"rgba": (0.5, 0.5, 0.5, 1.0), "damping": (0.0,), "armature": 0.0}


def _effective(model: Mujoco, kind: str, name: str, attribute: str) -> object:
    found = {item.name: item.value for item in effective_attributes(model, kind, name)}
    return found.get(attribute, _BUILT_IN[attribute])


@settings(deadline=None)
@given(models())
def test_effective_values_are_what_mujoco_compiles(model: Mujoco) -> None:
    """Through nested classes and childclass, geom rgba and joint damping are MuJoCo's.

    Each named geom's rgba and each joint's damping and armature are what the
    compiled model holds.
    """
    compiled = mujoco.MjModel.from_xml_string(dumps(model))
    for element, key, ancestors in keyed_walk(model):
        name = getattr(element, "name", None)
        if any(a.tag == "replicate" for a in ancestors):
            continue  # MuJoCo names the copies (rgeom00, rgeom01...), each with these classes
        if key == "body/geom" and name:
            index = compiled.geom(name).id
            rgba = np.array(_effective(model, "geom", name, "rgba"), dtype=np.float32)
            assert np.array_equal(compiled.geom_rgba[index], rgba), name
        if key == "body/joint" and name:
            first_dof = compiled.jnt_dofadr[compiled.joint(name).id]
            damping = _effective(model, "joint", name, "damping")
            assert isinstance(damping, tuple)
            assert compiled.dof_damping[first_dof] == damping[0], name
            assert compiled.dof_armature[first_dof] == _effective(
                model, "joint", name, "armature"
            ), name


_SHARED = """<mujoco>
  <default>
    <general ctrlrange="-1 1" ctrllimited="true"/>
    <motor gear="2"/>
    <tendon width="0.02"/>
    <default class="c"><position kp="7" ctrlrange="-2 2"/></default>
  </default>
  <actuator>
    <position name="p" joint="j"/>
    <motor name="m" class="c" joint="j"/>
  </actuator>
  <tendon><spatial name="t"><site site="a"/><site site="b"/></spatial></tendon>
  <worldbody>
    <body><joint name="j"/><geom size="1"/><site name="a"/><site name="b" pos="0 0 1"/></body>
  </worldbody>
</mujoco>"""


def test_actuators_share_one_default_and_tendons_read_theirs() -> None:
    """Actuators share one default per class and tendons read <tendon>, as MuJoCo compiles.

    A position reads the motor's gear, a motor does not read the position's kp,
    and a spatial tendon reads <tendon>.
    """
    model, compiled = loads(_SHARED), mujoco.MjModel.from_xml_string(_SHARED)
    position = {a.name: (a.value, a.source) for a in effective_attributes(model, "actuator", "p")}
    motor = {a.name: (a.value, a.source) for a in effective_attributes(model, "motor", "m")}
    assert position["gear"] == ((2.0,), "main") and compiled.actuator_gear[0, 0] == 2
    assert position["ctrlrange"][0] == tuple(compiled.actuator_ctrlrange[0])
    assert motor["ctrlrange"] == ((-2.0, 2.0), "c")
    assert tuple(compiled.actuator_ctrlrange[1]) == (-2.0, 2.0)
    assert "kp" not in motor and compiled.actuator_gainprm[1, 0] == 1.0
    tendon = {a.name: a.value for a in effective_attributes(model, "tendon", "t")}
    assert tendon["width"] == pytest.approx(compiled.tendon_width[0])


def test_unknown_element_is_a_lookup_error() -> None:
    """Asking for an element that is not there says which."""
    with pytest.raises(MjcfLookupError, match="no geom named 'x'"):
        effective_attributes(loads(_SHARED), "geom", "x")


#: Elements MuJoCo makes, moves or reads from elsewhere: files holding them are not counted.
_MULTIPLIED = {"replicate", "attach", "include", "flexcomp", "composite", "frame"}


def _countable() -> list[Path]:
    """The corpus files whose written elements are MuJoCo's elements, one for one."""
    return [
        path
        for path in compiling_corpus()
        if not {element.tag for _, element in walk(load(path))} & _MULTIPLIED
    ]


@pytest.mark.parametrize("path", _countable(), ids=corpus_id)
def test_summary_counts_are_mujoco_counts(path: Path) -> None:
    """The counts of bodies, geoms, joints and sites are the compiled model's."""
    compiled = mujoco.MjModel.from_xml_path(str(path))
    counts = model_summary(load(path)).counts
    assert counts.get("body", 0) == compiled.nbody - 1
    assert counts.get("geom", 0) == compiled.ngeom
    assert counts.get("joint", 0) + counts.get("freejoint", 0) == compiled.njnt
    assert counts.get("site", 0) == compiled.nsite


def test_summary_names_and_classes() -> None:
    """Names come in document order per namespace; classes with their parents and settings."""
    summary = model_summary(loads(_SHARED))
    assert summary.names["actuator"] == ("p", "m")
    assert summary.names["site"] == ("a", "b")
    assert dict(summary.classes) == {"main": None, "c": "main"}
    assert summary.class_settings["main"] == ("general", "motor", "tendon")
    assert summary.compiler["angle"] == "degree"


def test_equalities_read_the_equality_default() -> None:
    """<default><equality solref> reaches every kind of equality, as MuJoCo compiles it."""
    xml = """<mujoco><default><equality solref="0.05 1"/></default>
      <worldbody><body name="a"><freejoint/><geom size="1"/></body>
        <body name="b"><freejoint/><geom size="1"/></body></worldbody>
      <equality><weld name="w" body1="a" body2="b"/></equality></mujoco>"""
    given = {item.name: item for item in effective_attributes(loads(xml), "equality", "w")}
    compiled = mujoco.MjModel.from_xml_string(xml)
    assert (
        given["solref"].value == tuple(compiled.eq_solref[0]) and given["solref"].source == "main"
    )
