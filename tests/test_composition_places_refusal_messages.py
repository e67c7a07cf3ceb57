"""attach() refusing a placement or an attach point: the error type and what the message tells.

Each model here is a few lines of MJCF, so the names an error lists are read off
the text; MuJoCo compiles each parent, so every name is one MuJoCo accepts.
"""

from __future__ import annotations

import re
from typing import Any

import mujoco
import pytest

from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.transforms.composition.attaching import attach
from serializers import loads

#: A parent with two bodies, a frame and a site named ``mount`` and one more site.
PARENT = """<mujoco><worldbody>
  <body name="base">
    <frame name="mount" pos="0 0 0.1"/>
    <site name="mount" pos="0 0.1 0"/>
    <body name="arm" pos="0 0 0.5"><site name="tip"/></body>
  </body>
</worldbody></mujoco>"""
#: A child with one body.
CHILD = '<mujoco><worldbody><body name="palm"/></worldbody></mujoco>'


def _parent() -> Any:
    mujoco.MjModel.from_xml_string(PARENT)  # MuJoCo accepts every name listed below
    return loads(PARENT)


def test_both_quat_and_euler_are_refused_in_full_words() -> None:
    """Both quat and euler: MjcfValueError telling to give the orientation one way only."""
    with pytest.raises(
        MjcfValueError, match=r"^give the child's orientation as quat or as euler, not both$"
    ):
        attach(_parent(), loads(CHILD), at="arm", quat=(1, 0, 0, 0), euler=(0, 0, 0))


def test_an_unknown_at_kind_is_refused_naming_the_three_kinds() -> None:
    """at_kind other than body, frame or site: MjcfValueError listing the three and the value."""
    kind: Any = "geom"
    with pytest.raises(
        MjcfValueError, match=r"^at_kind must be 'body', 'frame' or 'site', not 'geom'$"
    ):
        attach(_parent(), loads(CHILD), at="arm", at_kind=kind)


def test_a_name_of_two_kinds_lists_the_at_kind_values_to_choose() -> None:
    """A frame and a site of one name: the message offers at_kind='frame' or 'site'."""
    expected = (
        "the parent has a frame and a site named 'mount'; say which with at_kind='frame' or 'site'"
    )
    with pytest.raises(MjcfLookupError, match=f"^{re.escape(expected)}$"):
        attach(_parent(), loads(CHILD), at="mount")


def test_an_unknown_name_lists_the_bodies_frames_and_sites_by_kind() -> None:
    """An unknown ``at``: the message lists its bodies, frames and sites, sorted, in plain words."""
    listed = (
        "its bodies are ['arm', 'base'], its frames are ['mount'], its sites are ['mount', 'tip']"
    )
    expected = f"the parent has no body named 'elsewhere' (nor a frame or site); {listed}"
    with pytest.raises(MjcfLookupError, match=f"^{re.escape(expected)}$"):
        attach(_parent(), loads(CHILD), at="elsewhere")
    expected = f"the parent has no site named 'arm'; {listed}"
    with pytest.raises(MjcfLookupError, match=f"^{re.escape(expected)}$"):
        attach(_parent(), loads(CHILD), at="arm", at_kind="site")


@pytest.mark.parametrize("target", ["site", "frame"])
def test_a_target_inside_a_replicate_is_refused_naming_it(target: str) -> None:
    """A site or frame inside a <replicate> (copied, so not one place): MjcfValueError naming it."""
    text = (
        '<mujoco><worldbody><body name="b"><replicate count="2" offset="0.1 0 0">'
        f'<{target} name="here"/></replicate></body></worldbody></mujoco>'
    )
    mujoco.MjModel.from_xml_string(text)  # MuJoCo accepts the parent
    with pytest.raises(
        MjcfValueError, match=r"^cannot attach at 'here': it is inside a <replicate>$"
    ):
        attach(loads(text), loads(CHILD), at="here")


def test_a_site_placed_by_fromto_is_refused_saying_what_to_give_instead() -> None:
    """A fromto site: MjcfValueError saying MjSpec ignores it; give pos and an orientation."""
    site = '<site name="rod" type="capsule" size="0.01" fromto="0 0 0 0.1 0.1 0.1"/>'
    text = f'<mujoco><worldbody><body name="b">{site}</body></worldbody></mujoco>'
    mujoco.MjModel.from_xml_string(text)  # MuJoCo accepts the parent
    expected = (
        "cannot attach at site 'rod': its pose comes from 'fromto' (MjSpec would ignore it); "
        "give the site pos and an orientation instead"
    )
    with pytest.raises(MjcfValueError, match=f"^{re.escape(expected)}$"):
        attach(loads(text), loads(CHILD), at="rod")
