"""A pytest plugin for mutation runs: a mutant's tests run shortest first.

mutmut 3.8 hands pytest the tests that call a mutated function in no particular
order, and stops at the first failure (``-x``): a killed mutant costs the tests
run before the one that kills it. Ordering them by the durations mutmut recorded
(``mutmut-stats.json`` in the folder it runs in) makes most kills take a second.
Tests it has no duration for were added after its run, most likely for the
survivors ``tests/mutation_rerun.py --all`` runs again: they go first.
Loaded by ``[tool.mutmut] pytest_add_cli_args`` (README); without the stats file
(mutmut's own first run, or any other run) the order is left alone.

A survivor costs every test that reaches its function. Where those include
corpus-wide tests (composition: three minutes a survivor), ``MUTATION_SECONDS``
leaves out the tests recorded as slower than that many seconds, keeping the
fastest one when every test is slower; the survivors of such a run are checked
against the whole selection afterwards (``tests/mutation_rerun.py --all``).
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

STATS = Path("mutmut-stats.json")


def recorded_durations(stats: Path = STATS) -> dict[str, float]:
    """The seconds each test took in mutmut's stats run, by node id; empty without one.

    Example:
        >>> recorded_durations(Path("no-such-file.json"))
        {}

    """
    if not stats.is_file():
        return {}
    durations: dict[str, float] = json.loads(stats.read_text())["duration_by_test"]
    return durations


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Run the shortest tests first; unrecorded ones (tests added since) before them all."""
    durations = recorded_durations()
    if not durations:
        return
    items.sort(key=lambda item: durations.get(item.nodeid, -1.0))
    limit = os.environ.get("MUTATION_SECONDS")
    if limit is not None and items:
        slow = [item for item in items[1:] if durations.get(item.nodeid, -1.0) > float(limit)]
        if slow:
            config.hook.pytest_deselected(items=slow)
            items[:] = items[: len(items) - len(slow)]
