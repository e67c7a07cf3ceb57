"""The composition check: two models from different folders attached into one scene.

For models ``a`` and ``b`` (files, each in its own folder, with its own meshes
and ``<compiler>``), :func:`compose_problems` builds
``attach(attach(empty, a, prefix="a_"), b, prefix="b_")`` and reports, stage by
stage, what keeps the scene from being right:

1. ``compiled``: the scene compiles in memory and is exactly its parts
   (tests/support/composition_oracle.py): its counts are the sums and every per-object
   array of every part's objects (bodies, joints, geoms... meshes, keys) holds
   the values MuJoCo gives them in their own file;
2. ``dump``: the scene dumped into a fresh folder compiles from there to the
   identical model;
3. ``export``: the exported folder, moved, compiles to the identical model.

MuJoCo compiling each file on its own is the referee. Run it over any two
folders of models with ``python -m tests.support.composing A.xml B.xml ...``.
"""

from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path
from typing import Any

import attrs
import mujoco

from mjcf_model import Mujoco, attach, compiled
from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.serializers import dump, export, load
from tests.support.composition_oracle import PlacedPart, composition_problems

__all__ = ["STAGES", "Outcome", "compose_problems"]

#: The stages of the check, in order; a stage runs only when the ones before it passed.
STAGES = ("attach", "compiled", "dump", "export")


@attrs.frozen
class Outcome:
    """What the check found for one pair."""

    #: The stages passed, in order.
    passed: tuple[str, ...]
    #: What went wrong at the first stage that failed (empty when all passed).
    problems: tuple[str, ...] = ()


def compose_problems(paths: list[Path], workdir: Path, *, parent: Path | None = None) -> Outcome:
    """Attach the models at ``paths`` (prefixes ``a_``, ``b_``...) and check the scene.

    They are attached into an empty world, or into the model at ``parent``,
    loaded from its file: its own objects must then keep their values too.
    """
    prefixes = [f"{chr(ord('a') + i)}_" for i in range(len(paths))]
    alone = [mujoco.MjModel.from_xml_path(str(path)) for path in paths]
    if parent is not None:
        prefixes, alone = ["", *prefixes], [mujoco.MjModel.from_xml_path(str(parent)), *alone]
    passed: list[str] = []
    try:
        scene = Mujoco() if parent is None else load(parent, inline_includes=True)
        for path, prefix in zip(paths, prefixes[-len(paths) :], strict=True):
            scene = attach(scene, load(path, inline_includes=True), prefix=prefix)
    except Exception as error:  # the check reports every failure, whatever its kind
        return Outcome(tuple(passed), (f"{type(error).__name__}: {error}",))
    passed.append("attach")
    try:
        together = compiled(scene)
    except Exception as error:
        return Outcome(tuple(passed), (f"{type(error).__name__}: {error}",))
    if parent is None:
        prefixes, alone = ["", *prefixes], [mujoco.MjModel.from_xml_string("<mujoco/>"), *alone]
    parts = [PlacedPart(model, prefix) for model, prefix in zip(alone, prefixes, strict=True)]
    problems = composition_problems(parts, together)
    if problems:
        return Outcome(tuple(passed), tuple(problems))
    passed.append("compiled")
    dumped = workdir / "dumped" / "scene.xml"
    dumped.parent.mkdir(parents=True)
    dump(scene, dumped)
    problems = same_model(dumped, together)
    if problems:
        return Outcome(tuple(passed), tuple(problems))
    passed.append("dump")
    exported = export(scene, workdir / "exported")
    shutil.move(workdir / "exported", workdir / "moved")
    problems = same_model(workdir / "moved" / exported.name, together)
    if problems:
        return Outcome(tuple(passed), tuple(problems))
    passed.append("export")
    return Outcome(tuple(passed))


def same_model(path: Path, expected: Any) -> list[str]:
    """Why the model at ``path`` is not ``expected`` (MuJoCo compiles both), if it is not."""
    try:
        again = mujoco.MjModel.from_xml_path(str(path))
    except ValueError as error:
        return [f"{path.name} does not compile: {str(error).strip()}"]
    return [f"field {f}" for f in model_differences(expected, again, ignore=path_fields())]


def main(arguments: list[str]) -> int:
    """Check consecutive pairs of the files given; print one line per pair and a summary."""
    paths = [Path(a) for a in arguments]
    pairs = list(zip(paths[::2], paths[1::2], strict=False))
    reached = dict.fromkeys(STAGES, 0)
    for a, b in pairs:
        with tempfile.TemporaryDirectory() as workdir:
            outcome = compose_problems([a, b], Path(workdir))
        for stage in outcome.passed:
            reached[stage] += 1
        status = "ok" if len(outcome.passed) == len(STAGES) else "FAILED"
        print(f"{status} {a} + {b}: {'; '.join(outcome.problems[:3])}")
    print(f"pairs {len(pairs)}; passed per stage: {reached}")
    return 0 if all(count == len(pairs) for count in reached.values()) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
