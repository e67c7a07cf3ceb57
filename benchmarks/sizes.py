"""Sizes rather than times: what a pickled subtree weighs, what loaded models keep, big lists.

Issue 26's size targets, measured on the corpus and on a generated 50 MB attribute,
written to ``RESULTS.md`` beside the timed cases as a table of their own.
"""

from __future__ import annotations

import gc
import itertools
import pickle
import random
import tempfile
import time
import tracemalloc
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

__all__ = ["sizes"]

#: The bound issue 26 sets on a pickled subtree: twice its own text plus a small constant.
_SLACK = 1024


def _own(element: Any, model: Any, path: Path) -> int:
    layout = element.layout
    return path.stat().st_size if element is model else layout.after - layout.begin


def _pickled_line(label: str, size: int, own: int) -> str:
    met = size <= 2 * own + _SLACK
    return (
        f"| pickled {label}: bytes / bytes of its own text | {size:,} / {own:,} = "
        f"{size / own:.2f} (target <= 2 + {_SLACK:,} bytes) | {'met' if met else 'MISSED'} |"
    )


def _pickled(files: tuple[Path, ...], most: int | None) -> list[str]:
    """Robosuite's Panda: a geom, its biggest body, the model; every element of ``most`` files."""
    from benchmarks.inputs import package_dir
    from mjcf_model import Body, Geom, walk
    from mjcf_model.serializers import load

    lines = []
    robosuite = package_dir("robosuite")
    if robosuite is not None:
        panda = robosuite / "models/assets/robots/panda/robot.xml"
        model = load(panda)
        elements = [e for _, e in walk(model)]
        geom = next(e for e in elements if isinstance(e, Geom))
        bodies = [e for e in elements if isinstance(e, Body)]
        body = max(bodies, key=lambda e: _own(e, model, panda))
        for label, element in (("geom", geom), ("body", body), ("model", model)):
            own = _own(element, model, panda)
            lines.append(_pickled_line(f"Panda {label}", len(pickle.dumps(element)), own))
    within = total = 0
    worst = (0.0, "")
    for path in files[:most]:
        model = load(path)
        for _, element in walk(model):
            if element.layout is None:
                continue
            own, size = _own(element, model, path), len(pickle.dumps(element))
            total += 1
            if size <= 2 * own + _SLACK:
                within += 1
            else:
                place = f"<{element.tag}> of {path.parent.name}/{path.name}, {own:,} bytes"
                worst = max(worst, (size / own, place))
    missing = f"; the others at most {worst[0]:.2f}x ({worst[1]})" if within < total else ""
    lines.append(
        f"| pickled corpus elements within 2x their text + {_SLACK:,} bytes | {within:,} of "
        f"{total:,}{missing} | {'met' if within == total else 'MISSED'} |"
    )
    return lines


def _traced(run: Callable[[], Any]) -> tuple[Any, float, int, int]:
    """``run()``'s result, seconds, and the bytes it left allocated and its peak growth."""
    gc.collect()
    tracemalloc.start()
    started = time.perf_counter()
    result = run()
    took = time.perf_counter() - started
    gc.collect()
    kept, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    return result, took, kept, peak


def _prefixed_memory(files: tuple[Path, ...], count: int) -> str:
    """The memory ``count`` loaded-then-prefixed corpus models keep (the corpus in turn)."""
    from mjcf_model import prefixed
    from mjcf_model.serializers import load

    def keep() -> list[Any]:
        paths = itertools.cycle(files)
        return [prefixed(load(next(paths), inline_includes=True), f"m{i}/") for i in range(count)]

    _, _, kept, _ = _traced(keep)
    return (
        f"| {count:,} loaded-then-prefixed corpus models: memory kept | "
        f"{kept / 2**20:,.1f} MiB ({kept / count / 2**10:,.0f} KiB a model) | measured |"
    )


def _numbers(megabytes: int) -> Iterator[str]:
    rng = random.Random(0)
    size = 0
    while size < megabytes * 1_000_000:
        text = f"{rng.uniform(-1, 1):.6f}"
        size += len(text) + 1
        yield text


def _big_list(megabytes: int) -> list[str]:
    """A mesh with a ``megabytes`` MB ``vertex`` attribute: load time and peak memory growth."""
    from mjcf_model.serializers import load

    numbers = list(_numbers(megabytes))
    numbers = numbers[: len(numbers) - len(numbers) % 3]
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "big.xml"
        path.write_text(
            f'<mujoco><asset><mesh name="m" vertex="{" ".join(numbers)}"/></asset>'
            '<worldbody><geom type="mesh" mesh="m"/></worldbody></mujoco>'
        )
        del numbers
        size = path.stat().st_size
        started = time.perf_counter()
        load(path)
        took = time.perf_counter() - started
        _, _, _, peak = _traced(lambda: load(path))
    return [
        f"| load a {size / 1e6:.0f} MB number list: seconds | {took:.2f} (target <= 5) | "
        f"{'met' if took <= 5 else 'MISSED'} |",
        f"| load a {size / 1e6:.0f} MB number list: peak memory growth / file size | "
        f"{peak / size:.1f} (target <= 8; {peak / 2**20:,.0f} MiB, traced) | "
        f"{'met' if peak <= 8 * size else 'MISSED'} |",
    ]


def sizes(files: tuple[Path, ...], tiny: bool = False) -> str:
    """The size table: pickled subtrees, memory kept by prefixed models, a big number list.

    ``files`` are the corpus files MuJoCo compiles; ``tiny`` measures a little of each.
    """
    lines = ["| measure | measured | |", "|---|---|---|"]
    lines += _pickled(files, 3 if tiny else None)
    lines.append(_prefixed_memory(files, 20 if tiny else 1000))
    lines += _big_list(1 if tiny else 50)
    return "\n".join(lines)
