"""Timing contenders side by side: medians (or least times), ratios and peak memory."""

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
    #: Time the contenders in turns (one untimed round first, then each round in the
    #: other order) instead of one after the other: for ratios near 1, where a slow
    #: stretch of a shared machine would otherwise fall on one contender only.
    interleaved: bool = False
    #: Time at least this many runs, whatever the runner's ``--repeat`` (a ratio near 1
    #: on a machine whose single runs now and then take twice as long needs more than 5).
    least_repeat: int = 0
    #: Show each contender's least time rather than its median: for work that does the
    #: same every run, where the machine's noise only ever adds time.
    least: bool = False


@dataclass
class Row:
    """The measurement of one contender in one case."""

    case: str
    contender: str
    inputs: str
    #: The time shown: the median of the runs, or their least where the case asks for it.
    time: float | None
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


def _interleaved_times(runs: list[Callable[[], object]], repeat: int) -> list[list[float]]:
    """Times of ``repeat`` rounds of every run, after one untimed round; the order turns."""
    for run in runs:
        run()
    times: list[list[float]] = [[] for _ in runs]
    for round_ in range(repeat):
        order = list(range(len(runs)))
        if round_ % 2:
            order.reverse()
        for index in order:
            gc.collect()
            start = time.perf_counter()
            runs[index]()
            times[index].append(time.perf_counter() - start)
    return times


def _peak(run: Callable[[], object]) -> int:
    gc.collect()
    tracemalloc.start()
    try:
        run()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def _taken_in_turns(case: Case, repeat: int) -> dict[str, list[float]]:
    """The times of an interleaved case's runnable contenders by name (none for others).

    A contender that fails here is timed again alone, so that its failure is reported.
    """
    runnable = [c for c in case.contenders if c.run is not None]
    if not case.interleaved or len(runnable) < 2:
        return {}
    try:
        times = _interleaved_times([c.run for c in runnable if c.run is not None], repeat)
    except Exception:  # run_case times each alone and reports the failure
        return {}
    return {c.name: t for c, t in zip(runnable, times, strict=True)}


def run_case(case: Case, repeat: int) -> list[Row]:
    """Run every contender of ``case``; ratios are contender time over mjcf-model's.

    Each contender runs ``repeat`` times (or ``case.least_repeat``, the more), one after
    the other or, for an interleaved case, in turns.
    """
    rows = []
    repeat = max(repeat, case.least_repeat)
    taken_in_turns = _taken_in_turns(case, repeat)
    for contender in case.contenders:
        if contender.run is None and contender.times is None:
            rows.append(Row(case.name, contender.name, case.inputs, None, note=contender.missing))
            continue
        if contender.run is None:
            times, peak = contender.times or [], None
        elif contender.name in taken_in_turns:
            times = taken_in_turns[contender.name]
            peak = _peak(contender.run) if case.memory else None
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
                min(times) if case.least else statistics.median(times),
                None,
                peak,
                contender.note,
                times,
            )
        )
    ours = next((r.time for r in rows if r.contender == OURS and r.time), None)
    for row in rows:
        if ours and row.time is not None:
            row.ratio = row.time / ours
    return rows
