"""The dropped-setting warning names the user's line, whichever function was called.

The warning once used a fixed ``stacklevel`` counted for a call through
:func:`mjcf_model.attach`; a direct :func:`mjcf_model.attach_all` call is one frame
shallower, so the warning named the caller's caller.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mjcf_model import MjcfDroppedSettingWarning, attach_all
from serializers import loads

PARENT = '<mujoco><option timestep="0.004"/></mujoco>'
CHILD = '<mujoco><option timestep="0.01"/></mujoco>'


def test_attach_all_warns_at_the_line_calling_it() -> None:
    """The dropped-setting warning of ``attach_all`` is reported at the user's call."""
    with pytest.warns(MjcfDroppedSettingWarning) as caught:
        attach_all(loads(PARENT), [(loads(CHILD), "c_")])  # the line the warning names
    lines = Path(__file__).read_text().splitlines()
    assert [(w.filename, "the line the warning names" in lines[w.lineno - 1]) for w in caught] == [
        (__file__, True)
    ]
