"""A ``<replicate>``'s turn in another ``eulerseq``: checked only at the multiples it uses.

A replicate turns copy ``i`` by ``i`` times its ``euler``; copies 0 and 1 turn by
nothing and by the angles themselves, which the parent's sequence always says
(to rounding, larger next to gimbal lock). Only copies 2 and up can refuse the
conversion. MuJoCo, compiling the child alone, referees.
"""

from __future__ import annotations

import numpy as np

from mjcf_model import compiled
from mjcf_model.transforms.composition.conventions import in_conventions
from mjcf_model.tree.traversal import with_children
from serializers import loads


def test_two_copies_next_to_gimbal_lock_are_converted() -> None:
    """Two copies turned next to gimbal lock convert, compiling to the child's quaternions."""
    child = loads(
        '<mujoco><compiler angle="radian" eulerseq="XYZ"/><worldbody>'
        '<replicate count="2" euler="1 1.5707863267948965 1.2">'
        '<body name="b"><geom size=".1" pos="1 0 0"/></body></replicate></worldbody></mujoco>'
    )
    parent = loads('<mujoco><compiler angle="radian" eulerseq="zyx"/></mujoco>')
    converted = in_conventions(child, parent)
    found = compiled(with_children(converted, [*parent.children, *converted.children]))
    expected = compiled(child)
    assert expected.nbody == found.nbody == 3
    assert np.allclose(found.body_quat, expected.body_quat, rtol=0, atol=1e-11)
    assert np.allclose(found.body_pos, expected.body_pos, rtol=0, atol=1e-11)
