"""A child whose ``eulerseq`` MuJoCo rejects is refused by ``attach`` with an ``MjcfValueError``."""

from __future__ import annotations

import mujoco
import pytest

from mjcf_model import Mujoco, attach
from mjcf_model.errors import MjcfValueError
from serializers import loads

CHILD = (
    '<mujoco><compiler eulerseq="{}"/><worldbody><body name="b" euler="10 20 30">'
    '<geom size="0.1"/></body></worldbody></mujoco>'
)


@pytest.mark.parametrize("sequence", ["xy", "xyzx"])
def test_an_eulerseq_of_other_than_three_axes_is_refused_as_mujoco_does(sequence: str) -> None:
    """MuJoCo rejects the child; attaching it says what MuJoCo reads instead of a bare error."""
    with pytest.raises(ValueError, match="XML Error"):
        mujoco.MjModel.from_xml_string(CHILD.format(sequence))
    with pytest.raises(MjcfValueError, match=rf"eulerseq='{sequence}'.*exactly 3 axes"):
        attach(Mujoco(), loads(CHILD.format(sequence)), prefix="c_")
