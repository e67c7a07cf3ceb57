"""Timing contenders side by side: medians, ratios and peak memory."""

from __future__ import annotations

import gc
import statistics
import time
import tracemalloc
from collections.abc import Callable
from dataclasses import dataclass, field

__all__ = ["OURS", "Case", "Contender", "Row", "run_case"]

#: The name of this library in every table.
OURS = "mjcf-model"


@dataclass
class Contender:
    """One tool's way of doing a case: ``run()`` does the work once."""

    name: str
    run: Callable[[], object] | None
    #: Why the contender cannot run here (``run`` is then ``None``).
    missing: str = ""
    #: What exactly the contender does, for the table's note column.
    note: str = ""
    #: The times of runs made elsewhere (another interpreter), when ``run`` is ``None``.
    times: list[float] | None = None


@dataclass
class Case:
    """A task every contender performs on the same inputs."""

    name: str
    contenders: list[Contender]
    #: What the inputs are, for the table.
    inputs: str = ""
    #: Also measure peak memory (tracemalloc) of one run.
    memory: bool = False


@dataclass
class Row:
    """The measurement of one contender in one case."""

    case: str
    contender: str
    inputs: str
    median: float | None
    ratio: float | None = None
    peak_bytes: int | None = None
    note: str = ""
    times: list[float] = field(default_factory=list)


def _median_time(run: Callable[[], object], repeat: int) -> list[float]:
    times = []
    for _ in range(repeat):
        gc.collect()
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return times


def _peak(run: Callable[[], object]) -> int:
    gc.collect()
    tracemalloc.start()
    try:
        run()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def run_case(case: Case, repeat: int) -> list[Row]:
    """Run every contender of ``case``; ratios are contender time over mjcf-model's."""
    rows = []
    for contender in case.contenders:
        if contender.run is None and contender.times is None:
            rows.append(Row(case.name, contender.name, case.inputs, None, note=contender.missing))
            continue
        if contender.run is None:
            times, peak = contender.times or [], None
        else:
            try:
                times = _median_time(contender.run, repeat)
            except Exception as error:  # a peer failing is a result, not a crash of the runner
                failed = f"failed: {error!r}"[:120]
                rows.append(Row(case.name, contender.name, case.inputs, None, note=failed))
                continue
            peak = _peak(contender.run) if case.memory else None
        rows.append(
            Row(
                case.name,
                contender.name,
                case.inputs,
                statistics.median(times),
                None,
                peak,
                contender.note,
                times,
            )
        )
    ours = next((r.median for r in rows if r.contender == OURS and r.median), None)
    for row in rows:
        if ours and row.median is not None:
            row.ratio = row.median / ours
    return rows
