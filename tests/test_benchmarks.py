"""The benchmark runner keeps working (one tiny run; timings are never asserted)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from benchmarks.harness import OURS, Case, Contender, run_case


def test_tiny_run_writes_every_case_with_every_contender(tmp_path: Path) -> None:
    """``python -m benchmarks --tiny`` runs every case and writes the results table."""
    output = tmp_path / "RESULTS.md"
    done = subprocess.run(
        [sys.executable, "-m", "benchmarks", "--tiny", "--output", str(output)],
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    text = output.read_text(encoding="utf-8")
    assert "## Targets" in text and "Machine:" in text and "--tiny" in text
    for case in (
        "corpus: load + prefix + dump",
        "corpus: load + dump",
        "corpus: prefix alone",
        "corpus: uniform scale alone",
        "synthetic deep: load + dump",
        "synthetic wide: hash",
        "construct CanObject",
        "compose 5 cans + write XML",
    ):
        assert f"| {case}" in text, case
    for contender in ("robosuite", "dm_control.mjcf", "MjSpec", "lxml", "ElementTree"):
        assert contender in text, contender
    assert "failed:" not in text


def test_ratios_are_relative_to_this_library() -> None:
    """Each ratio is the contender's median over mjcf-model's; a missing contender has none."""

    def work(n: int) -> None:
        sum(range(n))

    case = Case(
        "demo",
        [
            Contender(OURS, lambda: work(200_000)),
            Contender("slower", lambda: work(400_000)),
            Contender("absent", None, "not installed"),
        ],
    )
    rows = {row.contender: row for row in run_case(case, repeat=5)}
    assert rows[OURS].ratio == 1.0
    slower, ours = rows["slower"].median, rows[OURS].median
    assert slower is not None and ours is not None
    assert rows["slower"].ratio == slower / ours
    assert len(rows["slower"].times) == 5
    assert rows["absent"].median is None and rows["absent"].note == "not installed"
