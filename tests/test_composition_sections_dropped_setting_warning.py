"""A child's settings that the parent's replace are named in one warning, at the attach call.

The parent keeps its ``<option>``, ``<size>``, ``<statistic>`` and ``<visual>``
(MuJoCo's scene has one of each). Every setting of the child that does not hold
in the scene is named in a :class:`~mjcf_model.MjcfDroppedSettingWarning` (one per
section), by
its element path and written value, with what holds instead: the parent's value,
or MuJoCo's default when the parent writes none. MuJoCo referees what holds.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import MjcfDroppedSettingWarning, attach, compiled
from serializers import loads

PARENT = '<mujoco><option timestep="0.004"/><visual><global fovy="45"/></visual></mujoco>'
CHILD = '<mujoco><option timestep="0.01" density="2"/><visual><global fovy="50"/></visual></mujoco>'
#: What the child loses, one warning per section, each after saying who loses it.
LOST = (
    " loses settings the parent's replace: "
    '<option timestep="0.01"> (the parent has "0.004"); '
    '<option density="2"> (the parent writes none: MuJoCo\'s default holds)',
    ' loses settings the parent\'s replace: <visual><global fovy="50"> (the parent has "45")',
)


def test_each_dropped_setting_is_named_with_what_holds_instead() -> None:
    """The warnings name the prefixed child and each lost setting; MuJoCo keeps the parent's."""
    with pytest.warns(MjcfDroppedSettingWarning) as caught:
        scene = attach(loads(PARENT), loads(CHILD), prefix="c_")
    who = "the child attached with prefix 'c_'"
    assert [str(w.message) for w in caught] == [who + lost for lost in LOST]
    alone, together = mujoco.MjModel.from_xml_string(PARENT), compiled(scene)
    assert together.opt.timestep == alone.opt.timestep == 0.004
    assert together.opt.density == alone.opt.density == 0.0  # MuJoCo's default density
    assert together.vis.global_.fovy == alone.vis.global_.fovy == 45.0


def test_a_child_attached_without_a_prefix_is_called_the_child() -> None:
    """Without a prefix the warning says "the child", with no prefix named."""
    with pytest.warns(MjcfDroppedSettingWarning) as caught:
        attach(loads(PARENT), loads(CHILD))
    assert [str(w.message) for w in caught] == ["the child" + lost for lost in LOST]


def test_a_setting_the_parent_writes_alike_is_not_named_but_the_next_one_is() -> None:
    """A child setting equal to the parent's is not lost; the settings after it still warn."""
    parent = '<mujoco><option timestep="0.004"/></mujoco>'
    child = '<mujoco><option timestep="0.004" density="2"/></mujoco>'
    with pytest.warns(MjcfDroppedSettingWarning) as caught:
        scene = attach(loads(parent), loads(child), prefix="c_")
    assert [str(w.message) for w in caught] == [
        "the child attached with prefix 'c_' loses settings the parent's replace: "
        '<option density="2"> (the parent writes none: MuJoCo\'s default holds)'
    ]
    assert compiled(scene).opt.density == mujoco.MjModel.from_xml_string(parent).opt.density


def test_the_warning_points_at_the_line_calling_attach() -> None:
    """The warnings are reported at the user's ``attach`` call, not inside the library."""
    with pytest.warns(MjcfDroppedSettingWarning) as caught:
        attach(loads(PARENT), loads(CHILD), prefix="c_")  # the line the warning names
    lines = Path(__file__).read_text().splitlines()
    for warning in caught:
        assert warning.filename == __file__
        assert "the line the warning names" in lines[warning.lineno - 1]
