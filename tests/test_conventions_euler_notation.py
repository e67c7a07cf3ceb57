"""Which notation an orientation is written in when a child takes another model's conventions.

The module documentation of the conversion says: an angle in another unit stays
``euler`` (converted), a ``<default>``'s ``euler`` in another sequence stays
``euler`` (in the parent's sequence), and an orientation is left alone when
neither ``angle`` nor ``eulerseq`` differs. MuJoCo, compiling the child alone,
referees what the rewritten child means under the parent's ``<compiler>``.
"""

from __future__ import annotations

import numpy as np

from mjcf_model import Mujoco, compiled, find, get_attribute
from mjcf_model.bridge.compare import model_differences
from mjcf_model.transforms.composition.conventions import in_conventions
from mjcf_model.tree.traversal import with_children
from serializers import loads


def _under(converted: Mujoco, parent: Mujoco) -> Mujoco:
    """The rewritten child with the parent's ``<compiler>`` in front of it."""
    return with_children(converted, [*parent.children, *converted.children])


def _converted(child_text: str, parent_text: str) -> tuple[Mujoco, Mujoco, Mujoco]:
    child, parent = loads(child_text), loads(parent_text)
    return child, in_conventions(child, parent), parent


def test_an_orientation_is_left_as_written_when_only_autolimits_differs() -> None:
    """Degrees that do not round-trip through radians stay as written if angle does not differ."""
    child, converted, parent = _converted(
        '<mujoco><compiler autolimits="false"/><worldbody>'
        '<body name="b" euler="0 0 -357"><geom size="1"/></body></worldbody></mujoco>',
        "<mujoco/>",
    )
    body = find(converted, "body", name="b")
    assert body is not None
    assert get_attribute(body, "euler") == (0.0, 0.0, -357.0)
    assert get_attribute(body, "quat") is None
    assert model_differences(compiled(child), compiled(_under(converted, parent))) == []


def test_degrees_to_radians_stay_euler_in_the_same_sequence() -> None:
    """Under the same eulerseq, an angle unit change keeps euler: the radians MuJoCo makes."""
    child, converted, parent = _converted(
        '<mujoco><worldbody><body name="b" euler="10 20 30"><geom size="1"/></body>'
        "</worldbody></mujoco>",
        '<mujoco><compiler angle="radian"/></mujoco>',
    )
    body = find(converted, "body", name="b")
    assert body is not None and get_attribute(body, "quat") is None
    euler = get_attribute(body, "euler")
    assert euler == tuple(d / 180 * np.pi for d in (10.0, 20.0, 30.0))  # MuJoCo's d / 180 * pi
    assert model_differences(compiled(child), compiled(_under(converted, parent))) == []


def test_radians_to_degrees_stay_euler_in_the_same_sequence() -> None:
    """Radians that degrees read back exactly stay euler, in degrees, under the same eulerseq."""
    child, converted, parent = _converted(
        '<mujoco><compiler angle="radian"/><worldbody>'
        '<body name="b" euler="0.5 -0.25 1"><geom size="1"/></body></worldbody></mujoco>',
        "<mujoco/>",
    )
    body = find(converted, "body", name="b")
    assert body is not None and get_attribute(body, "quat") is None
    euler = get_attribute(body, "euler")
    assert isinstance(euler, tuple)
    assert np.allclose(euler, np.degrees([0.5, -0.25, 1.0]), rtol=1e-15, atol=0)
    assert model_differences(compiled(child), compiled(_under(converted, parent))) == []


def test_a_default_class_euler_stays_euler_in_the_parent_sequence() -> None:
    """A <default>'s euler in another eulerseq is rewritten as euler, never as quat."""
    child, converted, parent = _converted(
        '<mujoco><compiler eulerseq="zyx"/><default><geom euler="0 30 60"/></default>'
        '<worldbody><body name="b"><geom name="g" size="1"/></body></worldbody></mujoco>',
        '<mujoco><compiler eulerseq="xyz"/></mujoco>',
    )
    setting = find(converted, "default")
    assert setting is not None
    geom_default = setting.elements[0]
    assert get_attribute(geom_default, "quat") is None
    assert get_attribute(geom_default, "euler") is not None
    expected, found = compiled(child), compiled(_under(converted, parent))
    assert np.allclose(found.geom_quat, expected.geom_quat, rtol=0, atol=1e-12)
