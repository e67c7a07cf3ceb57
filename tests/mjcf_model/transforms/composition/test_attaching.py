"""Tests of ``mjcf_model.transforms.composition.attaching``."""

from __future__ import annotations

import os
from collections import Counter
from pathlib import Path

import mujoco
import numpy as np
import pytest

from mjcf_model import Mujoco, compiled, find, get_attribute
from mjcf_model.bridge.compare import compiled_names
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.serializers.skins import inline_skin_files
from mjcf_model.transforms.composition.attaching import attach, attach_all, attach_in_frame
from mjcf_model.tree.queries import find_all
from tests.conftest import FIXTURES, compiling_corpus, corpus_id
from tests.support.composition_oracle import PlacedPart, composition_problems

# -- attach(): composing models, checked by compiling the result with MuJoCo. ------------------


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


# -- ``attach_all`` checks every part for free joints or mocap bodies inside a body. -----------
#
# ``attach_all`` is documented as the same as calling :func:`mjcf_model.attach`
# for each child; with keyframes, ``attach`` refuses a part with mocap bodies
# inside a body (MuJoCo allows those only at the top level). ``attach_all`` once
# worked out the attach pose for its first part only, so a later part with a mocap
# body was placed inside the body and MuJoCo rejected the result.


PARENT_ALL_MOCAP_IN_BODY = (
    '<mujoco><worldbody><body name="mount"><joint/><geom size=".1"/></body></worldbody>'
    '<keyframe><key qpos="0.3"/></keyframe></mujoco>'
)
ARM = '<mujoco><worldbody><body><joint/><geom size=".1"/></body></worldbody></mujoco>'
TARGET = (
    '<mujoco><worldbody><body name="t" mocap="true"><geom size=".1" contype="0" '
    'conaffinity="0"/></body></worldbody></mujoco>'
)


def test_attach_refuses_a_mocap_part_after_another_part_at_a_body() -> None:
    """Attached one by one, the second (mocap) part at ``mount`` is refused, naming the body."""
    scene = attach(loads(PARENT_ALL_MOCAP_IN_BODY), loads(ARM), at="mount", prefix="a_")
    with pytest.raises(MjcfValueError, match=r"inside the <body> 'mount'"):
        attach(scene, loads(TARGET), at="mount", prefix="t_")


def test_attach_all_refuses_a_mocap_part_after_another_part_at_a_body() -> None:
    """In one ``attach_all`` the same mocap part is refused too (fails: it goes in the body)."""
    with pytest.raises(MjcfValueError, match=r"inside the <body> 'mount'"):
        attach_all(
            loads(PARENT_ALL_MOCAP_IN_BODY), [(loads(ARM), "a_"), (loads(TARGET), "t_")], at="mount"
        )


# -- A child's file paths are rewritten to name its files from the parent's folder, relatively.
#
# The scene keeps the parent's folder and ``<compiler>``, so a mesh the child
# reads from its own ``meshdir`` is written as the path from the parent's
# folder to that file: relative, so the scene's folder tree can be moved as a
# whole (:func:`mjcf_model.files.provenance.relocated`). MuJoCo compiling the
# child from its own file is the referee for what the mesh holds.


SCENE_DIR = FIXTURES / "attachments" / "nested"
GRIPPER = SCENE_DIR / "arm" / "gripper" / "gripper.xml"


def test_a_childs_mesh_is_named_relative_to_the_parents_folder() -> None:
    """The child's mesh file is written as the relative path from the parent's folder."""
    parent = loads("<mujoco/>", base_dir=SCENE_DIR)
    scene = attach(parent, load(GRIPPER), prefix="g_")
    (mesh,) = find_all(scene, "mesh")
    mesh_file = GRIPPER.parent / "meshes" / "pad.obj"
    assert get_attribute(mesh, "file") == os.path.relpath(mesh_file, SCENE_DIR)
    alone = mujoco.MjModel.from_xml_path(str(GRIPPER))
    assert compiled(scene).nmeshvert == alone.nmeshvert


# -- attach_in_frame: the child's world goes inside the named frame, its names kept without a
#    prefix.
#
# The frame is looked up among the parent's frames only, so a body of the same
# name (MuJoCo keeps bodies and frames in separate namespaces) does not make the
# name ambiguous. MuJoCo compiling each part alone is the referee
# (tests/support/composition_oracle.py): the child's objects hold their own values,
# placed at the frame.


CHILD = """<mujoco>
  <worldbody><body name="cup" pos="0.1 0 0"><joint name="tilt"/><geom size=".1"/></body></worldbody>
</mujoco>
"""
PARENT_IN_FRAME_ARGUMENTS = """<mujoco>
  <worldbody>
    <body name="here" pos="1 0 0"><geom size=".2"/></body>
    <frame name="here" pos="0 2 0"/>
  </worldbody>
</mujoco>
"""


def test_without_a_prefix_the_childs_names_are_kept() -> None:
    """With no ``prefix`` given, the child's bodies and joints keep their own names."""
    scene = compiled(attach_in_frame(loads(PARENT_IN_FRAME_ARGUMENTS), loads(CHILD), frame="here"))
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string(PARENT_IN_FRAME_ARGUMENTS)),
        PlacedPart(mujoco.MjModel.from_xml_string(CHILD), "", pos=(0.0, 2.0, 0.0)),
    ]
    assert composition_problems(parts, scene) == []
    assert scene.body("cup").name == "cup" and scene.joint("tilt").name == "tilt"


def test_the_frame_is_found_when_a_body_has_its_name() -> None:
    """The frame named ``frame`` is used even when a body has that name: the child goes there."""
    scene = compiled(
        attach_in_frame(loads(PARENT_IN_FRAME_ARGUMENTS), loads(CHILD), frame="here", prefix="c_")
    )
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string(PARENT_IN_FRAME_ARGUMENTS)),
        PlacedPart(mujoco.MjModel.from_xml_string(CHILD), "c_", pos=(0.0, 2.0, 0.0)),
    ]
    assert composition_problems(parts, scene) == []
    assert scene.body_parentid[scene.body("c_cup").id] == 0


# -- Names across the children of one attach_all: later children meet the earlier ones' names. -
#
# An asset that two children both declare as the same element is kept once (the
# module docstring of mjcf_model/transforms/composition/attaching.py); any other
# name a later child shares with an earlier one is a clash, as if it were the
# parent's. MuJoCo compiling each part alone says what the scene's objects hold.


CUP = """<mujoco>
  <asset><material name="red" rgba="1 0 0 1"/></asset>
  <worldbody><body name="cup"><geom name="cup_geom" size=".1" material="red"/></body></worldbody>
</mujoco>
"""
BOWL = """<mujoco>
  <asset><material name="red" rgba="1 0 0 1"/></asset>
  <worldbody><body name="bowl"><geom name="bowl_geom" size=".2" material="red"/></body></worldbody>
</mujoco>
"""


def test_an_asset_two_unprefixed_children_share_is_kept_once() -> None:
    """Two children declaring the same material: one material, used by both children's geoms."""
    scene = compiled(attach_all(Mujoco(), [(loads(CUP), ""), (loads(BOWL), "")]))
    alone = mujoco.MjModel.from_xml_string(CUP)
    assert scene.nmat == 1
    assert scene.geom("cup_geom").matid == scene.geom("bowl_geom").matid == scene.material("red").id
    np.testing.assert_allclose(scene.material("red").rgba, alone.material("red").rgba)


def test_a_child_attached_twice_with_one_prefix_clashes() -> None:
    """The same child twice under one prefix: its body names clash; use another prefix."""
    with pytest.raises(MjcfValueError, match=r"already has \(body: a_cup.*attach it with a prefix"):
        attach_all(Mujoco(), [(loads(CUP), "a_"), (loads(CUP), "a_")])


# -- attach refuses a parent or a child holding elements whose contents are not in the tree. ---
#
# An ``<include>`` names another file and a ``<composite>`` (removed in MuJoCo 4.0)
# makes elements that are nowhere in the tree, so attaching either model could
# give a scene MuJoCo reads differently. The error says which element is in the
# way, that the action was attaching, and what to do instead
# (``refuse_opaque`` in mjcf_model/tree/traversal.py).


PLAIN = '<mujoco><worldbody><body name="cup"><geom size=".1"/></body></worldbody></mujoco>'
INCLUDING = '<mujoco><include file="parts.xml"/></mujoco>'
COMPOSITE = (
    '<mujoco><worldbody><body name="cloth"><composite type="grid" count="2 2 1"/></body>'
    "</worldbody></mujoco>"
)
INCLUDE_REFUSED = r"cannot attach a model with <include> elements: .* inline_includes=True"
COMPOSITE_REFUSED = r"cannot attach a model with <composite> elements: .* <replicate> or <flexcomp>"


def test_a_parent_with_an_include_is_refused() -> None:
    """A parent with an ``<include>`` is refused, telling the user to inline includes."""
    with pytest.raises(MjcfValueError, match=INCLUDE_REFUSED):
        attach(loads(INCLUDING), loads(PLAIN), prefix="c_")


def test_a_parent_with_a_composite_is_refused() -> None:
    """A parent with a ``<composite>`` is refused, telling the user what to write instead."""
    with pytest.raises(MjcfValueError, match=COMPOSITE_REFUSED):
        attach(loads(COMPOSITE), loads(PLAIN), prefix="c_")


def test_a_child_with_an_include_is_refused() -> None:
    """A child with an ``<include>`` is refused, telling the user to inline includes."""
    with pytest.raises(MjcfValueError, match=INCLUDE_REFUSED):
        attach(loads(PLAIN), loads(INCLUDING), prefix="c_")


def test_a_child_with_a_composite_is_refused() -> None:
    """A child with a ``<composite>`` is refused, telling the user what to write instead."""
    with pytest.raises(MjcfValueError, match=COMPOSITE_REFUSED):
        attach(loads(PLAIN), loads(COMPOSITE), prefix="c_")


# -- An unnamed asset ``<model>`` two children share is read from the parent's folder. ---------
#
# Two children attached without a prefix that both declare the same unnamed
# ``<model file="sub.xml"/>`` share it (kept once). Its name is its file's root
# ``model`` attribute; the composer once read that file from the working folder
# instead of the parent's, where the child's paths are rebased, and failed elsewhere.


FOLDER = FIXTURES / "attach_shared_model_asset"


def test_a_shared_unnamed_model_asset_does_not_depend_on_the_working_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Attaching two children sharing an unnamed ``<model>`` asset works from any working folder."""
    monkeypatch.chdir(tmp_path)
    parent = loads("<mujoco/>", base_dir=FOLDER)
    children = [(load(FOLDER / "parts" / "a.xml"), ""), (load(FOLDER / "parts" / "b.xml"), "")]
    scene = attach_all(parent, children)
    assert len(find_all(scene, "model")) == 1
    together = compiled(scene)
    alone = [mujoco.MjModel.from_xml_path(str(FOLDER / "parts" / f)) for f in ("a.xml", "b.xml")]
    assert together.nbody == sum(m.nbody for m in alone) - 1
    assert together.body("a").id > 0 and together.body("b").id > 0
