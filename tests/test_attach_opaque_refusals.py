"""attach refuses a parent or a child holding elements whose contents are not in the tree.

An ``<include>`` names another file and a ``<composite>`` (removed in MuJoCo 4.0)
makes elements that are nowhere in the tree, so attaching either model could
give a scene MuJoCo reads differently. The error says which element is in the
way, that the action was attaching, and what to do instead
(``refuse_opaque`` in mjcf_model/tree/traversal.py).
"""

from __future__ import annotations

import pytest

from mjcf_model import MjcfValueError, attach
from serializers import loads

PLAIN = '<mujoco><worldbody><body name="cup"><geom size=".1"/></body></worldbody></mujoco>'
INCLUDING = '<mujoco><include file="parts.xml"/></mujoco>'
COMPOSITE = (
    '<mujoco><worldbody><body name="cloth"><composite type="grid" count="2 2 1"/></body>'
    "</worldbody></mujoco>"
)
INCLUDE_REFUSED = r"cannot attach a model with <include> elements: .* inline_includes=True"
COMPOSITE_REFUSED = r"cannot attach a model with <composite> elements: .* <replicate> or <flexcomp>"


def test_a_parent_with_an_include_is_refused() -> None:
    """A parent with an ``<include>`` is refused, telling the user to inline includes."""
    with pytest.raises(MjcfValueError, match=INCLUDE_REFUSED):
        attach(loads(INCLUDING), loads(PLAIN), prefix="c_")


def test_a_parent_with_a_composite_is_refused() -> None:
    """A parent with a ``<composite>`` is refused, telling the user what to write instead."""
    with pytest.raises(MjcfValueError, match=COMPOSITE_REFUSED):
        attach(loads(COMPOSITE), loads(PLAIN), prefix="c_")


def test_a_child_with_an_include_is_refused() -> None:
    """A child with an ``<include>`` is refused, telling the user to inline includes."""
    with pytest.raises(MjcfValueError, match=INCLUDE_REFUSED):
        attach(loads(PLAIN), loads(INCLUDING), prefix="c_")


def test_a_child_with_a_composite_is_refused() -> None:
    """A child with a ``<composite>`` is refused, telling the user what to write instead."""
    with pytest.raises(MjcfValueError, match=COMPOSITE_REFUSED):
        attach(loads(PLAIN), loads(COMPOSITE), prefix="c_")
