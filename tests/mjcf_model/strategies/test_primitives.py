"""Tests of ``mjcf_model.strategies.primitives``: names and comments MuJoCo reads."""

from __future__ import annotations

import mujoco
from hypothesis import given, settings

from mjcf_model import Comment
from mjcf_model.serializers import dumps, loads
from mjcf_model.strategies import comments, names

NO_DEADLINE = settings(deadline=None)


@NO_DEADLINE
@given(names())
def test_every_drawn_name_is_one_mujoco_finds_the_body_by(name: str) -> None:
    """A drawn name names a body MuJoCo compiles and looks up by that name."""
    text = f'<mujoco><worldbody><body name="{name}"><geom size="0.1"/></body></worldbody></mujoco>'
    assert mujoco.MjModel.from_xml_string(text).body(name).name == name


@NO_DEADLINE
@given(comments())
def test_every_drawn_comment_is_written_where_mujoco_reads_past_it(comment: Comment) -> None:
    """A drawn comment's text comes back unchanged and MuJoCo compiles the file around it."""
    text = f"<mujoco>{dumps(comment)}<worldbody/></mujoco>"
    assert mujoco.MjModel.from_xml_string(text).nbody == 1
    assert loads(text).children[0] == comment
