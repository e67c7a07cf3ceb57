"""A slide range a class gives is scaled along the class's axis, and rewritten where that is wrong.

Per-axis factors scale a slide's coordinate by the factor along its axis (see
``test_per_axis_factors_scale_axis_aligned_slides_exactly``). A class giving
slides an axis and a range has that range scaled along its axis; a joint of the
class keeps inheriting it when its own axis and type agree, and writes its own
scaled value when they do not (another axis, or a hinge, whose range is an
angle). MuJoCo compiles every joint's range to the original's times the factor
along its axis.
"""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.traversal import keyed_walk
from serializers import dumps, loads

_MODEL = """<mujoco><default><default class="rail">
  <joint type="slide" axis="1 0 0" range="-.1 .2" margin=".01"/></default></default>
<worldbody><body childclass="rail"><joint name="x"/><joint name="z" axis="0 0 1"/>
  <joint name="y" axis="0 1 0"/><joint name="h" type="hinge"/><geom size=".05"/>
</body></worldbody></mujoco>"""


def test_class_slide_ranges_scale_along_each_joints_axis() -> None:
    """Factors 2, 3, 5: x's range doubles (inherited), z's and y's are rewritten, h's stays."""
    factors = np.array([2.0, 3.0, 5.0])
    model = scaled(loads(_MODEL), factors)
    original = mujoco.MjModel.from_xml_string(_MODEL)
    changed = mujoco.MjModel.from_xml_string(dumps(model))
    slide = original.jnt_type == mujoco.mjtJoint.mjJNT_SLIDE
    along = np.where(slide, np.abs(original.jnt_axis) @ factors, 1.0)  # a hinge's is an angle
    assert along.tolist() == [2.0, 5.0, 3.0, 1.0]
    np.testing.assert_allclose(changed.jnt_range, original.jnt_range * along[:, None], rtol=1e-12)
    np.testing.assert_allclose(changed.jnt_margin, original.jnt_margin * along, rtol=1e-12)
    joints = {e.name: e for e, key, _ in keyed_walk(model) if key == "body/joint"}
    assert (joints["x"].range, joints["x"].margin) == (None, None)  # inherits the class's
    assert joints["z"].range is not None
