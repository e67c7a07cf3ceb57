"""Tests of ``mjcf_model.tools.settings``: the nearest ``[tool.mjcf-model]`` table."""

from __future__ import annotations

from pathlib import Path

import pytest

from mjcf_model.errors import MjcfValueError
from mjcf_model.tools.settings import project_settings


def test_the_nearest_file_with_the_table_is_found_and_one_without_it_is_passed(
    tmp_path: Path,
) -> None:
    """A ``pyproject.toml`` without the table does not stop the search upwards."""
    (tmp_path / "pyproject.toml").write_text('[tool.mjcf-model.lint]\nselect = ["K"]\n')
    inner = tmp_path / "robots" / "arm"
    inner.mkdir(parents=True)
    (tmp_path / "robots" / "pyproject.toml").write_text("[project]\nname = 'x'\n")
    table, path = project_settings(inner)
    assert table == {"lint": {"select": ["K"]}} and path == tmp_path / "pyproject.toml"


def test_no_table_gives_nothing_and_a_broken_file_is_named(tmp_path: Path) -> None:
    """Empty settings and ``None`` without any; a file TOML cannot read names itself."""
    assert project_settings(tmp_path / "nowhere") == ({}, None)
    (tmp_path / "pyproject.toml").write_text("[tool.mjcf-model\n")
    with pytest.raises(MjcfValueError) as caught:
        project_settings(tmp_path)
    assert caught.value.file == str(tmp_path / "pyproject.toml")
