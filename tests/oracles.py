"""Checks shared by the transform tests: MuJoCo decides whether a transform did its job."""

from __future__ import annotations

from collections.abc import Collection
from typing import Any

from mjcf_model.compare import NAME_FIELDS, compiled_names, model_differences, model_fields

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
