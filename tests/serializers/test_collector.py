"""The garbage collector is the caller's: reading never switches it, ``collector_paused`` does."""

from __future__ import annotations

import gc
from pathlib import Path

import pytest

from mjcf_model.serializers import collector_paused, load, loads


def test_reading_leaves_the_collector_running(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """``load`` and ``loads`` never call ``gc.disable``: the switch is process-wide."""
    switched: list[str] = []
    monkeypatch.setattr(gc, "disable", lambda: switched.append("disable"))
    text = "<mujoco><worldbody>" + '<body><geom size="1"/></body>' * 200 + "</worldbody></mujoco>"
    path = tmp_path / "m.xml"
    path.write_text(text)
    assert len(loads(text).worldbody.bodies) == 200
    assert load(path) == loads(text)
    assert switched == []


def test_collector_paused_pauses_and_restores_only_what_it_changed() -> None:
    """Paused inside the block; running after it; left off when the caller had it off."""
    assert gc.isenabled()
    with collector_paused():
        assert not gc.isenabled()
        model = loads('<mujoco><worldbody><geom size="1"/></worldbody></mujoco>')
    assert gc.isenabled() and model.worldbody is not None
    gc.disable()
    try:
        with collector_paused():
            assert not gc.isenabled()
        assert not gc.isenabled()
    finally:
        gc.enable()
    with pytest.raises(ValueError, match="inside"), collector_paused():
        raise ValueError("inside")
    assert gc.isenabled()
