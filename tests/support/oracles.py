"""Checks shared by the transform tests: MuJoCo decides whether a transform did its job."""

from __future__ import annotations

from collections.abc import Collection
from pathlib import Path
from typing import Any

import mujoco

from mjcf_model import (
    Mujoco,
    prefixed,
)
from mjcf_model.bridge.compare import (
    NAME_FIELDS,
    compile_text_beside,
    compiled_names,
    model_differences,
    model_fields,
)
from mjcf_model.serializers import dumps, loads
from tests.conftest import MUJOCO_VERSION

#: Every field that a renaming may change.
RENAMING_FIELDS = NAME_FIELDS | {f for f in model_fields() if f.startswith("name_")}


def prefix_problems(
    original: Any, changed: Any, prefix: str, kept: Collection[str] = ()
) -> list[str]:
    """What keeps ``changed`` from being ``original`` with every name prefixed.

    Every array must be identical apart from the name table; every non-empty
    name must be ``prefix + name`` except the world body and the names in ``kept``.
    """
    problems = [f"field {f}" for f in model_differences(original, changed, ignore=RENAMING_FIELDS)]
    before, after = compiled_names(original), compiled_names(changed)
    for kind, names in before.items():
        for old, new in zip(names, after[kind], strict=True):
            expected = (
                old if not old or old in kept or (kind, old) == ("body", "world") else prefix + old
            )
            if new != expected:
                problems.append(f"{kind} {old!r} became {new!r}, expected {expected!r}")
    return problems


def scaled_problems(
    original: Any, changed: Any, factor: float, fields: Collection[str], rtol: float = 1e-9
) -> list[str]:
    """The ``fields`` of ``changed`` that are not exactly ``factor`` times the original's."""
    import numpy as np

    problems = []
    for field in fields:
        before, after = np.asarray(getattr(original, field)), np.asarray(getattr(changed, field))
        if before.shape != after.shape or not np.allclose(
            after, before * factor, rtol=rtol, atol=0
        ):
            problems.append(field)
    return problems


def friction_problems(original: Any, changed: Any, factor: float) -> list[str]:
    """The frictions of ``changed`` whose sliding values differ or whose others are not scaled.

    A geom's torsional and rolling coefficients, and a pair's spin and rolling ones,
    must be the original's times ``factor``; the sliding (tangential) ones unchanged.
    """
    import numpy as np

    problems = []
    for field, start in (("geom_friction", 1), ("pair_friction", 2)):
        before, after = np.asarray(getattr(original, field)), np.asarray(getattr(changed, field))
        if before.shape != after.shape or not np.array_equal(after[:, :start], before[:, :start]):
            problems.append(f"{field} sliding")
        elif not np.allclose(after[:, start:], factor * before[:, start:], rtol=1e-9, atol=0):
            problems.append(f"{field} torsional and rolling")
    return problems


#: Whether MuJoCo's principal inertias of a mesh body are comparable one by one after
#: scaling. Before 4.0 they come out permuted or perturbed in the eighth digit for
#: nearly symmetric meshes (measured on MuJoCo 3.9.0, 13 corpus models, with equal
#: traces), so on 3.9 the trace of each body's inertia is compared instead.
INERTIA_COMPARABLE = MUJOCO_VERSION >= (4, 0)


def mass_problems(original: Any, changed: Any, mass: float, inertia: float) -> list[str]:
    """The body masses and inertias of ``changed`` that are not the original's times these."""
    import numpy as np

    problems = scaled_problems(original, changed, mass, ["body_mass"])
    if INERTIA_COMPARABLE:
        return problems + scaled_problems(original, changed, inertia, ["body_inertia"])
    traces = np.sum(changed.body_inertia, axis=1), inertia * np.sum(original.body_inertia, axis=1)
    return problems + ([] if np.allclose(*traces, rtol=1e-9, atol=0) else ["inertia traces"])


def trees_close(left: Any, right: Any, rel: float = 1e-9) -> bool:
    """Whether two node trees are equal, numbers compared within ``rel``."""
    import math

    from mjcf_model.nodes.base import Comment, attribute_items

    if type(left) is not type(right):
        return False
    if isinstance(left, Comment):
        return bool(left == right)
    items_left, items_right = dict(attribute_items(left)), dict(attribute_items(right))
    if items_left.keys() != items_right.keys() or left.tag != right.tag:
        return False
    for key, a in items_left.items():
        b = items_right[key]
        if isinstance(a, tuple) and isinstance(b, tuple) and len(a) == len(b):
            if not all(
                math.isclose(x, y, rel_tol=rel, abs_tol=1e-12) for x, y in zip(a, b, strict=True)
            ):
                return False
        elif isinstance(a, float) and isinstance(b, float):
            if not math.isclose(a, b, rel_tol=rel, abs_tol=1e-12):
                return False
        elif a != b:
            return False
    return len(left.children) == len(right.children) and all(
        trees_close(x, y, rel) for x, y in zip(left.children, right.children, strict=True)
    )


def _compiled(text: str) -> Any:
    return mujoco.MjModel.from_xml_string(text)


def _round_trips_like_mujoco(text: str) -> None:
    """MuJoCo compiles ``text``; we load it, and our text compiles to the same model."""
    before = _compiled(text)
    written = dumps(loads(text))
    assert model_differences(before, _compiled(written)) == []
    assert loads(written) == loads(text)


def compile_beside(model: Any, path: Path) -> Any:
    """Compile a model's text as if it were the file ``path``."""
    return compile_text_beside(dumps(model), path)


def prefixed_problems(model: Mujoco, path: Path, prefix: str = "p_") -> list[str]:
    """What keeps the prefixed ``model`` from compiling to the original with names prefixed."""
    original = compile_beside(model, path)
    changed = compile_beside(prefixed(model, prefix), path)
    return prefix_problems(original, changed, prefix)


def written(tmp_path: Path, text: str, name: str = "model.xml") -> Path:
    """Write ``text`` to ``tmp_path / name`` and return the path."""
    path = tmp_path / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path
