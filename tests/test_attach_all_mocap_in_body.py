"""``attach_all`` checks every part for free joints or mocap bodies inside a body.

``attach_all`` is documented as the same as calling :func:`mjcf_model.attach`
for each child; with keyframes, ``attach`` refuses a part with mocap bodies
inside a body (MuJoCo allows those only at the top level). ``attach_all`` once
worked out the attach pose for its first part only, so a later part with a mocap
body was placed inside the body and MuJoCo rejected the result.
"""

from __future__ import annotations

import pytest

from mjcf_model import MjcfValueError, attach, attach_all
from serializers import loads

PARENT = (
    '<mujoco><worldbody><body name="mount"><joint/><geom size=".1"/></body></worldbody>'
    '<keyframe><key qpos="0.3"/></keyframe></mujoco>'
)
ARM = '<mujoco><worldbody><body><joint/><geom size=".1"/></body></worldbody></mujoco>'
TARGET = (
    '<mujoco><worldbody><body name="t" mocap="true"><geom size=".1" contype="0" '
    'conaffinity="0"/></body></worldbody></mujoco>'
)


def test_attach_refuses_a_mocap_part_after_another_part_at_a_body() -> None:
    """Attached one by one, the second (mocap) part at ``mount`` is refused, naming the body."""
    scene = attach(loads(PARENT), loads(ARM), at="mount", prefix="a_")
    with pytest.raises(MjcfValueError, match=r"inside the <body> 'mount'"):
        attach(scene, loads(TARGET), at="mount", prefix="t_")


def test_attach_all_refuses_a_mocap_part_after_another_part_at_a_body() -> None:
    """In one ``attach_all`` the same mocap part is refused too (fails: it goes in the body)."""
    with pytest.raises(MjcfValueError, match=r"inside the <body> 'mount'"):
        attach_all(loads(PARENT), [(loads(ARM), "a_"), (loads(TARGET), "t_")], at="mount")
