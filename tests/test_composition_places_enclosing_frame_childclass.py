"""attach() at a site or frame inside a frame with a ``childclass``: that class stays behind.

MjSpec (and so :func:`mjcf_model.attach`) puts the child at the end of the body
holding the target, in frames that copy the poses on the way; a ``childclass``
of a frame around the target reaches only that frame's own children, so the
frames wrapping the child copy poses only and set no class.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model import find_all, get_attribute
from mjcf_model.transforms.composition.attaching import attach
from serializers import dumps, loads

#: Class ``red`` colours geoms; the frame ``outer`` gives it to what it holds.
PARENT = """<mujoco>
  <default><default class="red"><geom rgba="1 0 0 1"/></default></default>
  <worldbody><body name="b" pos="0 1 0">
    <frame name="outer" childclass="red" pos="0 0 1">{target}</frame>
  </body></worldbody>
</mujoco>"""
TARGETS = {
    "site": '<site name="here" pos="0 0 0.1"/>',
    "frame": '<frame name="here" pos="0 0 0.1"/>',
}
CHILD = '<mujoco><worldbody><body name="palm"><geom size="0.1"/></body></worldbody></mujoco>'


@pytest.mark.parametrize("kind", sorted(TARGETS))
def test_a_frame_childclass_around_the_target_does_not_reach_the_child(kind: str) -> None:
    """The wrapping frames set no childclass; the child sits at the target, in its own colours."""
    text = PARENT.format(target=TARGETS[kind])
    scene = attach(loads(text), loads(CHILD), at="here", prefix="g_")
    frames = [f for f in find_all(scene, "frame") if get_attribute(f, "name") is None]
    assert [get_attribute(f, "childclass") for f in frames] == [None, None]
    compiled = mujoco.MjModel.from_xml_string(dumps(scene))
    data = mujoco.MjData(compiled)
    mujoco.mj_kinematics(compiled, data)
    assert np.allclose(data.body("g_palm").xpos, [0, 1, 1.1])  # b + outer + here
    default_rgba = mujoco.MjModel.from_xml_string(CHILD).geom_rgba[0]
    assert np.allclose(compiled.geom_rgba[0], default_rgba)
