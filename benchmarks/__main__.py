"""Run the benchmarks: ``python -m benchmarks [--tiny] [--repeat N] [--only ...] [--output PATH]``.

Prints one table per case (median or least time per contender and its ratio to mjcf-model) and
writes them all to ``benchmarks/RESULTS.md`` with the machine and the command.

The whole run takes about 15 minutes; ``--only`` measures a part of it, so that a
change to a hot path is measured before and after in a minute::

    python -m benchmarks --only corpus:prefix,synthetic --peers robosuite,ElementTree

A selected run writes to ``benchmarks/RESULTS-only.md`` unless ``--output`` says
otherwise: ``RESULTS.md`` always holds a whole run.
"""

from __future__ import annotations

import argparse
import dataclasses
import importlib.metadata
import os
import platform
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from benchmarks.harness import OURS, Case, Row, run_case
from benchmarks.inputs import compiling_corpus
from benchmarks.sizes import sizes
from benchmarks.targets import targets

_RESULTS = Path(__file__).with_name("RESULTS.md")
#: Where a run of some cases (``--only``, ``--peers``) writes unless told otherwise.
_RESULTS_ONLY = Path(__file__).with_name("RESULTS-only.md")


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
        "| case | inputs | contender | time | ratio to mjcf-model | peak memory | note |",
        "|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        ratio = f"{row.ratio:.2f}x" if row.ratio is not None else "-"
        peak = f"{row.peak_bytes / 2**10:,.0f} KiB" if row.peak_bytes is not None else ""
        lines.append(
            f"| {row.case} | {row.inputs} | {row.contender} | {_format(row.time)} | {ratio} "
            f"| {peak} | {row.note} |"
        )
    return "\n".join(lines)


#: How many corpus files a tiny run uses (enough for three with meshes).
_TINY_CORPUS = 12

#: The groups of cases, in the order a whole run measures them (``sizes`` is the table of
#: sizes, not timed cases).
GROUPS = (
    "corpus",
    "synthetic",
    "scene",
    "objects",
    "imports",
    "compile",
    "variants",
    "sweep",
    "resets",
    "sharing",
    "sizes",
)


@dataclass(frozen=True)
class Selection:
    """What ``--only`` and ``--peers`` chose: groups, case-name filters and peers.

    Examples:
        >>> chosen = Selection.parse("corpus:prefix,synthetic", "robosuite")
        >>> chosen.groups, chosen.case_wanted("corpus", "corpus: prefix alone")
        (('corpus', 'synthetic'), True)
        >>> chosen.case_wanted("corpus", "corpus: load + dump"), chosen.peer_wanted("MjSpec")
        (False, False)

    """

    #: The groups to build and run, in :data:`GROUPS` order.
    groups: tuple[str, ...] = GROUPS
    #: Per group, the words one of which a case's name must contain (none: every case).
    filters: dict[str, tuple[str, ...]] = field(default_factory=dict)
    #: Words one of which a peer's name must contain (``None``: every peer).
    peers: tuple[str, ...] | None = None

    @classmethod
    def parse(cls, only: str | None, peers: str | None) -> Selection:
        """Read ``--only GROUP[:WORD][,...]`` and ``--peers WORD[,...]``.

        Raises:
            ValueError: A group that does not exist (the message lists those that do).

        """
        filters: dict[str, list[str]] = {}
        for item in (only or ",".join(GROUPS)).split(","):
            group, _, word = item.strip().partition(":")
            if group not in GROUPS:
                raise ValueError(f"no benchmark group {group!r}; the groups: {', '.join(GROUPS)}")
            words = filters.setdefault(group, [])
            if word.strip():
                words.append(word.strip().lower())
        chosen = tuple(group for group in GROUPS if group in filters)
        wanted_peers = None if peers is None else tuple(p.strip().lower() for p in peers.split(","))
        return cls(chosen, {k: tuple(v) for k, v in filters.items() if v}, wanted_peers)

    @property
    def whole(self) -> bool:
        """Whether this is the whole run (what ``RESULTS.md`` holds)."""
        return self.groups == GROUPS and not self.filters and self.peers is None

    def case_wanted(self, group: str, name: str) -> bool:
        """Whether the case ``name`` of ``group`` is measured."""
        words = self.filters.get(group)
        return not words or any(word in name.lower() for word in words)

    def peer_wanted(self, name: str) -> bool:
        """Whether the contender ``name`` is measured (mjcf-model always is)."""
        if name == OURS or self.peers is None:
            return True
        return any(word in name.lower() for word in self.peers)

    def chosen(self, case: Case) -> Case:
        """``case`` with only the wanted contenders."""
        kept = [c for c in case.contenders if self.peer_wanted(c.name)]
        return dataclasses.replace(case, contenders=kept)


def _group_cases(group: str, tiny: bool, selection: Selection, repeat: int) -> list[Case]:
    """The cases of one group, built only when the group is selected (building costs)."""
    corpus = compiling_corpus(_TINY_CORPUS if tiny else None)
    if group == "corpus":
        from benchmarks.cases_corpus import corpus_cases

        return corpus_cases(corpus[:3] if tiny else corpus, selection.peer_wanted)
    if group == "synthetic":
        from benchmarks.cases_synthetic import synthetic_cases

        return synthetic_cases(50 if tiny else 5000)
    if group == "scene":
        from benchmarks.cases_scene import SCENE_BODIES, scene_cases

        return scene_cases(50 if tiny else SCENE_BODIES)
    if group == "objects":
        from benchmarks.cases_objects import object_cases

        return object_cases((2, 5) if tiny else (10, 100, 1000))
    if group == "imports":
        from benchmarks.cases_imports import import_cases

        return import_cases()
    if group == "resets":
        from benchmarks.cases_resets import reset_cases

        return reset_cases(tiny, repeat)
    if group == "sharing":
        from benchmarks.cases_sharing import COPIES, sharing_cases

        return sharing_cases((2,) if tiny else COPIES)
    from benchmarks.cases_variants import compile_cases, sweep_cases, variant_cases

    if group == "compile":
        return compile_cases(list(corpus), 3 if tiny else None)
    if group == "variants":
        return variant_cases(tiny)
    return sweep_cases(tiny)


def _cases(tiny: bool, selection: Selection | None = None, repeat: int = 1) -> list[Case]:
    """The selected cases (all of them by default), with the selected contenders."""
    selection = selection or Selection()
    cases = []
    for group in selection.groups:
        if group == "sizes":
            continue
        for case in _group_cases(group, tiny, selection, repeat):
            if selection.case_wanted(group, case.name):
                cases.append(selection.chosen(case))
    return cases


def main(argv: list[str] | None = None) -> int:
    """Run every case and write the results."""
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__)
    parser.add_argument("--tiny", action="store_true", help="tiny inputs, one repetition (CI)")
    parser.add_argument("--repeat", type=int, default=5, help="repetitions per contender")
    parser.add_argument("--output", type=Path, default=None, help="where to write the table")
    parser.add_argument(
        "--only",
        help="measure only these groups, GROUP[:WORD] separated by commas: a WORD keeps the "
        f"cases of GROUP whose name contains it (groups: {', '.join(GROUPS)})",
    )
    parser.add_argument(
        "--peers",
        help="measure only the peers whose name contains one of these words, separated by "
        "commas (mjcf-model is always measured)",
    )
    args = parser.parse_args(argv)
    try:
        selection = Selection.parse(args.only, args.peers)
    except ValueError as error:
        parser.error(str(error))
    output = args.output or (_RESULTS if selection.whole else _RESULTS_ONLY)
    repeat = 1 if args.tiny else args.repeat
    started = time.perf_counter()
    rows: list[Row] = []
    for case in _cases(args.tiny, selection, repeat):
        case_rows = run_case(case, repeat)
        rows.extend(case_rows)
        print(_table(case_rows).split("\n", 2)[2], flush=True)
    measured_sizes = "not measured in this run"
    if "sizes" in selection.groups:
        measured_sizes = sizes(compiling_corpus(_TINY_CORPUS if args.tiny else None), args.tiny)
        print(measured_sizes, flush=True)
    command = "python -m benchmarks " + " ".join(argv if argv is not None else sys.argv[1:])
    took = time.perf_counter() - started
    text = (
        "# Benchmark results\n\n"
        f"Machine: {_machine()}.\n\n"
        f"Command: `{command.strip()}` ({repeat} run(s) per contender unless the note says "
        f"more; the median is shown unless the note says the least; ratio = contender's "
        f"time / mjcf-model's). Took {took:.0f} s.\n\n"
        "## Targets\n\n" + targets(rows) + "\n\n## Sizes\n\n" + measured_sizes + "\n\n"
        "## All cases\n\n" + _table(rows) + "\n"
    )
    output.write_text(text, encoding="utf-8")
    print(f"written to {output}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
