"""A setting section the parent does not write comes from the first child that writes it.

The parent keeps its ``<option>``, ``<size>``, ``<statistic>`` and ``<visual>``;
where it writes none, the first child writing one brings its own, and a later
child's same section is checked against that one: only settings that differ
are named in the :class:`~mjcf_model.MjcfDroppedSettingWarning`, which names
the prefix the child was attached with. MuJoCo compiling the child alone says
what its settings are.
"""

from __future__ import annotations

import warnings

import mujoco
import pytest

from mjcf_model import MjcfDroppedSettingWarning, Mujoco, attach, attach_all, compiled
from serializers import loads

FAST = """<mujoco>
  <option timestep="0.001"/>
  <worldbody><body name="cup"><geom size=".1"/></body></worldbody>
</mujoco>
"""
PLAIN = '<mujoco><worldbody><body name="bowl"><geom size=".2"/></body></worldbody></mujoco>'
#: A parent writing its own ``<option>``, with another timestep.
PARENT = '<mujoco><option timestep="0.004"/></mujoco>'


def _timestep(text: str) -> float:
    return float(mujoco.MjModel.from_xml_string(text).opt.timestep)


def test_a_childs_option_holds_when_the_parent_writes_none() -> None:
    """Into a parent without ``<option>``, the child's ``timestep`` holds in the scene."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        scene = attach(Mujoco(), loads(FAST), prefix="a_")
    assert compiled(scene).opt.timestep == _timestep(FAST)


def test_a_later_child_without_the_section_keeps_the_first_childs() -> None:
    """A second child writing no ``<option>`` leaves the first child's ``timestep`` in place."""
    scene = attach_all(Mujoco(), [(loads(FAST), "a_"), (loads(PLAIN), "b_")])
    assert compiled(scene).opt.timestep == _timestep(FAST)


def test_a_later_child_writing_the_same_settings_loses_nothing() -> None:
    """Two children writing the same ``<option>``: no warning, and their ``timestep`` holds."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        scene = attach_all(Mujoco(), [(loads(FAST), "a_"), (loads(FAST), "b_")])
    assert compiled(scene).opt.timestep == _timestep(FAST)


def test_the_dropped_setting_warning_names_the_childs_prefix() -> None:
    """The warning says which child loses its ``timestep``: the one attached with prefix 'c_'."""
    with pytest.warns(MjcfDroppedSettingWarning, match=r"prefix 'c_' loses settings.*timestep"):
        scene = attach(loads(PARENT), loads(FAST), prefix="c_")
    assert compiled(scene).opt.timestep == _timestep(PARENT)
