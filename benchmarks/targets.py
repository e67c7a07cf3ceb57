"""The speed targets of the project, checked against one run's rows (a report, not a test)."""

from __future__ import annotations

import re

from benchmarks.harness import OURS, Row

__all__ = ["targets"]


def _median(rows: list[Row], case: str, contender: str) -> float | None:
    for row in rows:
        if row.case == case and row.contender.startswith(contender):
            return row.median
    return None


def _peak(rows: list[Row], case: str, contender: str) -> int | None:
    for row in rows:
        if row.case == case and row.contender.startswith(contender):
            return row.peak_bytes
    return None


def _line(text: str, value: float | None, limit: float, at_most: bool) -> str:
    if value is None:
        return f"| {text} | not measured | |"
    met = value <= limit if at_most else value >= limit
    bound = f"{'<=' if at_most else '>='} {limit:g}"
    return f"| {text} | {value:.2f} ({bound}) | {'met' if met else 'MISSED'} |"


def _ratio(a: float | None, b: float | None) -> float | None:
    return a / b if a is not None and b else None


def targets(rows: list[Row]) -> str:
    """A table: each target, the measured ratio, and whether it holds."""
    lines = ["| target | measured | |", "|---|---|---|"]
    corpus = "corpus: load + prefix + dump"
    ours = _median(rows, corpus, OURS)
    lines.append(
        _line(
            "corpus load + prefix + dump: mjcf-model / robosuite ElementTree path",
            _ratio(ours, _median(rows, corpus, "robosuite")),
            1.5,
            at_most=True,
        )
    )
    lines.append(
        _line(
            "corpus load + prefix + dump: dm_control.mjcf / mjcf-model",
            _ratio(_median(rows, corpus, "dm_control"), ours),
            20,
            at_most=False,
        )
    )
    sizes = sorted(
        {int(m.group(1)) for r in rows if (m := re.match(r"compose (\d+) cans \+ write", r.case))}
    )
    if len(sizes) >= 2:
        big, small = sizes[-1], sizes[-2]
        write_big, write_small = (
            f"compose {big} cans + write XML",
            f"compose {small} cans + write XML",
        )
        ours_big = _median(rows, write_big, OURS)
        lines.append(
            _line(
                f"compose: mjcf-model N={big} / N={small} (linear: {big / small:g}x)",
                _ratio(ours_big, _median(rows, write_small, OURS)),
                1.2 * big / small,
                at_most=True,
            )
        )
        lines.append(
            _line(
                f"compose N={big}: robosuite / mjcf-model",
                _ratio(_median(rows, write_big, "robosuite"), ours_big),
                20,
                at_most=False,
            )
        )
        memory = f"compose {big} cans, before writing (peak memory)"
        lines.append(
            _line(
                f"compose N={big} peak memory: mjcf-model / robosuite ElementTree",
                _ratio(
                    *(
                        float(p) if p else None
                        for p in (_peak(rows, memory, OURS), _peak(rows, memory, "robosuite"))
                    )
                ),
                1.0,
                at_most=True,
            )
        )
    for shape in ("deep", "wide"):
        name = f"synthetic {shape}"
        load = _median(rows, f"{name}: load", OURS)
        lines.append(
            _line(
                f"{name}: load + dump, mjcf-model / ElementTree",
                _ratio(
                    _median(rows, f"{name}: load + dump", OURS),
                    _median(rows, f"{name}: load + dump", "ElementTree"),
                ),
                3,
                at_most=True,
            )
        )
        for what in ("== of two separately loaded models", "hash"):
            lines.append(
                _line(
                    f"{name}: {what} / load",
                    _ratio(_median(rows, f"{name}: {what}", OURS), load),
                    1,
                    at_most=True,
                )
            )
    return "\n".join(lines)
