"""Prefix plans: prefixing traced once and written for any prefix, checked by MuJoCo."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import pytest
from hypothesis import given

from mjcf_model import Mujoco, compiled
from mjcf_model.bridge.compare import compiled_names
from mjcf_model.nodes.base import AnyElement
from mjcf_model.strategies import models, names
from mjcf_model.transforms.composition.attaching import attach_all
from mjcf_model.transforms.naming.renaming import declared_names, prefixed, prefixed_declared
from mjcf_model.transforms.naming.repeated import MARK, PrefixPlan
from serializers import dumps, load, loads
from serializers.skins import inline_skin_files
from tests.conftest import compiling_corpus, corpus_id
from tests.support.oracles import prefix_problems

CORPUS = compiling_corpus()


def _declared_prefixer(model: Mujoco) -> Callable[[AnyElement, str], AnyElement]:
    """Prefixing as attach_all does it: every name the model declares."""
    declared = declared_names(model)
    return lambda node, prefix: prefixed_declared(node, prefix, declared)


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_planned_prefix_of_a_corpus_model_compiles_with_every_name_prefixed(path: Path) -> None:
    """A corpus model prefixed through its plan compiles to the same arrays, every name prefixed."""
    model = inline_skin_files(load(path, inline_includes=True))
    plan = PrefixPlan.traced(model, _declared_prefixer(model))
    assert plan is not None
    original = compiled(model)
    for prefix in ("a_", "second/"):
        assert prefix_problems(original, compiled(plan.applied(model, prefix)), prefix) == []


@given(models(), names())
def test_planned_prefix_of_a_drawn_model_compiles_with_every_name_prefixed(
    model: Mujoco, prefix: str
) -> None:
    """On drawn models too, the plan's prefixing changes every name and nothing else."""
    plan = PrefixPlan.traced(model, prefixed)
    assert plan is not None
    original = mujoco.MjModel.from_xml_string(dumps(model))
    changed = mujoco.MjModel.from_xml_string(dumps(plan.applied(model, prefix)))
    assert prefix_problems(original, changed, prefix) == []


def test_names_kept_by_name_stay_as_written() -> None:
    """``keep`` leaves the names it names, in single and in list references, MuJoCo agrees."""
    model = loads(
        '<mujoco><worldbody><body name="p_arm"><geom name="g" size="1"/><site name="s"/>'
        '<site name="t" pos="0 1 0"/></body></worldbody>'
        '<tendon><spatial name="rope"><site site="s"/><site site="t"/></spatial></tendon>'
        '<contact><exclude body1="p_arm" body2="world"/></contact></mujoco>'
    )
    plan = PrefixPlan.traced(
        model, lambda node, mark: prefixed(node, mark, undeclared=True), by_name=True
    )
    assert plan is not None
    changed = compiled(plan.applied(model, "p_", keep=lambda name: name in ("p_arm", "t", "world")))
    assert compiled_names(changed)["body"] == ["world", "p_arm"]
    assert compiled_names(changed)["site"] == ["p_s", "t"]
    assert compiled_names(changed)["geom"] == ["p_g"]


def test_a_model_whose_names_hold_the_marker_is_not_planned_but_attaches() -> None:
    """A name holding the marker has no plan; attaching copies of it still prefixes each name."""
    cup = loads(
        f'<mujoco><worldbody><body name="cup{MARK}"><joint name="j{MARK}"/><geom size="1"/>'
        f'</body></worldbody><actuator><motor name="m" joint="j{MARK}"/></actuator></mujoco>'
    )
    assert PrefixPlan.traced(cup, _declared_prefixer(cup)) is None
    scene = compiled(attach_all(loads("<mujoco/>"), [(cup, "a_"), (cup, "b_")]))
    assert compiled_names(scene)["body"] == ["world", f"a_cup{MARK}", f"b_cup{MARK}"]
    assert compiled_names(scene)["jnt"] == [f"a_j{MARK}", f"b_j{MARK}"]


def test_attaching_many_copies_compiles_each_prefixed() -> None:
    """Fifty planned copies of one model compile to fifty prefixed bodies, joints, materials."""
    cup = loads(
        '<mujoco><asset><material name="glaze"/></asset><worldbody><body name="cup">'
        '<freejoint name="free"/><geom size="0.1" material="glaze"/></body></worldbody></mujoco>'
    )
    scene = compiled(attach_all(loads("<mujoco/>"), [(cup, f"c{i}_") for i in range(50)]))
    assert compiled_names(scene)["body"] == ["world", *(f"c{i}_cup" for i in range(50))]
    assert compiled_names(scene)["jnt"] == [f"c{i}_free" for i in range(50)]
    assert compiled_names(scene)["mat"] == [f"c{i}_glaze" for i in range(50)]
