"""Tests of ``mjcf_model.tools.check``."""

from __future__ import annotations

from pathlib import Path

import pytest

# -- The ``mjcf-model`` command line. ----------------------------------------------------------


def test_written_model_that_does_not_compile_is_an_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """check_file reports an error, not a crash, when the written text does not compile."""
    from mjcf_model.tools import check
    from mjcf_model.tools.check import check_file

    path = tmp_path / "m.xml"
    path.write_text("<mujoco><worldbody><geom size='0.1'/></worldbody></mujoco>")
    assert check_file(path).ok
    monkeypatch.setattr(check, "dumps", lambda node: "<mujoco><nonsense/></mujoco>")
    result = check_file(path)
    assert result.status == "error"
    assert "the written model does not compile" in result.message
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.xml"]  # no temporary file left
