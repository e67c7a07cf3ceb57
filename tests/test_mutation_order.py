"""The mutation-run plugin orders a mutant's tests shortest first and can leave slow ones out."""

from __future__ import annotations

import json
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pytest

from tests.mutation_order import pytest_collection_modifyitems

#: Seconds mutmut recorded per test; "new" has none (added after the stats run).
DURATIONS = {"slow": 3.0, "quick": 0.01, "middle": 0.2}


def _ordered(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, names: list[str]) -> Any:
    (tmp_path / "mutmut-stats.json").write_text(json.dumps({"duration_by_test": DURATIONS}))
    monkeypatch.chdir(tmp_path)
    left_out: list[str] = []
    hook = SimpleNamespace(pytest_deselected=lambda items: left_out.extend(i.nodeid for i in items))
    items = [SimpleNamespace(nodeid=name) for name in names]
    pytest_collection_modifyitems(SimpleNamespace(hook=hook), items)  # type: ignore[arg-type]
    return [item.nodeid for item in items], left_out


def test_tests_run_shortest_first_and_new_ones_before_all(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Without a limit every test runs: the unrecorded one first, then by recorded time."""
    monkeypatch.delenv("MUTATION_SECONDS", raising=False)
    names = ["slow", "middle", "new", "quick"]
    assert _ordered(tmp_path, monkeypatch, names) == (["new", "quick", "middle", "slow"], [])


def test_a_limit_leaves_out_slower_tests_but_never_all(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``MUTATION_SECONDS`` deselects tests recorded as slower; the fastest always stays."""
    monkeypatch.setenv("MUTATION_SECONDS", "0.1")
    kept, left_out = _ordered(tmp_path, monkeypatch, ["slow", "middle", "quick"])
    assert (kept, left_out) == (["quick"], ["middle", "slow"])
    assert _ordered(tmp_path, monkeypatch, ["slow", "middle"]) == (["middle"], ["slow"])
