"""attach() under a body's ``childclass``: the innermost placing frame resets the class.

A ``childclass`` of the body holding the attach point would reach the child's
elements; ``MjSpec`` keeps them in the child's own classes. So the frame that
already places the child (the site's pose, or the placement asked for) sets
``childclass="main"``: no extra frame is added for it.
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np
import pytest

from mjcf_model import find_all, get_attribute
from mjcf_model.transforms.composition.attaching import attach
from serializers import dumps, loads

#: Class ``red`` colours geoms; the body ``b`` gives it to everything it holds.
PARENT = """<mujoco>
  <default><default class="red"><geom rgba="1 0 0 1"/></default></default>
  <worldbody><body name="b" pos="0 1 0" childclass="red">
    <geom size="0.2"/><site name="s" pos="0 0 0.1"/>
  </body></worldbody>
</mujoco>"""
CHILD = '<mujoco><worldbody><body name="palm"><geom size="0.1"/></body></worldbody></mujoco>'
CASES: dict[str, dict[str, Any]] = {
    "at the site": {"at": "s"},
    "at the body, placed": {"at": "b", "pos": (0, 0, 0.1)},
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_placing_frame_itself_resets_the_body_childclass(case: str) -> None:
    """One frame places the child and sets childclass main; the child keeps its own colours."""
    scene = attach(loads(PARENT), loads(CHILD), prefix="g_", **CASES[case])
    frames = find_all(scene, "frame")
    assert [(get_attribute(f, "pos"), get_attribute(f, "childclass")) for f in frames] == [
        ((0, 0, 0.1), "main")
    ]
    compiled = mujoco.MjModel.from_xml_string(dumps(scene))
    data = mujoco.MjData(compiled)
    mujoco.mj_kinematics(compiled, data)
    assert np.allclose(data.body("g_palm").xpos, [0, 1, 0.1])  # b + the site's pos
    palm_geom = compiled.body_geomadr[compiled.body("g_palm").id]
    alone = mujoco.MjModel.from_xml_string(CHILD)
    assert np.allclose(compiled.geom_rgba[palm_geom], alone.geom_rgba[0])
