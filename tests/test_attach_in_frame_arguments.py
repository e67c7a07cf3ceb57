"""attach_in_frame: the child's world goes inside the named frame, its names kept without a prefix.

The frame is looked up among the parent's frames only, so a body of the same
name (MuJoCo keeps bodies and frames in separate namespaces) does not make the
name ambiguous. MuJoCo compiling each part alone is the referee
(tests/support/composition_oracle.py): the child's objects hold their own values,
placed at the frame.
"""

from __future__ import annotations

import mujoco

from mjcf_model import compiled
from mjcf_model.transforms.composition.attaching import attach_in_frame
from serializers import loads
from tests.support.composition_oracle import PlacedPart, composition_problems

CHILD = """<mujoco>
  <worldbody><body name="cup" pos="0.1 0 0"><joint name="tilt"/><geom size=".1"/></body></worldbody>
</mujoco>
"""
PARENT = """<mujoco>
  <worldbody>
    <body name="here" pos="1 0 0"><geom size=".2"/></body>
    <frame name="here" pos="0 2 0"/>
  </worldbody>
</mujoco>
"""


def test_without_a_prefix_the_childs_names_are_kept() -> None:
    """With no ``prefix`` given, the child's bodies and joints keep their own names."""
    scene = compiled(attach_in_frame(loads(PARENT), loads(CHILD), frame="here"))
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string(PARENT)),
        PlacedPart(mujoco.MjModel.from_xml_string(CHILD), "", pos=(0.0, 2.0, 0.0)),
    ]
    assert composition_problems(parts, scene) == []
    assert scene.body("cup").name == "cup" and scene.joint("tilt").name == "tilt"


def test_the_frame_is_found_when_a_body_has_its_name() -> None:
    """The frame named ``frame`` is used even when a body has that name: the child goes there."""
    scene = compiled(attach_in_frame(loads(PARENT), loads(CHILD), frame="here", prefix="c_"))
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string(PARENT)),
        PlacedPart(mujoco.MjModel.from_xml_string(CHILD), "c_", pos=(0.0, 2.0, 0.0)),
    ]
    assert composition_problems(parts, scene) == []
    assert scene.body_parentid[scene.body("c_cup").id] == 0
