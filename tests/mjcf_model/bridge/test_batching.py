"""``batched`` stacks, one row per variant, exactly the fields the variants change.

The referee is MuJoCo compiling each variant in full: row ``i`` of every returned array
is that field of ``compiled(variants[i])``, and every field not returned is the same in
every compiled variant (and the base).
"""

from __future__ import annotations

import warnings
from functools import reduce
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from mjcf_model import (
    MjcfRecompiledWarning,
    MjcfValueError,
    batched,
    compiled,
    map_elements,
    with_attributes,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.nodes.base import AnyElement
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers import load, loads
from mjcf_model.strategies import models
from tests.conftest import MUJOCO_VERSION, PER_CLASS, compiling_corpus, corpus_id
from tests.mjcf_model.bridge.test_patching import variant


def _field(model: Any, name: str) -> Any:
    return reduce(getattr, name.split("."), model)


def _check_batch(base: Mujoco, variants: list[Mujoco]) -> dict[str, Any]:
    """``batched`` against every variant compiled in full; the arrays it returned."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MjcfRecompiledWarning)
        arrays = batched(base, variants)
    expected = [compiled(v) for v in variants]
    for name, rows in arrays.items():
        assert rows.shape[0] == len(variants), name
        for index, model in enumerate(expected):
            want = np.asarray(_field(model, name))
            assert np.array_equal(rows[index], want, equal_nan=True), (name, index)
    for model in [*expected, compiled(base)]:
        differing = set(model_differences(model, expected[0]))
        assert differing <= arrays.keys(), differing - arrays.keys()
    return arrays


@settings(PER_CLASS, suppress_health_check=[HealthCheck.too_slow])
@given(model=models(), seed=st.integers(0, 2**32 - 1))
def test_batched_drawn_models_are_the_compiled_variants_row_by_row(
    model: Mujoco, seed: int
) -> None:
    """Any drawn model, three variants of every mapped value: rows are MuJoCo's arrays."""
    _check_batch(model, [variant(model, seed + i)[0] for i in range(3)])


@pytest.mark.parametrize("path", compiling_corpus()[::7], ids=corpus_id)
def test_batched_corpus_variants_are_the_compiled_variants_row_by_row(path: Path) -> None:
    """Corpus models, three variants each (their classes' values changed too)."""
    base = load(path, inline_includes=True)
    made = [variant(base, i) for i in range(3)]
    arrays = _check_batch(base, [after for after, _ in made])
    assert bool(arrays) == (made[0][1] > 0)  # a model with mapped values gets rows


def test_unchanged_variants_give_no_arrays_and_a_changed_one_its_rows() -> None:
    """The base itself changes nothing; one joint damped differently gives one field."""
    base = loads(
        '<mujoco><worldbody><body><joint name="j"/><geom size="0.1"/></body></worldbody></mujoco>'
    )
    assert batched(base, [base, base]) == {}
    assert batched(base, []) == {}

    def damped(element: AnyElement, key: str | None, ancestors: Any) -> AnyElement:
        return with_attributes(element, {"damping": 3.0}) if key == "body/joint" else element

    arrays = batched(base, [base, map_elements(damped, base)])
    assert list(arrays) == ["dof_damping"]
    assert arrays["dof_damping"].tolist() == [[0.0], [3.0]]


def test_a_variant_that_changes_the_structure_is_refused_by_name() -> None:
    """A variant with one more geom cannot share a batch: the error names variant and count."""
    base = loads('<mujoco><worldbody><geom size="0.1"/></worldbody></mujoco>')
    more = loads('<mujoco><worldbody><geom size="0.1"/><geom size="0.2"/></worldbody></mujoco>')
    with (
        warnings.catch_warnings(),
        pytest.raises(MjcfValueError, match=r"variant 1 changes ngeom from 1 to 2"),
    ):
        warnings.simplefilter("ignore", MjcfRecompiledWarning)
        batched(base, [base, more])


def test_option_values_batch_under_their_struct_names() -> None:
    """A changed ``<option>`` value is compiled and batched as ``opt.<field>``."""
    base = loads(
        '<mujoco><option timestep="0.002"/><worldbody><geom size="0.1"/></worldbody></mujoco>'
    )
    slower = loads(
        '<mujoco><option timestep="0.004"/><worldbody><geom size="0.1"/></worldbody></mujoco>'
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MjcfRecompiledWarning)
        arrays = batched(base, [base, slower])
    assert arrays["opt.timestep"].tolist() == [0.002, 0.004]


@pytest.mark.skipif(
    MUJOCO_VERSION < (4, 0), reason=f"MuJoCo {mujoco.__version__} has no mujoco.batch (4.0 on)"
)
@pytest.mark.parametrize("path", compiling_corpus()[3::17], ids=corpus_id)
def test_worlds_given_the_batched_rows_step_as_each_compiled_variant_alone(path: Path) -> None:
    """The variants guide's loop: MuJoCo's ``Batch`` of the base, each batched field expanded.

    After ``set_const`` and 20 steps, every world's state is the state its variant,
    compiled in full and stepped alone, reaches: bit for bit. Every batched field is a
    field ``Batch`` expands, but the compiler's statistics (``stat.*``, ``vis.*``), which
    the worlds of a ``Batch`` share: the variant stepped alone is given the base's.
    """
    from mujoco.batch import MODEL_FIELDS, Batch

    base = load(path, inline_includes=True)
    variants = [variant(base, seed)[0] for seed in range(3)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MjcfRecompiledWarning)
        arrays = batched(base, variants)
    shared = {name for name in arrays if name not in MODEL_FIELDS}
    assert all(name.startswith(("stat.", "vis.")) for name in shared), shared
    base_model = compiled(base)
    worlds = Batch(base_model, nsim=len(variants), nthread=1)
    for name, rows in arrays.items():
        if name not in shared:
            worlds.expand(name)[:] = rows
    worlds.set_const()
    qpos, qvel = worlds.bind("qpos"), worlds.bind("qvel")
    worlds.step(nstep=20)
    for index, after in enumerate(variants):
        alone = compiled(after)
        for name in shared:
            struct, field = name.split(".")
            setattr(getattr(alone, struct), field, _field(base_model, name))
        data = mujoco.MjData(alone)
        mujoco.mj_step(alone, data, nstep=20)
        assert np.array_equal(qpos[index], data.qpos), (path.name, index)
        assert np.array_equal(qvel[index], data.qvel), (path.name, index)
