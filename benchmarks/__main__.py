"""Run the benchmarks: ``python -m benchmarks [--tiny] [--repeat N] [--output PATH]``.

Prints one table per case (median per contender and its ratio to mjcf-model) and
writes them all to ``benchmarks/RESULTS.md`` with the machine and the command.
"""

from __future__ import annotations

import argparse
import importlib.metadata
import os
import platform
import sys
import time
from pathlib import Path

from benchmarks.harness import Case, Row, run_case
from benchmarks.inputs import compiling_corpus
from benchmarks.sizes import sizes
from benchmarks.targets import targets

_RESULTS = Path(__file__).with_name("RESULTS.md")


def _machine() -> str:
    import mujoco

    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    versions = [f"Python {platform.python_version()}", f"mujoco {mujoco.__version__}"]
    for package in ("robosuite", "dm-control", "lxml"):
        try:
            versions.append(f"{package} {importlib.metadata.version(package)}")
        except importlib.metadata.PackageNotFoundError:
            versions.append(f"{package} not installed")
    return f"{platform.system()} {platform.release()}, {cpu}, {os.cpu_count()} CPUs; " + ", ".join(
        versions
    )


def _format(seconds: float | None) -> str:
    if seconds is None:
        return "-"
    return f"{seconds * 1e3:.3f} ms" if seconds < 1 else f"{seconds:.3f} s"


def _table(rows: list[Row]) -> str:
    lines = [
        "| case | inputs | contender | median | ratio to mjcf-model | peak memory | note |",
        "|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        ratio = f"{row.ratio:.2f}x" if row.ratio is not None else "-"
        peak = f"{row.peak_bytes / 2**10:,.0f} KiB" if row.peak_bytes is not None else ""
        lines.append(
            f"| {row.case} | {row.inputs} | {row.contender} | {_format(row.median)} | {ratio} "
            f"| {peak} | {row.note} |"
        )
    return "\n".join(lines)


#: How many corpus files a tiny run uses (enough for three with meshes).
_TINY_CORPUS = 12


def _cases(tiny: bool) -> list[Case]:
    from benchmarks.cases_corpus import corpus_cases
    from benchmarks.cases_imports import import_cases
    from benchmarks.cases_objects import object_cases
    from benchmarks.cases_synthetic import synthetic_cases
    from benchmarks.cases_variants import compile_cases, sweep_cases, variant_cases

    corpus = compiling_corpus(_TINY_CORPUS if tiny else None)
    return [
        *corpus_cases(corpus[:3] if tiny else corpus),
        *synthetic_cases(50 if tiny else 5000),
        *object_cases((2, 5) if tiny else (10, 100, 1000)),
        *import_cases(),
        *compile_cases(list(corpus), 3 if tiny else None),
        *variant_cases(tiny),
        *sweep_cases(tiny),
    ]


def main(argv: list[str] | None = None) -> int:
    """Run every case and write the results."""
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__)
    parser.add_argument("--tiny", action="store_true", help="tiny inputs, one repetition (CI)")
    parser.add_argument("--repeat", type=int, default=5, help="repetitions per contender")
    parser.add_argument("--output", type=Path, default=_RESULTS, help="where to write the table")
    args = parser.parse_args(argv)
    repeat = 1 if args.tiny else args.repeat
    started = time.perf_counter()
    rows: list[Row] = []
    for case in _cases(args.tiny):
        case_rows = run_case(case, repeat)
        rows.extend(case_rows)
        print(_table(case_rows).split("\n", 2)[2], flush=True)
    measured_sizes = sizes(compiling_corpus(_TINY_CORPUS if args.tiny else None), args.tiny)
    print(measured_sizes, flush=True)
    command = "python -m benchmarks " + " ".join(argv if argv is not None else sys.argv[1:])
    took = time.perf_counter() - started
    text = (
        "# Benchmark results\n\n"
        f"Machine: {_machine()}.\n\n"
        f"Command: `{command.strip()}` ({repeat} run(s) per contender; the median is "
        f"shown; ratio = contender's median / mjcf-model's). Took {took:.0f} s.\n\n"
        "## Targets\n\n" + targets(rows) + "\n\n## Sizes\n\n" + measured_sizes + "\n\n"
        "## All cases\n\n" + _table(rows) + "\n"
    )
    args.output.write_text(text, encoding="utf-8")
    print(f"written to {args.output}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
