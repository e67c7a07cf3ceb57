"""Euler angles attached under another ``eulerseq`` or angle unit keep their exact quaternions.

Each test compiles the child alone and the parent with the child attached, and
compares the quaternions MuJoCo made of every body, inertial, geom, site and
camera (through a frame too): no digit is lost, even at gimbal lock.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import compiled, find, get_attribute
from mjcf_model.transforms.composition.attaching import attach
from serializers import loads

#: The compiled quaternions compared, one per kind of element that takes ``euler``.
QUATS = ("body_quat", "body_iquat", "geom_quat", "site_quat", "cam_quat")
#: Sequences a child or a parent may read Euler angles in.
SEQUENCES = ("xyz", "zyx", "XYZ", "xYz", "zxz", "YZY")
#: Angles at and next to gimbal lock, where converting Euler angles loses digits.
LOCKED = (math.pi / 2, -math.pi / 2, 1.5708, 3.14159, math.pi, 0.0)


def _child(euler: str, angle: str, eulerseq: str) -> str:
    """A child whose body, inertial, geom, site, camera and framed site all say ``euler``."""
    return (
        f'<mujoco><compiler angle="{angle}" eulerseq="{eulerseq}"/><worldbody>'
        f'<body name="b" euler="{euler}">'
        f'<inertial pos="0 0 0" mass="1" diaginertia="1 2 3" euler="{euler}"/>'
        f'<geom size="0.1" euler="{euler}"/><site euler="{euler}"/><camera euler="{euler}"/>'
        f'<frame euler="{euler}"><site/></frame></body></worldbody></mujoco>'
    )


def _largest_difference(child_text: str, parent_text: str) -> float:
    """The largest difference in a compared quaternion between the child alone and attached."""
    child = loads(child_text)
    alone, attached = compiled(child), compiled(attach(loads(parent_text), child))
    return max(float(np.abs(getattr(alone, q) - getattr(attached, q)).max()) for q in QUATS)


def test_gimbal_lock_keeps_every_digit() -> None:
    """A zyx site at gimbal lock attached to an xyz parent compiles to its own quaternion."""
    child = _child("0 1.5708 3.14159", "radian", "zyx")
    assert _largest_difference(child, "<mujoco/>") <= 1e-15


def test_the_turn_is_written_as_quat() -> None:
    """Where no class orients an element, its turn in another sequence becomes a quat."""
    child = loads(_child("0 90 180", "degree", "zyx"))
    site = find(attach(loads("<mujoco/>"), child), "site")
    assert site is not None and get_attribute(site, "euler") is None
    assert get_attribute(site, "quat") is not None


def test_a_class_orientation_keeps_the_euler_notation() -> None:
    """A site its class orients keeps euler (MuJoCo 3.9 would prefer the class's to a quat)."""
    child = loads(
        '<mujoco><compiler eulerseq="zyx"/><default><site euler="0 0 10"/></default>'
        '<worldbody><site name="s" euler="0 90 180"/></worldbody></mujoco>'
    )
    attached = attach(loads("<mujoco/>"), child)
    site = find(attached, "site", name="s")
    assert site is not None and get_attribute(site, "quat") is None
    assert get_attribute(site, "euler") is not None
    assert np.allclose(compiled(attached).site_quat, compiled(child).site_quat, atol=1e-9)


angles = st.one_of(
    st.floats(-2 * math.pi, 2 * math.pi, allow_nan=False, allow_subnormal=False),
    st.sampled_from(LOCKED).flatmap(lambda a: st.sampled_from([a, math.nextafter(a, 4)])),
).filter(lambda a: a == 0 or abs(a) >= sys.float_info.min)  # MuJoCo 3.9 refuses subnormals


@given(
    euler=st.tuples(angles, angles, angles),
    mine=st.tuples(st.sampled_from(("radian", "degree")), st.sampled_from(SEQUENCES)),
    theirs=st.tuples(st.sampled_from(("radian", "degree")), st.sampled_from(SEQUENCES)),
)
def test_attached_euler_angles_compile_to_the_same_quaternions(
    euler: tuple[float, float, float], mine: tuple[str, str], theirs: tuple[str, str]
) -> None:
    """Any angles, in either unit and any sequence, compile attached as the child alone."""
    scale = 180 / math.pi if mine[0] == "degree" else 1.0
    text = " ".join(repr(a * scale) for a in euler)
    parent = f'<mujoco><compiler angle="{theirs[0]}" eulerseq="{theirs[1]}"/></mujoco>'
    assert _largest_difference(_child(text, *mine), parent) <= 1e-15
