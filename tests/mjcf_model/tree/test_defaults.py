"""Tests of ``mjcf_model.tree.defaults``: which class an element takes unwritten values from.

MuJoCo is the referee: what :class:`DefaultClasses` resolves for an element is what
MuJoCo compiles for it.
"""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Geom, Joint, Motor
from mjcf_model.serializers import loads
from mjcf_model.tree.defaults import MAIN, DefaultClasses
from mjcf_model.tree.traversal import keyed_walk

#: Nested classes reached by ``class``, by an inherited ``childclass`` and by main.
MODEL = """<mujoco>
  <default>
    <geom type="box" size="0.1 0.2 0.3" rgba="1 0 0 1"/>
    <motor gear="3"/>
    <default class="round">
      <geom type="sphere" size="0.05"/>
      <default class="blue"><geom rgba="0 0 1 1"/><joint type="slide" axis="0 1 0"/></default>
    </default>
  </default>
  <worldbody>
    <geom name="plain"/>
    <body name="arm" childclass="blue">
      <joint name="rail"/>
      <geom name="inherits"/>
      <geom name="own" class="round" rgba="0 1 0 1"/>
      <body name="hand" childclass="round">
        <joint name="hinge" type="hinge"/><geom name="deep"/>
      </body>
    </body>
  </worldbody>
  <actuator><motor name="push" joint="rail"/></actuator>
</mujoco>
"""
#: MuJoCo's geom type numbers.
GEOM_TYPES = {"box": int(mujoco.mjtGeom.mjGEOM_BOX), "sphere": int(mujoco.mjtGeom.mjGEOM_SPHERE)}
#: MuJoCo's joint type numbers.
JOINT_TYPES = {"slide": int(mujoco.mjtJoint.mjJNT_SLIDE), "hinge": int(mujoco.mjtJoint.mjJNT_HINGE)}


def test_resolved_values_are_what_mujoco_compiles_for_each_element() -> None:
    """Type, colour and axis come from the element, its class, a ``childclass`` or main."""
    model = loads(MODEL)
    classes = DefaultClasses.of(model)
    compiled = mujoco.MjModel.from_xml_string(MODEL)
    seen = 0
    for element, _, ancestors in keyed_walk(model):
        if any(a.tag == "default" for a in ancestors):
            continue
        if isinstance(element, Geom):
            kind, rgba = classes.resolve_many(element, ancestors, ("type", "rgba"))
            assert GEOM_TYPES[kind] == compiled.geom(element.name).type[0], element.name
            assert np.array_equal(np.float32(rgba), compiled.geom(element.name).rgba)
            seen += 1
        elif isinstance(element, Joint):
            kind = classes.resolve(element, ancestors, "type")
            assert JOINT_TYPES[kind] == compiled.joint(element.name).type[0], element.name
            axis = classes.resolve(element, ancestors, "axis") or (0.0, 0.0, 1.0)
            assert np.array_equal(axis, compiled.joint(element.name).axis), element.name
            seen += 1
        elif isinstance(element, Motor):
            given = classes.given_to(element, ancestors)
            assert given["gear"] == ((3.0,), MAIN)
            assert compiled.actuator("push").gear[0] == 3.0
            seen += 1
    assert seen == 7


def test_classes_nest_as_written_and_lookups_name_the_writing_class() -> None:
    """A class's chain runs to main; a value found says which class wrote it."""
    classes = DefaultClasses.of(loads(MODEL))
    assert classes.chain("blue") == ("blue", "round", MAIN)
    assert classes.chain("unknown") == ("unknown",)
    assert classes.lookup("blue", "geom", "rgba") == ((0.0, 0.0, 1.0, 1.0), "blue")
    assert classes.lookup("blue", "geom", "type") == ("sphere", "round")
    assert classes.lookup("blue", "geom", "size") == ((0.05,), "round")
    assert classes.lookup(MAIN, "geom", "size") == ((0.1, 0.2, 0.3), MAIN)
    assert classes.lookup("round", "site", "size") is None
    assert classes.sets("geom") and classes.sets("joint") and not classes.sets("site")
    assert DefaultClasses.empty().chain(MAIN) == (MAIN,)
