"""Expanding ``<attach>``: what is refused, and what the user is told to do about it.

Each case is first put to MuJoCo: where MuJoCo refuses the scene too, the expansion
refuses it with its own error; where MuJoCo compiles it but the expansion cannot
reproduce the result exactly, the message names the construct and the way out.
MuJoCo 3.9 refuses every ``<attach>`` without ``model`` (MuJoCo 4.0's self-attach);
the expansion gives the same refusals under either release.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import inlined_attachments
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from serializers import load, loads
from tests.conftest import MUJOCO_VERSION

#: What MuJoCo 3.9 says of an ``<attach>`` without ``model``: its schema requires
#: ``model`` and has no ``frame`` (both came in MuJoCo 4.0); which it says first depends
#: on where the ``<attach>`` stands.
BEFORE_4 = "required attribute missing: 'model'|unrecognized attribute: 'frame'"


def test_euler_angles_in_another_sequence_are_refused_with_the_way_out(tmp_path: Path) -> None:
    """The refusal names both sequences and says to write the angles as quat first."""
    (tmp_path / "child.xml").write_text(
        '<mujoco><compiler eulerseq="zyx"/><worldbody><body name="b" euler="30 0 10">'
        '<joint/><geom size="0.1"/></body></worldbody></mujoco>',
        encoding="utf-8",
    )
    path = tmp_path / "scene.xml"
    path.write_text(
        '<mujoco><asset><model name="c" file="child.xml"/></asset><worldbody>'
        '<body name="a"><attach model="c" body="b" prefix="c_"/></body></worldbody></mujoco>',
        encoding="utf-8",
    )
    mujoco.MjModel.from_xml_path(str(path))
    message = (
        r"eulerseq='zyx' into one with eulerseq='xyz': its euler angles would be rewritten "
        r"in the other sequence, exactly only to the last digit; write them as quat "
        r"\(or give both models the same eulerseq\) first"
    )
    with pytest.raises(MjcfValueError, match=message):
        inlined_attachments(load(path))


def test_attach_without_model_body_or_frame_is_refused() -> None:
    """MuJoCo and the expansion refuse a self-attach that names nothing to copy."""
    text = (
        '<mujoco><worldbody><body name="a"><geom size="1"/></body>'
        '<body name="m"><attach prefix="c_"/></body></worldbody></mujoco>'
    )
    said = "either 'body' or 'frame' attribute must be specified"
    with pytest.raises(ValueError, match=said if MUJOCO_VERSION >= (4, 0) else BEFORE_4):
        mujoco.MjModel.from_xml_string(text)
    with pytest.raises(
        MjcfValueError, match=r"^an <attach> without model must name a body or a frame to copy$"
    ):
        inlined_attachments(loads(text))


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            '<mujoco><worldbody><body name="a"><geom size="1"/><body name="m">'
            '<attach body="a" prefix="c_"/></body></body></worldbody></mujoco>',
            r"^<attach body='a'> is inside the body it copies$",
        ),
        (
            '<mujoco><worldbody><frame name="f"><body name="m"><geom size="1"/>'
            '<attach frame="f" prefix="c_"/></body></frame></worldbody></mujoco>',
            r"^<attach frame='f'> is inside the frame it copies$",
        ),
    ],
    ids=["body", "frame"],
)
def test_attach_inside_what_it_copies_is_refused(text: str, message: str) -> None:
    """MuJoCo copies what it has read so far; the expansion refuses, naming the element."""
    if MUJOCO_VERSION >= (4, 0):
        mujoco.MjModel.from_xml_string(text)
    else:
        with pytest.raises(ValueError, match=BEFORE_4):
            mujoco.MjModel.from_xml_string(text)
    with pytest.raises(MjcfValueError, match=message):
        inlined_attachments(loads(text))


@pytest.mark.parametrize("kind", ["body", "frame"])
def test_attach_of_something_written_later_is_refused(kind: str) -> None:
    """MuJoCo copies only what it has read: both refuse an element written after the attach."""
    text = (
        f'<mujoco><worldbody><body name="m"><attach {kind}="late" prefix="c_"/></body>'
        f'<{kind} name="late"><geom size="1"/></{kind}></worldbody></mujoco>'
    )
    said = f"could not find {kind} 'late'" if MUJOCO_VERSION >= (4, 0) else BEFORE_4
    with pytest.raises(ValueError, match=said):
        mujoco.MjModel.from_xml_string(text)
    message = (
        rf"<attach {kind}='late'> without model: no {kind} of that name is written before it "
        r"\(MuJoCo copies only what it has read\)"
    )
    with pytest.raises(MjcfLookupError, match=message):
        inlined_attachments(loads(text))
