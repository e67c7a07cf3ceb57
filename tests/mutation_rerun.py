"""Run surviving mutants again, each in a fresh process, against every test of the selection.

mutmut 3.8 forks every mutant from a process that has imported the library, and
records which tests call each function while the suite runs once. A function that
runs at import (the code that builds the namespace table, or robosuite's
``scale_*_element`` functions) has then already run, unmutated, when a mutant of it
is switched on, and mutmut credits it to the first test alone (the one that ran the
import): its mutants "survive" without having been tried. This script finds those
functions in ``mutants/mutmut-stats.json``, and runs each of their surviving mutants
in a new Python process, where the import happens under the mutant, against every
test of the selection (shortest first, ``tests/mutation_order.py``), and prints the
ones that still survive. Run it in the folder ``mutmut run`` ran in, after that run::

    HYPOTHESIS_PROFILE=mutation python tests/mutation_rerun.py

With ``--all`` it runs that way every mutant mutmut did not kill (survivors, those
no selected test reached, and those a stopped run left unchecked): after tests were
added (copy them into ``mutants/tests`` and the selection), the verdicts then need no
new mutmut run.

Not in CI; pinned to the stats format of mutmut 3.8.1 (the ``mutation`` extra).
"""

from __future__ import annotations

import collections
import concurrent.futures
import json
import os
import subprocess
import sys
import tomllib
from pathlib import Path

STATS = Path("mutants") / "mutmut-stats.json"


def import_time_functions(tests_by_function: dict[str, list[str]]) -> list[str]:
    """The functions credited to nothing but the test most often credited alone.

    Example:
        >>> import_time_functions({"a": ["t1"], "b": ["t1"], "c": ["t1", "t2"], "d": ["t2"]})
        ['a', 'b']

    """
    alone = collections.Counter(tests[0] for tests in tests_by_function.values() if len(tests) == 1)
    if not alone:
        return []
    first = alone.most_common(1)[0][0]
    return sorted(name for name, tests in tests_by_function.items() if tests == [first])


def _survivors(functions: list[str] | None) -> list[str]:
    """The surviving mutants of ``functions``; for ``None``, every mutant not killed."""
    results = subprocess.run(
        [sys.executable, "-m", "mutmut", "results"], capture_output=True, text=True, check=True
    ).stdout
    names = []
    for line in results.splitlines():
        mutant, _, verdict = line.strip().partition(": ")
        function = mutant.rsplit("__mutmut_", 1)[0]
        wanted = verdict == "survived" and (functions is None or function in functions)
        if wanted or (functions is None and verdict in ("not checked", "no tests")):
            names.append(mutant)
    return names


def _survives(mutant: str, tests: list[str]) -> bool:
    """Whether every test passes with ``mutant`` switched on from the first import."""
    command = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider"]
    command += ["-p", "tests.mutation_order", *tests]
    run = subprocess.run(
        command,
        cwd="mutants",
        env={**os.environ, "MUTANT_UNDER_TEST": mutant},
        capture_output=True,
        check=False,
    )
    if run.returncode == 5:  # no test ran: the selection is wrong, not the mutant killed
        raise SystemExit(f"no test ran for {mutant}: check pytest_add_cli_args_test_selection")
    return run.returncode == 0


def main() -> int:
    """Print each import-time survivor's verdict, then the number still surviving."""
    config = tomllib.loads(Path("pyproject.toml").read_text())["tool"]["mutmut"]
    tests: list[str] = config["pytest_add_cli_args_test_selection"]
    stats = json.loads(STATS.read_text())
    if not _survives("", tests):  # no mutant: a failing test would "kill" every mutant
        raise SystemExit("the selection fails without a mutant: fix it (or the copies) first")
    functions = import_time_functions(stats["tests_by_mangled_function_name"])
    mutants = _survivors(None if "--all" in sys.argv[1:] else functions)
    print(f"{len(mutants)} survivors to run again", file=sys.stderr)
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        verdicts = pool.map(lambda mutant: _survives(mutant, tests), mutants)
        left = 0
        for mutant, survived in zip(mutants, verdicts, strict=True):
            print(f"{mutant}: {'survived' if survived else 'killed'}", flush=True)
            left += survived
    print(f"{left} of {len(mutants)} still survive", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
