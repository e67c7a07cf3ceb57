"""Which attached parts bring keyframe entries, refereed by MuJoCo compiling each part alone.

A part brings entries to the scene's keys when it has anything a key sets: a
joint, an actuator, a mocap body, a ``<key>`` or a ``<size nkey>``
(mjcf_model/transforms/composition/keyframes.py). When one such part is
attached between two others in one :func:`mjcf_model.attach_all`, the later
part's entries must land after its own, so every key is checked, object by
object, against the parts compiled alone (tests/support/composition_oracle.py). A part
with nothing a key sets leaves the parent's keys alone, even a parent whose
``<replicate>`` hides where entries would go.
"""

from __future__ import annotations

import mujoco
import pytest

from mjcf_model import GenericElement, Mujoco, Worldbody, attach, attach_all, compiled
from serializers import loads
from tests.conftest import MUJOCO_VERSION
from tests.support.composition_oracle import PlacedPart, composition_problems

#: A part with every kind of entry: a mocap body, a joint, an actuator and a key setting all.
FULL = """<mujoco>
  <worldbody>
    <body name="goal" mocap="true" pos="0.5 0 0">
      <geom size=".05" contype="0" conaffinity="0"/>
    </body>
    <body name="link"><joint name="hinge" ref="10"/><geom size=".1"/></body>
  </worldbody>
  <actuator><motor name="drive" joint="hinge"/></actuator>
  <keyframe>
    <key name="home" qpos="0.7" qvel="0.3" ctrl="0.4" mpos="0.5 1 0" mquat="0 0 0 1"/>
  </keyframe>
</mujoco>
"""
#: Parts that each have one kind of entry only, and no key of their own (but ``ONLY_KEY``).
ONLY_ACTUATOR = """<mujoco>
  <worldbody><site name="spot"/></worldbody>
  <actuator><motor name="push" site="spot"/></actuator>
</mujoco>
"""
ONLY_MOCAP = """<mujoco>
  <worldbody>
    <body name="target" mocap="true" pos="0 1 0" quat="0 1 0 0">
      <geom size=".05" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>
"""
ONLY_JOINT = """<mujoco>
  <worldbody><body name="arm"><joint name="swing" type="slide" ref="0.1"/><geom size=".1"/></body>
  </worldbody>
</mujoco>
"""
ONLY_NKEY = '<mujoco><size nkey="1"/></mujoco>'
ONLY_KEY = '<mujoco><keyframe><key name="later" time="1.5"/></keyframe></mujoco>'
#: A parent with a key and a ``<replicate>`` (its copies' place in the keys is not in the tree).
REPLICATED = """<mujoco>
  <worldbody>
    <body name="shelf"><joint name="lift" type="slide"/><geom size=".1"/></body>
    <replicate count="2" offset="0.3 0 0"><geom size=".05" pos="0 1 0"/></replicate>
  </worldbody>
  <keyframe><key name="up" qpos="0.2"/></keyframe>
</mujoco>
"""
#: A part with nothing a key sets: a plain body (``mocap="false"``), a sensor, a ``<size>``.
STATELESS = """<mujoco>
  <size memory="1M"/>
  <worldbody><body name="box" mocap="false" pos="0 0 1"><geom size=".1"/></body></worldbody>
  <sensor><framepos name="where" objtype="body" objname="box"/></sensor>
</mujoco>
"""


def _alone(text: str) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(text)


def _generic_mocap() -> Mujoco:
    """``ONLY_MOCAP`` with its body as a generic element (``mocap`` held as the text "true")."""
    geom = GenericElement(
        tag="geom", attributes={"size": ".05", "contype": "0", "conaffinity": "0"}
    )
    attributes = {"name": "target", "mocap": "true", "pos": "0 1 0", "quat": "0 1 0 0"}
    body = GenericElement(tag="body", attributes=attributes, children=[geom])
    return Mujoco(children=[Worldbody(children=[body])])


@pytest.mark.parametrize("generic", [False, True], ids=["typed", "generic_mocap_body"])
def test_every_part_with_something_a_key_sets_brings_its_entries(generic: bool) -> None:
    """An actuator, a mocap body, a joint, a key or ``<size nkey>`` alone each bring entries."""
    middle = [
        (ONLY_ACTUATOR, "u_"),
        (ONLY_MOCAP, "m_"),
        (ONLY_JOINT, "j_"),
        (ONLY_NKEY, "n_"),
        (ONLY_KEY, "k_"),
    ]
    parts = [(FULL, "a_"), *middle, (FULL, "b_")]
    models = [(loads(text), prefix) for text, prefix in parts]
    if generic:
        models[2] = (_generic_mocap(), "m_")
    scene = compiled(attach_all(loads(FULL), models))
    placed = [PlacedPart(_alone(FULL)), *(PlacedPart(_alone(t), p) for t, p in parts)]
    assert scene.nkey == sum(part.alone.nkey for part in placed) == 5
    assert composition_problems(placed, scene) == []


def test_a_part_without_state_leaves_the_parents_keys_as_they_are() -> None:
    """Nothing to place (no joint, mocap, actuator or key): attaching inside a body just works.

    MuJoCo 3.9 copies the key at each ``<replicate>`` copy (``up0``, ``up1``, then ``up``).
    """
    scene = compiled(attach(loads(REPLICATED), loads(STATELESS), at="shelf", prefix="c_"))
    alone = _alone(REPLICATED)
    assert scene.nkey == alone.nkey == (1 if MUJOCO_VERSION >= (4, 0) else 3)
    assert [scene.key(i).name for i in range(scene.nkey)] == [
        alone.key(i).name for i in range(alone.nkey)
    ]
    lift, own = scene.joint("lift").qposadr[0], alone.joint("lift").qposadr[0]
    assert scene.key("up").qpos[lift] == alone.key("up").qpos[own]
    assert scene.body("c_box").mocapid[0] == -1
