"""Counting the prefix plans traced and applied: a fixture, and the counts expected.

A tree prefixed again and again is prefixed directly the first time, traces a plan the
second time (the trace applies it once itself, to check it against the direct
prefixing) and only applies that plan from then on.
"""

from __future__ import annotations

from typing import Any

import pytest

from mjcf_model.transforms.naming.repeated import PrefixPlan

#: The counts after each of four copies of one tree: planned once, at the second.
PLANNED_AT_THE_SECOND_COPY = [
    {"traced": 0, "applied": 0},
    {"traced": 1, "applied": 2},
    {"traced": 1, "applied": 3},
    {"traced": 1, "applied": 4},
]


@pytest.fixture
def plan_calls(monkeypatch: pytest.MonkeyPatch) -> dict[str, int]:
    """How often a plan is traced and applied while the test runs."""
    calls = {"traced": 0, "applied": 0}
    traced, applied = PrefixPlan.traced.__func__, PrefixPlan.applied  # type: ignore[attr-defined]

    def counting_traced(cls: type[PrefixPlan], *args: Any, **kwargs: Any) -> Any:
        calls["traced"] += 1
        return traced(cls, *args, **kwargs)

    def counting_applied(self: PrefixPlan, *args: Any, **kwargs: Any) -> Any:
        calls["applied"] += 1
        return applied(self, *args, **kwargs)

    monkeypatch.setattr(PrefixPlan, "traced", classmethod(counting_traced))
    monkeypatch.setattr(PrefixPlan, "applied", counting_applied)
    return calls
