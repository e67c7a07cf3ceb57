"""Tests of ``mjcf_model.transforms.naming.repeated``."""

from __future__ import annotations

import re
from collections.abc import Callable, Collection
from pathlib import Path

import mujoco
import pytest
from hypothesis import given

from mjcf_model import Mujoco, compiled
from mjcf_model.bridge.compare import compiled_names
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.nodes.base import AnyElement
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.serializers.skins import inline_skin_files
from mjcf_model.strategies import models, names
from mjcf_model.transforms.composition.attaching import attach_all
from mjcf_model.transforms.naming.renaming import declared_names, prefixed, prefixed_declared
from mjcf_model.transforms.naming.repeated import MARK, PrefixPlan, RepeatedPrefixing
from tests.conftest import compiling_corpus, corpus_id
from tests.support.oracles import prefix_problems
from tests.support.plan_counting import PLANNED_AT_THE_SECOND_COPY

# -- Prefix plans: a prefixing traced once, then written with other prefixes and kept names. ---
#
# MuJoCo is the referee: a model written through a plan compiles to the original's
# arrays with every name prefixed, except the names the caller keeps. The flex's
# ``body`` list holds several names, so the plan writes the prefix word by word.


BODIES = """<body name="b1" pos="1 0 0"><joint name="j1" type="free"/><geom name="g1" size="0.1"/>
  </body><body name="b2" pos="0 1 0"><joint name="j2" type="free"/><geom name="g2" size="0.1"/>
  </body>"""
#: A flex whose body list names two bodies.
PAIR = f"""<mujoco><worldbody>{BODIES}</worldbody><deformable>
  <flex name="f" dim="1" body="b1 b2" element="0 1" vertex="0 0 0 0 0 0"/></deformable></mujoco>"""
#: A flex whose body list names the world body (declared nowhere) and one body.
TO_WORLD = f"""<mujoco><worldbody>{BODIES}</worldbody><deformable>
  <flex name="f" dim="1" body="world b2" element="0 1" vertex="0 0 0 0 0 0"/>
  </deformable></mujoco>"""


def every_reference(node: AnyElement, prefix: str) -> AnyElement:
    """Prefixing every name and every reference, declared or not (robosuite's way)."""
    return prefixed(node, prefix, undeclared=True)


def compiled_problems(text: str, new: AnyElement, kept: Collection[str] = ()) -> list[str]:
    """What keeps ``new`` from compiling to ``text``'s model with names prefixed by p_."""
    original = mujoco.MjModel.from_xml_string(text)
    return prefix_problems(original, mujoco.MjModel.from_xml_string(dumps(new)), "p_", kept)


def test_a_plan_writes_the_prefix_into_name_lists() -> None:
    """Written through its plan, the flex's body list is prefixed name by name."""
    model = loads(PAIR)
    plan = PrefixPlan.traced(model, prefixed)
    assert plan is not None
    assert compiled_problems(PAIR, plan.applied(model, "p_")) == []


def test_a_plan_refuses_a_prefix_xml_cannot_carry() -> None:
    """A prefix holding NUL is refused by name, as for any text."""
    plan = PrefixPlan.traced(loads(PAIR), prefixed)
    assert plan is not None
    bad = "p\x00"
    message = f"prefix {bad!r} holds U+0000, which XML cannot carry"
    with pytest.raises(MjcfValueError, match=f"^{re.escape(message)}$") as info:
        plan.applied(loads(PAIR), bad)
    assert isinstance(info.value, MjcfError)


@pytest.mark.parametrize("kept", [{"b1"}, {"b2"}, set()], ids=["first", "second", "none"])
def test_kept_names_in_a_list_stay_and_the_others_are_prefixed(kept: set[str]) -> None:
    """A by-name plan leaves kept names out of the prefixing, in name lists too."""
    model = loads(PAIR)
    plan = PrefixPlan.traced(model, every_reference, by_name=True)
    assert plan is not None
    new = plan.applied(model, "p_", keep=kept.__contains__)
    assert compiled_problems(PAIR, new, kept) == []


def test_a_list_whose_names_are_all_kept_is_shared() -> None:
    """When every name of the flex is kept, the flex is not rebuilt: the result shares it."""
    model = loads(PAIR)
    plan = PrefixPlan.traced(model, every_reference, by_name=True)
    assert plan is not None
    new = plan.applied(model, "p_", keep={"b1", "b2", "f"}.__contains__)
    assert compiled_problems(PAIR, new, {"b1", "b2", "f"}) == []
    assert new.deformable is not None and model.deformable is not None
    assert new.deformable.children[0] is model.deformable.children[0]


def test_a_list_naming_the_world_is_written_with_kept_names() -> None:
    """Where a plan stands for the prefixing, a list naming the world body still compiles.

    Only b2 is declared, so only it is prefixed; a caller keeping names uses the
    plan when there is one and ordinary prefixing when there is none.
    """
    model = loads(TO_WORLD)
    plan = PrefixPlan.traced(model, prefixed, by_name=True)

    def keep(name: str) -> bool:
        return name == "g1"

    if plan is None:
        new = prefixed(model, "p_", exclude=keep)
    else:
        new = plan.applied(model, "p_", keep=keep)
    assert compiled_problems(TO_WORLD, new, {"g1"}) == []


#: A flex whose body list names the world body first, then two bodies.
WORLD_FIRST = f"""<mujoco><worldbody>{BODIES}</worldbody><deformable>
  <flex name="f" dim="1" body="world b1 b2" element="0 1 1 2" vertex="0 0 0 0 0 0 0 0 0"/>
  </deformable></mujoco>"""


@pytest.mark.parametrize("kept", [{"b1"}, set()], ids=["b1", "none"])
def test_a_list_with_a_name_left_alone_has_a_by_name_plan(kept: set[str]) -> None:
    """Prefixing only declared names leaves world as it is: each prefix still starts a name.

    So a by-name plan stands for the prefixing, and writes kept names as they are.
    """
    model = loads(WORLD_FIRST)
    plan = PrefixPlan.traced(model, prefixed, by_name=True)
    assert plan is not None
    new = plan.applied(model, "p_", keep=kept.__contains__)
    assert compiled_problems(WORLD_FIRST, new, kept) == []


def test_repeated_prefixing_traces_at_the_second_copy_and_applies_after(
    plan_calls: dict[str, int],
) -> None:
    """Copy 1 is prefixed directly, copy 2 traces the plan, copies 3 and 4 only apply it.

    Every copy compiles to the original with its names prefixed (MuJoCo's names);
    a trace applies its plan once itself, to check it.
    """
    model = loads(PAIR)
    copies = RepeatedPrefixing(model, prefixed)
    seen = []
    for _ in range(4):
        assert compiled_problems(PAIR, copies.prefixed("p_")) == []
        seen.append(dict(plan_calls))
    assert seen == PLANNED_AT_THE_SECOND_COPY


def test_a_plan_prefixes_a_tree_of_generic_nodes() -> None:
    """Robosuite's layer holds generic nodes: the plan writes their attribute text alike."""
    import xml.etree.ElementTree as ET

    from mjcf_model.serializers import from_etree

    model = from_etree(ET.fromstring(PAIR), typed=False)
    plan = PrefixPlan.traced(model, prefixed)
    assert plan is not None
    assert compiled_problems(PAIR, plan.applied(model, "p_")) == []
    assert plan.applied(model, "p_") == prefixed(model, "p_")


def test_a_plan_writes_attributes_a_typed_node_keeps_as_extra_text() -> None:
    """A prefixer may write an attribute a newer MuJoCo reads (kept as ``extra``): so does the plan.

    The plan's contract is to reproduce its prefixer, here one that also prefixes
    the unknown ``futureref``.
    """
    from mjcf_model.nodes.base import get_attribute, with_attributes
    from mjcf_model.tree.traversal import map_elements

    def with_future(node: AnyElement, prefix: str) -> AnyElement:
        def visit(element: AnyElement, key: str | None, _: object) -> AnyElement:
            future = get_attribute(element, "futureref")
            return (
                element
                if future is None
                else with_attributes(element, {"futureref": prefix + str(future)})
            )

        return prefixed(map_elements(visit, node), prefix)

    model = loads('<mujoco><worldbody><geom name="g" size="1" futureref="x"/></worldbody></mujoco>')
    plan = PrefixPlan.traced(model, with_future)
    assert plan is not None
    copy = plan.applied(model, "p_")
    assert copy == with_future(model, "p_")
    geom = copy.children[0].children[0]
    assert (geom.name, get_attribute(geom, "futureref")) == ("p_g", "p_x")


def test_a_chain_nested_as_deep_as_a_long_cable_has_a_plan(plan_calls: dict[str, int]) -> None:
    """A cable of 150 segments nests 150 bodies: its copies are written through one plan.

    Each copy compiles to the chain with its names prefixed (MuJoCo's names), and
    the fourth copy is written by the plan traced at the second, not directly.
    """
    depth = 150
    opening = "".join(
        f'<body name="s{i}" pos="0 0 0.1"><joint/><geom size="0.01"/>' for i in range(depth)
    )
    chain = f"<mujoco><worldbody>{opening}{'</body>' * depth}</worldbody></mujoco>"
    copies = RepeatedPrefixing(loads(chain), prefixed)
    seen = []
    for _ in range(4):
        assert compiled_problems(chain, copies.prefixed("p_")) == []
        seen.append(dict(plan_calls))
    assert seen == PLANNED_AT_THE_SECOND_COPY


# -- Prefix plans: prefixing traced once and written for any prefix, checked by MuJoCo. --------


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
