"""The speed targets of the project, checked against one run's rows (a report, not a test)."""

from __future__ import annotations

import re

import numpy as np

from benchmarks.cases_resets import RESET_CASE, ROBOSUITE_RESETS
from benchmarks.cases_variants import BATCHED_CASE, PATCHED
from benchmarks.harness import OURS, Row

__all__ = ["targets"]


def _time(rows: list[Row], case: str, contender: str) -> float | None:
    for row in rows:
        if row.case == case and row.contender.startswith(contender):
            return row.time
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
    bound = f"target {'<=' if at_most else '>='} {limit:g}"
    return f"| {text} | {value:.2f} ({bound}) | {'met' if met else 'MISSED'} |"


def _ratio(a: float | None, b: float | None) -> float | None:
    return a / b if a is not None and b else None


def _at_most(rows: list[Row], case: str, peer: str, label: str, limit: float) -> str:
    """mjcf-model's time over ``peer``'s in ``case``: met when at most ``limit``."""
    return _line(
        f"{label}: mjcf-model time / {peer} time",
        _ratio(_time(rows, case, OURS), _time(rows, case, peer)),
        limit,
        at_most=True,
    )


def _faster(rows: list[Row], case: str, peer: str, label: str, limit: float) -> str:
    """``peer``'s time over mjcf-model's in ``case``: met when at least ``limit``."""
    return _line(
        f"{label}: {peer} time / mjcf-model time",
        _ratio(_time(rows, case, peer), _time(rows, case, OURS)),
        limit,
        at_most=False,
    )


def _compose(rows: list[Row]) -> list[str]:
    sizes = sorted(
        {int(m.group(1)) for r in rows if (m := re.match(r"compose (\d+) cans \+ write", r.case))}
    )
    if len(sizes) < 2:
        return []
    big, small = sizes[-1], sizes[-2]
    write_big = f"compose {big} cans + write XML"
    memory = f"compose {big} cans, before writing (peak memory)"
    peaks = (_peak(rows, memory, OURS), _peak(rows, memory, "robosuite"))
    return [
        _line(
            f"compose: mjcf-model time N={big} / N={small} (linear: {big / small:g})",
            _ratio(
                _time(rows, write_big, OURS),
                _time(rows, f"compose {small} cans + write XML", OURS),
            ),
            1.2 * big / small,
            at_most=True,
        ),
        _faster(rows, write_big, "robosuite", f"compose {big} cans + write", 20),
        _line(
            f"compose {big} cans peak memory: mjcf-model / robosuite",
            _ratio(*(float(p) if p else None for p in peaks)),
            1.0,
            at_most=True,
        ),
    ]


def _scene(rows: list[Row]) -> list[str]:
    """Issue 39's targets on the 20,000-body scene: load, find by name, prefix + write."""
    return [
        _at_most(rows, "scene: load", "ElementTree", "scene load", 2.0),
        *[
            _at_most(
                rows,
                f"scene: find a geom by name, first query of a {kind} tree",
                "ElementTree",
                f"scene find by name, first query of a {kind} tree",
                2.0,
            )
            for kind in ("loaded", "transformed", "built")
        ],
        _at_most(
            rows,
            "scene: find a geom by name, asked again",
            "ElementTree",
            "scene find by name, asked again",
            2.0,
        ),
        _at_most(rows, "scene: prefix + write", "robosuite", "scene prefix + write", 1.5),
    ]


def _per_case(rows: list[Row], prefix: str, peer: str) -> dict[str, float]:
    """mjcf-model's time over ``peer``'s in every case whose name starts with ``prefix``."""
    ratios = {}
    for case in sorted({row.case for row in rows if row.case.startswith(prefix)}):
        ratio = _ratio(_time(rows, case, OURS), _time(rows, case, peer))
        if ratio is not None:
            ratios[case.removeprefix(prefix)] = ratio
    return ratios


def _variants(rows: list[Row]) -> list[str]:
    """Issue 26's targets: compiling mesh models, the physical and the scaled variant loops."""
    lines = []
    compiles = _per_case(rows, "compile: ", "MjModel.from_xml_path")
    if compiles:
        worst = max(compiles, key=compiles.__getitem__)
        within = sum(ratio <= 1.2 for ratio in compiles.values())
        lines.append(
            _line(
                f"compile a mesh model: compiled(load(p)) / from_xml_path(p), worst of "
                f"{len(compiles)} ({worst}; {within} within 1.2)",
                compiles[worst],
                1.2,
                at_most=True,
            )
        )
    physical = _per_case(rows, "physical variants: ", "MjSpec")
    if physical:
        lines.append(_geometric_mean_line("physical variants + compile", physical))
        # mjcf-model/patched over mjcf-model/MjSpec: MjSpec's time over patched()'s.
        faster = _patched_speedups(rows, "physical variants: ", physical)
        if faster:
            slowest = min(faster, key=faster.__getitem__)
            lines.append(
                _line(
                    f"physical variants, patched: MjSpec time / patched() time, least of "
                    f"{len(faster)} ({slowest}; {_listed(faster)})",
                    faster[slowest],
                    10.0,
                    at_most=False,
                )
            )
    scaled = _per_case(rows, "scaled variants: ", "MjSpec")
    if scaled:
        lines.append(_geometric_mean_line("scaled variants + compile", scaled))
        faster = _patched_speedups(rows, "scaled variants: ", scaled)
        panda = next((case for case in faster if case.startswith("panda/")), None)
        if panda is not None:
            lines.append(
                _line(
                    f"scaled variants, patched: MjSpec time / patched() time on {panda} "
                    f"({_listed(faster)})",
                    faster[panda],
                    20.0,
                    at_most=False,
                )
            )
    batch = _time(rows, BATCHED_CASE, OURS)
    count = next((row.inputs for row in rows if row.case == BATCHED_CASE), "")
    if batch:
        variants = int(count.split()[0]) if count[:1].isdigit() else 0
        lines.append(
            f"| {BATCHED_CASE}: variants per second ({count.split(' (')[0]}) "
            f"| {variants / batch:,.0f} | measured |"
        )
    return lines


def _patched_speedups(rows: list[Row], prefix: str, against: dict[str, float]) -> dict[str, float]:
    """MjSpec's time over ``patched()``'s per case (``against``: ours over MjSpec's)."""
    patched = _per_case(rows, prefix, PATCHED)  # ours over patched()'s
    return {case: ratio / against[case] for case, ratio in patched.items() if case in against}


def _listed(ratios: dict[str, float]) -> str:
    """``case 12.3, other 4.5``: ratios for people, in case order."""
    return ", ".join(f"{case.split('/')[0]} {ratio:.1f}" for case, ratio in sorted(ratios.items()))


def _geometric_mean_line(
    label: str, ratios: dict[str, float], peer: str = "MjSpec", limit: float = 1.0
) -> str:
    """mjcf-model's time over ``peer``'s, geometric mean over cases: met when at most ``limit``."""
    worst = max(ratios, key=ratios.__getitem__)
    return _line(
        f"{label}: mjcf-model time / {peer} time, geometric mean of {len(ratios)} "
        f"(worst: {worst} {ratios[worst]:.2f})",
        float(np.exp(np.mean(np.log(list(ratios.values()))))),
        limit,
        at_most=True,
    )


def _resets(rows: list[Row]) -> list[str]:
    """Issue 39's parity target: robosuite's hard resets with our objects and with its own."""
    prefix = RESET_CASE.format(task="")
    ratios = _per_case(rows, prefix, ROBOSUITE_RESETS)
    if not ratios:
        return [_line("robosuite hard resets (19 environments)", None, 1.05, at_most=True)]
    return [_geometric_mean_line("robosuite hard reset", ratios, "robosuite", 1.05)]


def targets(rows: list[Row]) -> str:
    """A table: each target, the measured ratio, and whether it holds (issue 12's targets).

    Each ratio says which time is divided by which, and its bound says which way is met.

    Example:
        >>> from benchmarks.harness import Row
        >>> rows = [Row("corpus: load + dump", OURS, "", 0.3),
        ...         Row("corpus: load + dump", "ElementTree parse + tostring", "", 0.1)]
        >>> print(targets(rows).splitlines()[4])
        | corpus load + dump: mjcf-model time / ElementTree time | 3.00 (target <= 1.5) | MISSED |

    """
    lines = ["| target | measured | |", "|---|---|---|"]
    prefix = "corpus: load + prefix + dump"
    lines.append(_at_most(rows, prefix, "robosuite", "corpus load + prefix + dump", 1.5))
    lines.append(_faster(rows, prefix, "dm_control", "corpus load + prefix + dump", 20))
    lines.append(_at_most(rows, "corpus: load + dump", "ElementTree", "corpus load + dump", 1.5))
    lines.append(_at_most(rows, "corpus: load", "ElementTree", "corpus load", 2.0))
    lines.append(
        _at_most(rows, "corpus: prefix alone", "robosuite add_prefix", "corpus prefix", 1.0)
    )
    lines += _scene(rows)
    for shape in ("deep", "wide"):
        case = f"synthetic {shape}: load + dump"
        lines.append(_at_most(rows, case, "ElementTree", f"synthetic {shape} load + dump", 1.5))
    scale = "robosuite scale_mjcf_model"
    lines.append(_at_most(rows, "corpus: uniform scale alone", scale, "corpus uniform scale", 1.0))
    for shape in ("deep", "wide"):
        case = f"synthetic {shape}: uniform scale"
        lines.append(_at_most(rows, case, scale, f"synthetic {shape} uniform scale", 1.0))
    for label in ("CanObject", "BoxObject", "CompositeObject"):
        case = f"construct {label} + get_obj() + asset (compat layer)"
        lines.append(
            _at_most(rows, case, "robosuite", f"construct {label} + get_obj() + asset", 1.0)
        )
    lines += _compose(rows)
    lines += _resets(rows)
    for shape in ("deep", "wide"):
        load = _time(rows, f"synthetic {shape}: load", OURS)
        for what in ("== of two separately loaded models", "hash"):
            lines.append(
                _line(
                    f"synthetic {shape}: mjcf-model time of {what} / of load",
                    _ratio(_time(rows, f"synthetic {shape}: {what}", OURS), load),
                    1,
                    at_most=True,
                )
            )
    lines += _variants(rows)
    return "\n".join(lines)
