"""The composition check: two models from different folders attached into one scene.

For models ``a`` and ``b`` (files, each in its own folder, with its own meshes
and ``<compiler>``), :func:`compose_problems` builds
``attach(attach(empty, a, prefix="a_"), b, prefix="b_")`` and reports, stage by
stage, what keeps the scene from being right:

1. ``compiled``: the scene compiles in memory; its counts are the sums; every
   mesh keeps its vertex count; every named body, joint, geom, site and
   actuator compiles to the values MuJoCo gives it in its own file;
2. ``dump``: the scene dumped into a fresh folder compiles from there to the
   identical model;
3. ``export``: the exported folder, moved, compiles to the identical model.

MuJoCo compiling each file on its own is the referee. Run it over any two
folders of models with ``python -m tests.composing A.xml B.xml ...``.
"""

from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path
from typing import Any

import attrs
import mujoco
import numpy as np

from mjcf_model import Mujoco, attach, compiled
from mjcf_model.tools.compare import compiled_names, model_differences, path_fields
from serializers import dump, export, load

__all__ = ["STAGES", "Outcome", "compose_problems"]

#: The stages of the check, in order; a stage runs only when the ones before it passed.
STAGES = ("attach", "compiled", "dump", "export")

#: Per kind of named object: the compiled fields that must keep their values.
COMPARED: dict[str, tuple[str, ...]] = {
    "body": ("body_pos", "body_quat", "body_mass", "body_inertia", "body_ipos", "body_iquat"),
    "jnt": (
        "jnt_type",
        "jnt_range",
        "jnt_limited",
        "jnt_axis",
        "jnt_pos",
        "jnt_stiffness",
        "qpos0",
    ),
    "geom": (
        "geom_type",
        "geom_size",
        "geom_pos",
        "geom_quat",
        "geom_friction",
        "geom_contype",
        "geom_conaffinity",
    ),
    "site": ("site_pos", "site_quat", "site_size"),
    "actuator": (
        "actuator_ctrlrange",
        "actuator_forcerange",
        "actuator_ctrllimited",
        "actuator_forcelimited",
        "actuator_gear",
        "actuator_gainprm",
        "actuator_biasprm",
    ),
    "mesh": ("mesh_vertnum",),
}
#: The counts that must add up.
COUNTS = ("nbody", "njnt", "ngeom", "nmesh", "nu", "nsite")


@attrs.frozen
class Outcome:
    """What the check found for one pair."""

    #: The stages passed, in order.
    passed: tuple[str, ...]
    #: What went wrong at the first stage that failed (empty when all passed).
    problems: tuple[str, ...] = ()


def _rows(model: Any, field: str, index: int) -> np.ndarray[Any, Any]:
    values = np.asarray(getattr(model, field))
    if field == "qpos0":  # per joint: its qpos values
        start = int(model.jnt_qposadr[index])
        size = {0: 7, 1: 4}.get(int(model.jnt_type[index]), 1)
        return values[start : start + size]
    return values[index]


def value_problems(alone: Any, scene: Any, prefix: str) -> list[str]:
    """The named objects of ``alone`` whose values differ from ``prefix`` + name in ``scene``."""
    problems = []
    names_alone, names_scene = compiled_names(alone), compiled_names(scene)
    for kind, fields in COMPARED.items():
        where = {name: i for i, name in enumerate(names_scene[kind]) if name}
        for index, name in enumerate(names_alone[kind]):
            if not name or (kind == "body" and index == 0):
                continue
            other = where.get(prefix + name)
            if other is None:
                problems.append(f"{kind} {prefix + name!r} is missing")
                continue
            for field in fields:
                a, b = _rows(alone, field, index), _rows(scene, field, other)
                if a.shape != b.shape or not np.allclose(a, b, rtol=1e-9, atol=1e-12):
                    problems.append(f"{kind} {name!r}: {field} {a.tolist()} -> {b.tolist()}")
    return problems


def _count_problems(alone: list[Any], scene: Any) -> list[str]:
    problems = []
    for count in COUNTS:
        expected = sum(getattr(m, count) for m in alone) - (len(alone) - 1) * (count == "nbody")
        if getattr(scene, count) != expected:
            problems.append(f"{count} is {getattr(scene, count)}, expected {expected}")
    return problems


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
    problems = _count_problems(alone, together)
    for model, prefix in zip(alone, prefixes, strict=True):
        problems += value_problems(model, together, prefix)
    if problems:
        return Outcome(tuple(passed), tuple(problems))
    passed.append("compiled")
    dumped = workdir / "dumped" / "scene.xml"
    dumped.parent.mkdir(parents=True)
    dump(scene, dumped)
    problems = _same_model(dumped, together)
    if problems:
        return Outcome(tuple(passed), tuple(problems))
    passed.append("dump")
    exported = export(scene, workdir / "exported")
    shutil.move(workdir / "exported", workdir / "moved")
    problems = _same_model(workdir / "moved" / exported.name, together)
    if problems:
        return Outcome(tuple(passed), tuple(problems))
    passed.append("export")
    return Outcome(tuple(passed))


def _same_model(path: Path, expected: Any) -> list[str]:
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
