"""Tests of ``mjcf_model.bridge.numbering``: MuJoCo's row of each element, by its path."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest
from hypothesis import HealthCheck, assume, given, settings

from mjcf_model import compiled, load
from mjcf_model.bridge.numbering import numbering
from mjcf_model.nodes.base import get_attribute
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers.locations import element_at
from mjcf_model.strategies import models
from mjcf_model.tree.traversal import keyed_walk
from tests.conftest import PER_CLASS, compiling_corpus, corpus_id

#: Each numbered kind and the count of its rows in a compiled model.
_COUNTS = {
    "body": "nbody",
    "geom": "ngeom",
    "joint": "njnt",
    "site": "nsite",
    "camera": "ncam",
    "light": "nlight",
    "key": "nkey",
    "material": "nmat",
    "actuator": "nu",
    "tendon": "ntendon",
    "sensor": "nsensor",
    "equality": "neq",
}


def _check(model: Mujoco) -> None:
    """Every row of every kind has one element, of that kind, named as MuJoCo names the row."""
    physics = compiled(model)
    rows = numbering(model)
    written_keys = sum(1 for _, key, _ in keyed_walk(model) if key == "keyframe/key")
    for kind, count in _COUNTS.items():
        first = 1 if kind == "body" else 0  # the world body is no element
        kind_id = getattr(mujoco.mjtObj, f"mjOBJ_{kind.upper()}")
        # <size nkey> adds keys after the written ones, elements of none
        total = written_keys if kind == "key" else getattr(physics, count)
        for row in range(first, total):
            path = rows.path_of(kind, row)
            assert path is not None, (kind, row)
            assert rows.rows[path] == row
            found = element_at(model, path)
            assert found is not None, (kind, row, path)
            element = found[0]
            name = get_attribute(element, "name")
            if name:
                assert mujoco.mj_id2name(physics, kind_id, row) == name, (kind, row)
            elif kind != "material":
                assert not mujoco.mj_id2name(physics, kind_id, row), (kind, row)


@pytest.mark.parametrize("path", compiling_corpus()[::10], ids=corpus_id)
def test_every_row_of_a_corpus_model_is_its_element(path: Path) -> None:
    """Corpus files, their includes inlined (an included file's elements are in the tree)."""
    _check(load(path, inline_includes=True))


@settings(PER_CLASS, suppress_health_check=[HealthCheck.too_slow])
@given(model=models())
def test_every_row_of_a_drawn_model_is_its_element(model: Mujoco) -> None:
    """Drawn models (frames, default classes, every section): no row without its element.

    But for models that copy elements (``<replicate>``) or pull in others (``<attach>``),
    whose copies have no element of their own.
    """
    assume(not any(key in ("body/replicate", "body/attach") for _, key, _ in keyed_walk(model)))
    _check(model)
