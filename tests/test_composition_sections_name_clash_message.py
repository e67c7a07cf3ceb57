"""A child whose names meet the parent's is refused, and the message lists exactly the clashes.

MuJoCo rejects a model declaring one name twice in a namespace, so
:func:`mjcf_model.attach` refuses such a child before composing. The message
names each clashing namespace with its clashing names (and nothing else) and
tells the user what to do: attach with a prefix, and for keys alone also
``keyframes='merged'``.
"""

from __future__ import annotations

import re

import pytest

from mjcf_model import MjcfValueError, attach
from serializers import loads

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
