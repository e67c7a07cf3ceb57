"""The child's own ``<lengthrange>`` does not block attaching under other inertia settings.

``<lengthrange>`` is model-wide: the parent's holds, and attaching drops the
child's. When an inertia setting differs, the child is compiled once more to read
its inertias; that compile once kept the child's ``<lengthrange>``, so one MuJoCo
cannot satisfy refused an attach the child's own compile allows.
"""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Mujoco, attach, compiled
from serializers import loads

BODY = (
    '<worldbody><body name="b"><joint name="j" type="slide"/><geom size="0.01" mass="0.001"/>'
    '</body></worldbody><actuator><motor joint="j"/></actuator></mujoco>'
)
#: A length range MuJoCo cannot compute for the motor on an unlimited slide joint.
LENGTHRANGE = '<lengthrange mode="all" useexisting="false"/>'


def test_a_child_lengthrange_does_not_block_keeping_its_inertias() -> None:
    """The child's unsatisfiable lengthrange (dropped anyway) does not refuse the attach."""
    child = f'<mujoco><compiler boundmass="0.5">{LENGTHRANGE}</compiler>{BODY}'
    alone = mujoco.MjModel.from_xml_string(f'<mujoco><compiler boundmass="0.5"/>{BODY}')
    scene = compiled(attach(Mujoco(), loads(child), prefix="c_"))
    assert np.array_equal(scene.body_mass, alone.body_mass)
