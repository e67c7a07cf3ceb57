"""What scaling leaves unchanged is the input's own node (shared, not copied)."""

from __future__ import annotations

from mjcf_model import Body, Joint
from mjcf_model.transforms.scaling.transform import scaled


def test_a_hinge_at_the_origin_is_shared() -> None:
    """A hinge's zero position scales to itself: the joint node is the input's."""
    joint = Joint(name="j", type="hinge", pos=[0.0, 0.0, 0.0], range=[-1.0, 1.0])
    body = Body(name="b", pos=[0.0, 0.0, 1.0], children=[joint])
    new = scaled(body, 2.0)
    assert new.pos == (0.0, 0.0, 2.0)
    assert new.children[0] is joint
