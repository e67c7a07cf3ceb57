"""robosuite's hard resets, with robosuite's objects and with this library's: parity.

A hard reset (robosuite's default) builds the environment's objects anew, merges the
robots, arena and objects into one model, writes its XML and compiles it. Each of the
19 environments (:data:`~benchmarks.environments.TASKS`) is built once each way; a run
is one hard reset, with the environment's modules building robosuite's objects or this
library's (:func:`~benchmarks.environments.our_objects`).

robosuite 1.5.2 runs only on MuJoCo up to 3.9. On a newer MuJoCo the group runs these
cases in the interpreter ``MJCF_MODEL_MUJOCO39_PYTHON`` names (one with MuJoCo 3.9,
robosuite 1.5.2 and this library, as ``tests/environments/oldest.txt`` pins them) and
reads its times back; without one, the rows say what is missing. Run alone::

    python -m benchmarks.cases_resets --repeat 5   # prints the times as JSON
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from benchmarks.environments import ROBOSUITE_RUNS, TASKS, make, our_objects
from benchmarks.harness import OURS, Case, Contender

__all__ = ["RESET_CASE", "ROBOSUITE_RESETS", "reset_cases"]

#: The name of each environment's case, and of robosuite's own contender in it.
RESET_CASE = "robosuite hard reset: {task}"
ROBOSUITE_RESETS = "robosuite (its own objects)"
#: The variable naming an interpreter robosuite's environments run in.
_PYTHON_VARIABLE = "MJCF_MODEL_MUJOCO39_PYTHON"
_MISSING = (
    f"robosuite 1.5.2 needs MuJoCo <= 3.9: set {_PYTHON_VARIABLE} to an interpreter with "
    "MuJoCo 3.9, robosuite 1.5.2 and mjcf-model (tests/environments/oldest.txt)"
)
_NOTE = "env.reset() with hard_reset: objects built, model merged, written and compiled"


def _resetter(env: Any, task: str, ours: bool) -> Callable[[], object]:
    def reset() -> object:
        if not ours:
            return env.reset()
        with our_objects(task):
            return env.reset()

    return reset


def _in_process(tasks: list[str]) -> list[Case]:
    cases = []
    for task in tasks:
        theirs = make(task, seed=0)
        with our_objects(task):
            mine = make(task, seed=0)
        cases.append(
            Case(
                RESET_CASE.format(task=task),
                [
                    Contender(OURS, _resetter(mine, task, ours=True), note=_NOTE),
                    Contender(ROBOSUITE_RESETS, _resetter(theirs, task, ours=False)),
                ],
                "1 hard reset",
            )
        )
    return cases


def _measured_elsewhere(tasks: list[str], repeat: int) -> list[Case]:
    python = os.environ.get(_PYTHON_VARIABLE)
    if not python:
        return [
            Case(
                RESET_CASE.format(task=task),
                [Contender(OURS, None, _MISSING), Contender(ROBOSUITE_RESETS, None, _MISSING)],
                "1 hard reset",
            )
            for task in tasks
        ]
    root = Path(__file__).resolve().parents[1]
    command = [python, "-m", "benchmarks.cases_resets", "--repeat", str(repeat), *tasks]
    found = subprocess.run(command, cwd=root, check=True, capture_output=True, text=True)
    times: dict[str, dict[str, list[float]]] = json.loads(found.stdout.splitlines()[-1])
    where = f"measured by {python}"
    return [
        Case(
            RESET_CASE.format(task=task),
            [
                Contender(OURS, None, note=f"{_NOTE}; {where}", times=times[task][OURS]),
                Contender(ROBOSUITE_RESETS, None, note=where, times=times[task][ROBOSUITE_RESETS]),
            ],
            "1 hard reset",
        )
        for task in tasks
    ]


def reset_cases(tiny: bool, repeat: int) -> list[Case]:
    """One case per environment (two with ``tiny``): a hard reset each way."""
    tasks = ["Lift", "TwoArmPegInHole"] if tiny else list(TASKS)
    if ROBOSUITE_RUNS:
        return _in_process(tasks)
    return _measured_elsewhere(tasks, repeat)


def main(argv: list[str] | None = None) -> int:
    """Measure the reset cases here and print each contender's times as one JSON line."""
    from benchmarks.harness import run_case

    parser = argparse.ArgumentParser(prog="python -m benchmarks.cases_resets")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("tasks", nargs="*", default=list(TASKS))
    args = parser.parse_args(argv)
    if not ROBOSUITE_RUNS:
        parser.error(_MISSING)
    times: dict[str, dict[str, list[float]]] = {}
    for task, case in zip(args.tasks, _in_process(args.tasks), strict=True):
        times[task] = {row.contender: row.times for row in run_case(case, args.repeat)}
    print(json.dumps(times))
    return 0


if __name__ == "__main__":
    sys.exit(main())
