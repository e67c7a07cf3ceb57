"""Tests of ``mjcf_model.transforms.composition.sections``."""

from __future__ import annotations

import re
import warnings
from pathlib import Path

import mujoco
import pytest

from mjcf_model import (
    MjcfDroppedSettingWarning,
    MjcfValueError,
    Mujoco,
    attach,
    attach_all,
    compiled,
)
from mjcf_model.serializers import loads

# -- A child's settings that the parent's replace are named in one warning, at the attach call.
#
# The parent keeps its ``<option>``, ``<size>``, ``<statistic>`` and ``<visual>``
# (MuJoCo's scene has one of each). Every setting of the child that does not hold
# in the scene is named in a :class:`~mjcf_model.MjcfDroppedSettingWarning` (one per
# section), by
# its element path and written value, with what holds instead: the parent's value,
# or MuJoCo's default when the parent writes none. MuJoCo referees what holds.


PARENT_DROPPED = '<mujoco><option timestep="0.004"/><visual><global fovy="45"/></visual></mujoco>'
CHILD_DROPPED = (
    '<mujoco><option timestep="0.01" density="2"/><visual><global fovy="50"/></visual></mujoco>'
)
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
        scene = attach(loads(PARENT_DROPPED), loads(CHILD_DROPPED), prefix="c_")
    who = "the child attached with prefix 'c_'"
    assert [str(w.message) for w in caught] == [who + lost for lost in LOST]
    alone, together = mujoco.MjModel.from_xml_string(PARENT_DROPPED), compiled(scene)
    assert together.opt.timestep == alone.opt.timestep == 0.004
    assert together.opt.density == alone.opt.density == 0.0  # MuJoCo's default density
    assert together.vis.global_.fovy == alone.vis.global_.fovy == 45.0


def test_a_child_attached_without_a_prefix_is_called_the_child() -> None:
    """Without a prefix the warning says "the child", with no prefix named."""
    with pytest.warns(MjcfDroppedSettingWarning) as caught:
        attach(loads(PARENT_DROPPED), loads(CHILD_DROPPED))
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
        parent, child = loads(PARENT_DROPPED), loads(CHILD_DROPPED)
        attach(parent, child, prefix="c_")  # the line the warning names
    lines = Path(__file__).read_text().splitlines()
    for warning in caught:
        assert warning.filename == __file__
        assert "the line the warning names" in lines[warning.lineno - 1]


# -- A child whose names meet the parent's is refused, and the message lists exactly the
#    clashes.
#
# MuJoCo rejects a model declaring one name twice in a namespace, so
# :func:`mjcf_model.attach` refuses such a child before composing. The message
# names each clashing namespace with its clashing names (and nothing else) and
# tells the user what to do: attach with a prefix, and for keys alone also
# ``keyframes='merged'``.


#: The start of every clash refusal.
START = "the child declares names the parent already has "


def _exactly(message: str) -> str:
    """A ``match`` pattern for exactly ``message``."""
    return f"^{re.escape(message)}$"


def test_only_the_clashing_name_is_listed_and_the_way_out_is_a_prefix() -> None:
    """Names only the child has (even in a namespace the parent lacks) are not listed."""
    parent = loads('<mujoco><worldbody><body name="a"/><body name="c"/></worldbody></mujoco>')
    child = loads(
        '<mujoco><worldbody><body name="a"><joint name="j"/><geom size="1"/></body>'
        '<body name="b"/></worldbody></mujoco>'
    )
    message = START + "(body: a); attach it with a prefix"
    with pytest.raises(MjcfValueError, match=_exactly(message)):
        attach(parent, child)


def test_several_names_in_several_namespaces_are_listed_each_under_its_namespace() -> None:
    """Clashing names are comma-separated within a namespace, namespaces separated by "; "."""
    parent = loads(
        '<mujoco><worldbody><body name="a"/><body name="b"><site name="s"/></body>'
        "</worldbody></mujoco>"
    )
    child = loads(
        '<mujoco><worldbody><body name="b"><site name="s"/></body><body name="a"/>'
        "</worldbody></mujoco>"
    )
    message = START + "(body: a, b; site: s); attach it with a prefix"
    with pytest.raises(MjcfValueError, match=_exactly(message)):
        attach(parent, child)


def test_a_clash_of_keys_also_suggests_merging_keys_of_one_name() -> None:
    """Keys of one name in both models clash, and the message offers ``keyframes='merged'``."""
    home = loads('<mujoco><keyframe><key name="home"/></keyframe></mujoco>')
    message = (
        START + "(key: home); attach it with a prefix (or keys of one name with keyframes='merged')"
    )
    with pytest.raises(MjcfValueError, match=_exactly(message)):
        attach(home, home)


# -- The dropped-setting warning names the user's line, whichever function was called. ---------
#
# The warning once used a fixed ``stacklevel`` counted for a call through
# :func:`mjcf_model.attach`; a direct :func:`mjcf_model.attach_all` call is one frame
# shallower, so the warning named the caller's caller.


PARENT_LOCATION = '<mujoco><option timestep="0.004"/></mujoco>'
CHILD_LOCATION = '<mujoco><option timestep="0.01"/></mujoco>'


def test_attach_all_warns_at_the_line_calling_it() -> None:
    """The dropped-setting warning of ``attach_all`` is reported at the user's call."""
    with pytest.warns(MjcfDroppedSettingWarning) as caught:
        parent, child = loads(PARENT_LOCATION), loads(CHILD_LOCATION)
        attach_all(parent, [(child, "c_")])  # the line the warning names
    lines = Path(__file__).read_text().splitlines()
    assert [(w.filename, "the line the warning names" in lines[w.lineno - 1]) for w in caught] == [
        (__file__, True)
    ]


# -- A setting section the parent does not write comes from the first child that writes it. ----
#
# The parent keeps its ``<option>``, ``<size>``, ``<statistic>`` and ``<visual>``;
# where it writes none, the first child writing one brings its own, and a later
# child's same section is checked against that one: only settings that differ
# are named in the :class:`~mjcf_model.MjcfDroppedSettingWarning`, which names
# the prefix the child was attached with. MuJoCo compiling the child alone says
# what its settings are.


FAST = """<mujoco>
  <option timestep="0.001"/>
  <worldbody><body name="cup"><geom size=".1"/></body></worldbody>
</mujoco>
"""
PLAIN = '<mujoco><worldbody><body name="bowl"><geom size=".2"/></body></worldbody></mujoco>'
#: A parent writing its own ``<option>``, with another timestep.
PARENT_LACKS = '<mujoco><option timestep="0.004"/></mujoco>'


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
        scene = attach(loads(PARENT_LACKS), loads(FAST), prefix="c_")
    assert compiled(scene).opt.timestep == _timestep(PARENT_LACKS)
