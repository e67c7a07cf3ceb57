"""attach(): composing models, checked by compiling the result with MuJoCo."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import mujoco
import numpy as np
import pytest

from mjcf_model import Mujoco, compiled, find, get_attribute
from mjcf_model.bridge.compare import compiled_names
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.transforms.composition.attaching import attach, attach_all
from serializers import dumps, load, loads
from serializers.skins import inline_skin_files
from tests.conftest import compiling_corpus, corpus_id

CORPUS = compiling_corpus()
EMPTY = "<mujoco/>"


def _corpus_model(path: Path) -> Mujoco:
    return inline_skin_files(load(path, inline_includes=True), path.parent)


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_two_prefixed_copies_attached_into_a_world_compile(path: Path) -> None:
    """Two differently prefixed copies of a corpus model attached into one world compile."""
    model = _corpus_model(path)
    scene = attach(attach(loads(EMPTY), model, prefix="a_"), model, prefix="b_")
    one = compiled(model)
    both = compiled(scene)
    assert (both.nbody, both.ngeom, both.njnt, both.nu, both.nsensor, both.nq) == (
        2 * one.nbody - 1,
        2 * one.ngeom,
        2 * one.njnt,
        2 * one.nu,
        2 * one.nsensor,
        2 * one.nq,
    )
    for kind in ("geom", "joint", "actuator", "site"):
        kind = {"joint": "jnt"}.get(kind, kind)
        names = [n for n in compiled_names(one)[kind] if n]
        expected = Counter([f"a_{n}" for n in names] + [f"b_{n}" for n in names])
        assert Counter(n for n in compiled_names(both)[kind] if n) == expected


def test_collisions_are_errors_naming_the_names() -> None:
    """Attaching a model twice without a prefix reports the clashing names."""
    cube = loads(
        '<mujoco><worldbody><body name="cube"><geom size="1"/></body></worldbody></mujoco>'
    )
    with pytest.raises(MjcfValueError, match=r"body: cube.*prefix"):
        attach(attach(loads(EMPTY), cube), cube)


def test_attach_at_a_body_and_unknown_body() -> None:
    """``at`` puts the child's world inside a parent body; an unknown body lists the real ones."""
    table = loads(
        '<mujoco><worldbody><body name="table"><geom size="1"/></body></worldbody></mujoco>'
    )
    cup = loads(
        '<mujoco><worldbody><body name="cup"><geom size="0.1"/></body></worldbody></mujoco>'
    )
    scene = attach(table, cup, at="table", prefix="c_")
    compiled = mujoco.MjModel.from_xml_string(dumps(scene))
    assert compiled.body_parentid[compiled.body("c_cup").id] == compiled.body("table").id
    with pytest.raises(MjcfLookupError, match=r"no body named 'chair'.*\['table'\]"):
        attach(table, cup, at="chair")


def test_childs_main_defaults_stay_with_the_child() -> None:
    """The child's top-level defaults apply to the child only, the parent's to the parent."""
    parent = loads(
        '<mujoco><default><geom friction="0.5 0.1 0.1"/></default>'
        '<worldbody><geom name="floor" type="plane" size="1 1 1"/></worldbody></mujoco>'
    )
    child = loads(
        '<mujoco><default><geom friction="2 0.1 0.1"/><default class="soft"><geom solref="0.1 1"/>'
        '</default></default><worldbody><body name="b"><geom name="g" size="0.1"/>'
        '<geom name="s" class="soft" size="0.1"/></body></worldbody></mujoco>'
    )
    compiled = mujoco.MjModel.from_xml_string(dumps(attach(parent, child, prefix="c_")))
    assert compiled.geom("floor").friction[0] == 0.5
    assert compiled.geom("c_g").friction[0] == 2.0
    assert compiled.geom("c_s").friction[0] == 2.0
    assert compiled.geom("c_s").solref[0] == 0.1


def test_only_elements_the_childs_main_defaults_reach_name_its_class() -> None:
    """The child's class goes where its settings apply, and the values MuJoCo compiles follow."""
    parent = loads('<mujoco><default><material rgba="0 0 1 1"/></default></mujoco>')
    child = loads(
        '<mujoco><default><material rgba="1 0 0 1"/><motor gear="7"/><equality solref="0.3 1"/>'
        '</default><asset><texture name="t" builtin="flat" width="8" height="8"/>'
        '<material name="m" texture="t"/></asset><worldbody><geom name="g" size="0.1"/>'
        '<body name="b"><joint name="j"/><geom size="0.1"/></body></worldbody>'
        '<equality><joint joint1="j"/></equality><tendon><fixed name="f"><joint joint="j" '
        'coef="1"/></fixed></tendon><actuator><position joint="j"/></actuator></mujoco>'
    )
    composed = attach(parent, child, prefix="c_")

    def attribute(tag: str, which: str = "class", **match: str) -> object:
        return get_attribute(find(composed, tag, **match), which)

    assert attribute("material", name="c_m") == attribute("position") == "c_main"
    assert attribute("joint", joint1="c_j") == "c_main"  # the equality
    assert attribute("body", "childclass") == "c_main"
    assert (
        attribute("texture", name="c_t") is None
    )  # class on a texture: MuJoCo before 4.0 rejects it
    assert attribute("geom", name="c_g") is None  # nothing of c_main reaches these
    assert attribute("fixed", name="c_f") is None
    compiled = mujoco.MjModel.from_xml_string(dumps(composed))
    alone = mujoco.MjModel.from_xml_string(dumps(child))
    assert list(compiled.mat_rgba[0]) == list(alone.mat_rgba[0]) == [1, 0, 0, 1]
    assert compiled.actuator_gear[0][0] == alone.actuator_gear[0][0] == 7
    assert compiled.eq_solref[0][0] == alone.eq_solref[0][0] == 0.3


def test_equal_assets_are_kept_once_and_different_ones_clash() -> None:
    """A shared identical material is merged; a different one of the same name is an error."""
    parent = loads('<mujoco><asset><material name="m" rgba="1 0 0 1"/></asset></mujoco>')
    same = loads('<mujoco><asset><material name="m" rgba="1 0 0 1"/></asset></mujoco>')
    other = loads('<mujoco><asset><material name="m" rgba="0 1 0 1"/></asset></mujoco>')
    assert dumps(attach(parent, same)).count("<material") == 1
    with pytest.raises(MjcfValueError, match="material: m"):
        attach(parent, other)


def test_the_parent_keeps_its_compiler_and_the_child_is_converted() -> None:
    """The child's <compiler> is not copied: its values are converted into the parent's terms."""
    parent = loads('<mujoco><compiler angle="degree"/></mujoco>')
    child = loads(
        '<mujoco><compiler angle="radian"/><worldbody><body name="b" euler="0 0 1.5">'
        '<geom size="1"/></body></worldbody></mujoco>'
    )
    scene = attach(parent, child)
    assert [s for s in scene.elements if s.tag == "compiler"] == list(parent.elements)
    assert np.allclose(compiled(scene).body_quat[1], compiled(child).body_quat[1])
    assert attach(loads(EMPTY), child).compiler is None


def test_keyframes_are_spliced_by_position() -> None:
    """Child keys get the parent's initial qpos first; parent keys stay valid."""
    parent = loads(
        '<mujoco><worldbody><body><joint name="j0" type="slide" ref="0.25"/><geom size="0.1"/>'
        '</body></worldbody><actuator><motor joint="j0" name="m0"/></actuator>'
        '<keyframe><key name="p" qpos="0.5"/></keyframe></mujoco>'
    )
    child = loads(
        '<mujoco><worldbody><body><joint name="h" type="hinge"/><geom size="0.1"/></body>'
        '</worldbody><actuator><motor joint="h" name="m"/></actuator>'
        '<keyframe><key name="k" qpos="0.7" ctrl="3"/></keyframe></mujoco>'
    )
    compiled = mujoco.MjModel.from_xml_string(dumps(attach(parent, child, prefix="c_")))
    assert np.allclose(compiled.key("p").qpos, [0.5, 0.0])
    assert np.allclose(compiled.key("c_k").qpos, [0.25, 0.7])
    assert np.allclose(compiled.key("c_k").ctrl, [0.0, 3.0])


def test_inputs_are_unchanged_and_includes_refused() -> None:
    """Attach returns a new model; kept includes cannot be attached."""
    parent = loads('<mujoco><worldbody><geom size="1"/></worldbody></mujoco>')
    text = dumps(parent)
    attach(parent, loads('<mujoco><worldbody><body name="b"/></worldbody></mujoco>'))
    assert dumps(parent) == text
    with pytest.raises(MjcfValueError, match="inline_includes"):
        attach(parent, loads('<mujoco><include file="x.xml"/></mujoco>'))


def test_parent_keyframes_stay_when_the_child_has_none() -> None:
    """A child without keys leaves the parent's keys as they were."""
    parent = loads(
        '<mujoco><worldbody><body><joint type="slide"/><geom size="0.1"/></body></worldbody>'
        '<keyframe><key name="p" qpos="0.5"/></keyframe></mujoco>'
    )
    child = loads(
        '<mujoco><worldbody><body name="c"><geom size="0.1"/></body></worldbody></mujoco>'
    )
    compiled = mujoco.MjModel.from_xml_string(dumps(attach(parent, child)))
    assert compiled.nkey == 1 and np.allclose(compiled.key("p").qpos, [0.5])


def test_attach_all_equals_attaching_one_by_one() -> None:
    """``attach_all`` equals repeated ``attach``, and converts each child's compiler on its own."""
    cup = loads(
        '<mujoco><default><geom rgba="1 0 0 1"/></default><asset><material name="m"/></asset>'
        '<worldbody><body name="cup"><geom size="0.1" material="m"/></body></worldbody></mujoco>'
    )
    pairs = [(cup, f"c{i}_") for i in range(4)]
    one_by_one = loads(EMPTY)
    for child, prefix in pairs:
        one_by_one = attach(one_by_one, child, prefix=prefix)
    assert attach_all(loads(EMPTY), pairs) == one_by_one
    body = '<worldbody><body name="b" euler="0 0 1"><geom size="1"/></body></worldbody>'
    radians = loads(f'<mujoco><compiler angle="radian"/>{body}</mujoco>')
    degrees = loads(f'<mujoco><compiler angle="degree"/>{body}</mujoco>')
    scene = compiled(attach_all(loads(EMPTY), [(radians, "r_"), (degrees, "d_")]))
    assert np.allclose(
        scene.body_quat[1:], [compiled(radians).body_quat[1], compiled(degrees).body_quat[1]]
    )
