"""Limit flags under another ``autolimits``: written only where unset or auto, and as MuJoCo reads.

The conversion writes each limit flag the child's ``autolimits`` decides
(``limited``, ``ctrllimited``...) on the elements that leave it unset or auto; a
flag a class sets stays the class's. An ``<intvelocity>`` sets ``actlimited``
itself, so nothing is written there, and MuJoCo 4.0 rejects its ``actrange``
under ``autolimits="false"``: refused, saying what to do. MuJoCo 3.9 limits every
``<intvelocity>`` (it needs an ``actrange``, under any ``autolimits``): there the
range is kept as it is. MuJoCo, compiling the child alone, referees.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from mjcf_model import Mujoco, compiled, find, get_attribute
from mjcf_model.bridge.compare import model_differences
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.transforms.composition.conventions import in_conventions
from mjcf_model.tree.traversal import with_children
from serializers import loads
from tests.conftest import MUJOCO_VERSION

BODY = (
    '<worldbody><body><joint name="j" limited="true" range="-1 1"/><geom size="1"/></body>'
    "</worldbody>"
)


def _under(converted: Mujoco, parent: Mujoco) -> Mujoco:
    """The rewritten child with the parent's ``<compiler>`` in front of it."""
    return with_children(converted, [*parent.children, *converted.children])


def test_an_inheritrange_of_zero_leaves_a_position_unlimited() -> None:
    """A position with inheritrange="0" and no ctrlrange stays unlimited under autolimits off."""
    child = loads(
        f'<mujoco>{BODY}<actuator><position name="p" joint="j" kp="1" inheritrange="0"/>'
        "</actuator></mujoco>"
    )
    parent = loads('<mujoco><compiler autolimits="false"/></mujoco>')
    converted = in_conventions(child, parent)
    assert model_differences(compiled(child), compiled(_under(converted, parent))) == []
    assert not compiled(child).actuator_ctrllimited[0]


def test_a_flag_a_class_sets_is_left_to_the_class() -> None:
    """A joint whose class sets limited gets no limited of its own; it compiles the same."""
    child = loads(
        '<mujoco><compiler autolimits="false"/><default><default class="free_range">'
        '<joint limited="false"/></default></default><worldbody><body>'
        '<joint name="j" class="free_range" range="0 1"/><geom size="1"/></body></worldbody>'
        "</mujoco>"
    )
    parent = loads("<mujoco/>")
    converted = in_conventions(child, parent)
    joint = find(converted, "joint", name="j")
    assert joint is not None and get_attribute(joint, "limited") is None
    assert model_differences(compiled(child), compiled(_under(converted, parent))) == []


def test_nothing_is_written_for_an_integrated_velocity_activation_limit() -> None:
    """An intvelocity gets no actlimited (MuJoCo 3.9 has no such attribute); compiles the same.

    MuJoCo 3.9 rejects an intvelocity without an ``actrange``, so there it has one.
    """
    actrange = "" if MUJOCO_VERSION >= (4, 0) else ' actrange="-1 1"'
    child = loads(
        f'<mujoco><compiler autolimits="false"/>{BODY}'
        f'<actuator><intvelocity name="v" joint="j" kp="1"{actrange}/></actuator></mujoco>'
    )
    parent = loads("<mujoco/>")
    converted = in_conventions(child, parent)
    actuator = find(converted, "intvelocity", name="v")
    assert actuator is not None and get_attribute(actuator, "actlimited") is None
    assert get_attribute(actuator, "ctrllimited") == "false"
    found = compiled(_under(converted, parent))
    assert model_differences(compiled(child), found) == []


REJECTED = "^" + re.escape(
    "the parent's autolimits='false' makes MuJoCo reject the child's "
    "<intvelocity actrange>; give the two models the same autolimits"
)


@pytest.mark.parametrize(
    "actuators",
    [
        '<actuator><intvelocity joint="j" kp="1" actrange="-1 1"/></actuator>',
        '<default><general actrange="-1 1"/></default>'
        '<actuator><intvelocity joint="j" kp="1"/></actuator>',
    ],
    ids=["own", "from its class"],
)
def test_an_integrated_velocity_range_refuses_autolimits_false(actuators: str) -> None:
    """An intvelocity actrange, own or from a class, is refused under autolimits="false".

    MuJoCo 3.9 reads it under autolimits="false" too: there it is kept, and compiles the same.
    """
    child = loads(f"<mujoco>{BODY}{actuators}</mujoco>")
    assert compiled(child).actuator_actlimited[0]
    rejected = loads(f'<mujoco><compiler autolimits="false"/>{BODY}{actuators}</mujoco>')
    parent = loads('<mujoco><compiler autolimits="false"/></mujoco>')
    if MUJOCO_VERSION < (4, 0):
        assert compiled(rejected).actuator_actlimited[0]
        converted = in_conventions(child, parent)
        assert model_differences(compiled(child), compiled(_under(converted, parent))) == []
        return
    with pytest.raises(MjcfError, match="actrange"):  # MuJoCo rejects it under the parent's
        compiled(rejected)
    with pytest.raises(MjcfValueError, match=REJECTED + "$"):
        in_conventions(child, parent)


def test_inheritrange_still_limits_the_control() -> None:
    """A position with inheritrange="1" is ctrl-limited to its joint's range, as the child alone."""
    child = loads(
        f'<mujoco>{BODY}<actuator><position joint="j" kp="1" inheritrange="1"/></actuator></mujoco>'
    )
    parent = loads('<mujoco><compiler autolimits="false"/></mujoco>')
    found = compiled(_under(in_conventions(child, parent), parent))
    assert found.actuator_ctrllimited[0]
    assert np.array_equal(found.actuator_ctrlrange, compiled(child).actuator_ctrlrange)
