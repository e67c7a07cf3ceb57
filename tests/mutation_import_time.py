"""Give mutmut's import-time functions every test, and name their survivors to run again.

mutmut 3.8 records which tests call each function while the suite runs once. The
library's rule tables (the scaling rules, robosuite's ``scale_*_element`` functions) are
built by factories that run at import, which happens inside the first test: mutmut then
credits such a factory to that one test alone, and its mutants run against it alone.
This script gives those functions every test of the run, shortest first, in
``mutants/mutmut-stats.json`` and prints the names of their surviving mutants, for::

    python tests/mutation_import_time.py > names.txt
    HYPOTHESIS_PROFILE=mutation mutmut run $(cat names.txt)

Run it in the folder ``mutmut run`` ran in, after that run (not in CI; pinned to the
stats format of mutmut 3.8.1, the ``mutation`` extra).
"""

from __future__ import annotations

import collections
import json
import subprocess
import sys
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


def main() -> int:
    """Rewrite the stats and print the survivors of the import-time functions."""
    stats = json.loads(STATS.read_text())
    tests_by_function = stats["tests_by_mangled_function_name"]
    durations = stats["duration_by_test"]
    functions = import_time_functions(tests_by_function)
    every_test = sorted(durations, key=durations.get)
    for name in functions:
        tests_by_function[name] = every_test
    STATS.write_text(json.dumps(stats))
    results = subprocess.run(
        [sys.executable, "-m", "mutmut", "results"], capture_output=True, text=True, check=True
    ).stdout
    for line in results.splitlines():
        mutant, _, verdict = line.strip().partition(": ")
        if verdict == "survived" and mutant.rsplit("__mutmut_", 1)[0] in functions:
            print(mutant)
    print(f"{len(functions)} import-time functions given {len(every_test)} tests", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
