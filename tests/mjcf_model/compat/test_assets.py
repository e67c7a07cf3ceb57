"""Tests of ``mjcf_model.compat.assets``: where robosuite's asset files are."""

from __future__ import annotations

import importlib.util
import os
from typing import Any

import pytest
import robosuite.models

from mjcf_model.compat.assets import assets_root
from mjcf_model.errors import MjcfLookupError


def test_the_assets_root_is_robosuites() -> None:
    """The folder is robosuite's own ``models.assets_root``, holding its textures and objects."""
    assert os.path.samefile(assets_root(), robosuite.models.assets_root)
    assert os.path.isdir(os.path.join(assets_root(), "textures"))
    assert os.path.isfile(os.path.join(assets_root(), "objects", "can.xml"))


def test_without_robosuite_the_lookup_error_says_so(monkeypatch: pytest.MonkeyPatch) -> None:
    """When robosuite cannot be found, the error is a lookup error with the caller's message."""
    find_spec = importlib.util.find_spec

    def without_robosuite(name: str, *arguments: Any) -> Any:
        return None if name == "robosuite" else find_spec(name, *arguments)

    monkeypatch.setattr(importlib.util, "find_spec", without_robosuite)
    with pytest.raises(MjcfLookupError) as default:
        assets_root()
    assert "robosuite is not installed" in str(default.value)
    with pytest.raises(MjcfLookupError) as given:
        assets_root("the can needs robosuite")
    assert str(given.value) == "the can needs robosuite"
