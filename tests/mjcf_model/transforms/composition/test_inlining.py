"""Tests of ``mjcf_model.transforms.composition.inlining``."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from mjcf_model import compiled, inlined_attachments, prefixed, scaled
from mjcf_model.bridge.compare import compiled_names, model_differences, path_fields
from mjcf_model.errors import (
    MjcfCompileError,
    MjcfIncludeCycleError,
    MjcfLookupError,
    MjcfValueError,
)
from mjcf_model.nodes.base import Comment, get_attribute
from mjcf_model.nodes.body import Worldbody
from mjcf_model.nodes.compiler import Compiler
from mjcf_model.nodes.keyframe import Keyframe
from mjcf_model.serializers import dump, load, loads
from mjcf_model.tree.queries import find, find_all, parent_of
from mjcf_model.tree.traversal import walk
from tests.conftest import FIXTURES, MUJOCO_VERSION, compiling_corpus, corpus_id
from tests.support.attach_files import written
from tests.support.oracles import prefix_problems, scaled_problems

# -- Expanding ``<attach>``: the expanded model compiles to MuJoCo's own ``<attach>`` result. --
#
# The fixtures in ``tests/fixtures/attachments`` each hold a scene and the models it
# attaches, in folders of their own with their own ``<compiler>``. For each, MuJoCo
# compiles the original (its ``<attach>``) and the expansion; every array must be
# equal (the recorded file paths aside). The expansion is then dumped elsewhere,
# prefixed and scaled, and MuJoCo referees those too.


ATTACHMENTS = FIXTURES / "attachments"

#: Scenes MuJoCo 3.9 and 4.0 both compile, with the corpus models that use ``<attach>``.
SCENES = [
    ATTACHMENTS / "robot" / "scene.xml",
    ATTACHMENTS / "nested" / "scene.xml",
    ATTACHMENTS / "nested" / "keyed" / "scene.xml",
    ATTACHMENTS / "whole_world" / "scene.xml",
    ATTACHMENTS / "repeat" / "scene.xml",
    ATTACHMENTS / "replicate" / "scene.xml",
    ATTACHMENTS / "world_refs" / "scene.xml",
    FIXTURES / "attach.xml",
    FIXTURES / "naming" / "attach_scene.xml",
    FIXTURES / "scaling" / "attach.xml",
    *(p for p in compiling_corpus() if "<attach" in p.read_text(errors="replace")),
]

#: A scene only MuJoCo 4.0 reads (``<attach>`` without ``model``, and ``frame``).
SAME_MODEL = ATTACHMENTS / "same_model" / "scene.xml"
#: A sub-model with keys attached inside a ``<replicate>``.
REPLICATED_KEYS = ATTACHMENTS / "replicate" / "keyed" / "scene.xml"

#: Lengths that double when the expansion is scaled by two. Before 4.0 MuJoCo turns a
#: scaled mesh into its principal frame with single-precision differences (see
#: ``MESH_ARRAYS_COMPARABLE`` in ``tests/support/scaling_oracle.py``), so mesh vertices
#: and mesh geom sizes are compared from 4.0 on.
LENGTHS = ("body_pos", "body_ipos", "geom_pos", "site_pos", "site_size", "jnt_pos", "flex_vert")
MESHES_COMPARABLE = MUJOCO_VERSION >= (4, 0)


def _id(path: Path) -> str:
    return corpus_id(path) if "fixtures" not in path.parts else str(path.relative_to(FIXTURES))


def _differences_attachments(path: Path, model: mujoco.MjModel) -> list[str]:
    """The fields in which ``model`` differs from MuJoCo's compilation of ``path``."""
    reference = mujoco.MjModel.from_xml_path(str(path))
    return model_differences(reference, model, ignore=path_fields())


@pytest.mark.parametrize("path", SCENES, ids=_id)
def test_expansion_compiles_as_mujocos_attach(path: Path) -> None:
    """Every array of the expansion equals MuJoCo's compilation of the ``<attach>`` scene."""
    assert _differences_attachments(path, compiled(inlined_attachments(load(path)))) == []


@pytest.mark.parametrize("path", SCENES, ids=_id)
def test_expansion_has_no_attach_include_or_model_asset(path: Path) -> None:
    """Only plain elements are left, so that every transform can work on them."""
    tags = {element.tag for _, element in walk(inlined_attachments(load(path)))}
    assert tags & {"attach", "model", "include"} == set()


@pytest.mark.parametrize("path", SCENES, ids=_id)
def test_expansion_dumped_elsewhere_compiles_identically(path: Path, tmp_path: Path) -> None:
    """Written to another folder and read back, the expansion still finds every file."""
    target = tmp_path / "elsewhere" / "scene.xml"
    target.parent.mkdir()
    dump(inlined_attachments(load(path)), target)
    assert _differences_attachments(path, mujoco.MjModel.from_xml_path(str(target))) == []


@pytest.mark.parametrize("path", SCENES, ids=_id)
def test_prefixed_expansion_passes_the_prefix_oracle(path: Path) -> None:
    """Prefixing the expansion renames every compiled name and changes nothing else."""
    expanded = inlined_attachments(load(path))
    changed = compiled(prefixed(expanded, "p_"))
    assert prefix_problems(compiled(expanded), changed, "p_") == []


@pytest.mark.parametrize("path", SCENES, ids=_id)
def test_scaled_expansion_passes_the_scale_oracle(path: Path) -> None:
    """Scaling the expansion by two doubles every length and keeps every mass."""
    expanded = inlined_attachments(load(path))
    original, changed = compiled(expanded), compiled(scaled(expanded, 2.0))
    problems = scaled_problems(original, changed, 2.0, LENGTHS)
    problems += scaled_problems(original, changed, 1.0, ["body_mass"])
    rows = slice(None) if MESHES_COMPARABLE else original.geom_type != mujoco.mjtGeom.mjGEOM_MESH
    if not np.allclose(changed.geom_size[rows], 2 * original.geom_size[rows], rtol=1e-9, atol=0):
        problems.append("geom_size")
    if MESHES_COMPARABLE:
        problems += scaled_problems(original, changed, 2.0, ["mesh_vert"])
    assert problems == []


def test_scaling_refuses_attach_but_not_its_expansion() -> None:
    """``scaled`` names ``<attach>``; after the expansion there is none left to refuse."""
    path = ATTACHMENTS / "robot" / "scene.xml"
    with pytest.raises(MjcfValueError, match="attach"):
        scaled(load(path), 2.0)
    assert compiled(scaled(inlined_attachments(load(path)), 2.0)).nbody == 9


def test_queries_find_attached_elements_where_mujoco_puts_them() -> None:
    """Queries see the attached bodies, under the parents MuJoCo gives them."""
    path = ATTACHMENTS / "robot" / "scene.xml"
    expanded = inlined_attachments(load(path))
    reference = mujoco.MjModel.from_xml_path(str(path))
    names = compiled_names(reference)["body"]
    assert [b.name for b in find_all(expanded, "body")] == names[1:]
    palm = find(expanded, "body", name="right_palm")
    assert palm is not None
    holder = parent_of(expanded, palm)
    while holder is not None and holder.tag != "body":
        holder = parent_of(expanded, holder)
    parent_id = reference.body_parentid[reference.body("right_palm").id]
    assert holder is not None and holder.name == names[parent_id]


def test_same_model_attach_and_frame_as_mujoco_reads_them() -> None:
    """Without ``model`` or with ``frame``, MuJoCo 4.0 copies from the model itself; 3.9 refuses."""
    expanded = inlined_attachments(load(SAME_MODEL))
    if MUJOCO_VERSION >= (4, 0):
        assert _differences_attachments(SAME_MODEL, compiled(expanded)) == []
    else:
        with pytest.raises(ValueError, match="frame"):
            mujoco.MjModel.from_xml_path(str(SAME_MODEL))
    assert compiled_names(compiled(expanded))["sensor"][-3:] == [
        "copy_clock",
        "shelf_clock",
        "shelf_copy_clock",
    ]


def test_keys_of_a_model_attached_in_a_replicate() -> None:
    """MuJoCo 4.0's keys are written; MuJoCo 3.9 cannot read full keys there, which is said."""
    if MUJOCO_VERSION >= (4, 0):
        assert (
            _differences_attachments(
                REPLICATED_KEYS, compiled(inlined_attachments(load(REPLICATED_KEYS)))
            )
            == []
        )
    else:
        assert mujoco.MjModel.from_xml_path(str(REPLICATED_KEYS)).nkey > 0
        said = (
            r"^cannot write the keyframes MuJoCo adds for the attached models' keys as plain "
            r"keyframes \(.*scene\.xml:\d+: .*Keyframe 'f_curled' has invalid qpos size.*\); "
            r"this MuJoCo reads keyframes differently where a <replicate> copies joints: "
            r"remove the attached models' keyframes first$"
        )
        with pytest.raises(MjcfValueError, match=said):
            inlined_attachments(load(REPLICATED_KEYS))


def test_loads_expands_from_base_dir() -> None:
    """A model read from text with ``base_dir`` finds its sub-models as one loaded from its file."""
    path = ATTACHMENTS / "nested" / "scene.xml"
    text = path.read_text(encoding="utf-8")
    from_text = inlined_attachments(loads(text, base_dir=path.parent))
    assert from_text == inlined_attachments(load(path))
    assert _differences_attachments(path, compiled(from_text)) == []


def test_unattached_model_asset_is_removed(tmp_path: Path) -> None:
    """An asset ``<model>`` no ``<attach>`` uses adds nothing in MuJoCo, and is dropped."""
    path = written(
        tmp_path,
        {
            "scene.xml": '<mujoco><asset><model file="cup.xml"/><material name="m"/></asset>'
            '<worldbody><geom size="1" material="m"/></worldbody></mujoco>',
            "cup.xml": '<mujoco model="cup"><asset><material name="glaze"/></asset></mujoco>',
        },
    )
    expanded = inlined_attachments(load(path))
    assert find(expanded, "model") is None
    assert _differences_attachments(path, compiled(expanded)) == []


def test_euler_angles_in_another_sequence_are_refused(tmp_path: Path) -> None:
    """A sub-model whose Euler angles would need another sequence is refused, naming eulerseq.

    The same sub-model without ``euler`` attributes expands to MuJoCo's result.
    """
    child = (
        '<mujoco><compiler eulerseq="zyx"/><worldbody><body name="b" {}><joint/>'
        '<geom size="0.1"/></body></worldbody></mujoco>'
    )
    scene = (
        '<mujoco><asset><model name="c" file="child.xml"/></asset><worldbody>'
        '<body name="a" euler="10 20 30"><attach model="c" body="b" prefix="c_"/></body>'
        "</worldbody></mujoco>"
    )
    path = written(tmp_path, {"scene.xml": scene, "child.xml": child.format('euler="30 0 10"')})
    mujoco.MjModel.from_xml_path(str(path))
    with pytest.raises(MjcfValueError, match="eulerseq"):
        inlined_attachments(load(path))
    written(tmp_path, {"child.xml": child.format('quat="0.9 0.1 0.3 0.2"')})
    assert _differences_attachments(path, compiled(inlined_attachments(load(path)))) == []


def test_unknown_model_body_or_source_is_an_error(tmp_path: Path) -> None:
    """What MuJoCo cannot find, the expansion cannot either: both refuse, naming it."""
    child = '<mujoco model="c"><worldbody><body name="b"/></worldbody></mujoco>'
    cases = {
        '<attach model="nope" body="b" prefix="x_"/>': r"model='nope'.*\['c'\]",
        '<attach model="c" body="nope" prefix="x_"/>': r"no body named 'nope'.*\['b'\]",
        '<attach body="late" prefix="x_"/>': r"body='late'.*written before",
    }
    for attach_element, message in cases.items():
        scene = (
            '<mujoco><asset><model file="child.xml"/></asset><worldbody>'
            f'<body name="a">{attach_element}</body><body name="late"/></worldbody></mujoco>'
        )
        path = written(tmp_path, {"scene.xml": scene, "child.xml": child})
        with pytest.raises(ValueError):
            mujoco.MjModel.from_xml_path(str(path))
        with pytest.raises(MjcfLookupError, match=message):
            inlined_attachments(load(path))


def test_models_attaching_each_other_are_refused(tmp_path: Path) -> None:
    """A cycle of sub-models raises (MuJoCo documents that it loops forever, so it is not run)."""
    one = '<mujoco><asset><model name="two" file="two.xml"/></asset><worldbody><body name="b">'
    two = '<mujoco><asset><model name="one" file="one.xml"/></asset><worldbody><body name="b">'
    path = written(
        tmp_path,
        {
            "one.xml": one
            + '<attach model="two" body="b" prefix="t_"/></body></worldbody></mujoco>',
            "two.xml": two
            + '<attach model="one" body="b" prefix="o_"/></body></worldbody></mujoco>',
        },
    )
    with pytest.raises(MjcfIncludeCycleError, match=r"two\.xml -> .*one\.xml -> .*two\.xml"):
        inlined_attachments(load(path))


def test_unknown_world_reference_is_refused(tmp_path: Path) -> None:
    """A flex naming the world body is refused: whether ``<attach>`` copies it is not measured.

    MuJoCo compiles the scene; the expansion says what it cannot reproduce instead of guessing.
    """
    child = (
        '<mujoco model="c"><worldbody><body name="b"><geom size="0.1"/></body></worldbody>'
        '<deformable><flex name="f" dim="1" body="world b" vertex="0 0 0 0 0 0" '
        'element="0 1"/></deformable></mujoco>'
    )
    scene = (
        '<mujoco><asset><model file="child.xml"/></asset><worldbody>'
        '<attach model="c" body="b" prefix="x_"/></worldbody></mujoco>'
    )
    path = written(tmp_path, {"scene.xml": scene, "child.xml": child})
    mujoco.MjModel.from_xml_path(str(path))
    with pytest.raises(MjcfValueError, match=r'flex body="world"'):
        inlined_attachments(load(path))


# -- Expanding ``<attach>`` across angle units: a degree parent meets a radian sub-model. ------
#
# MuJoCo reads each model under its own ``<compiler angle>``. Some radians, such as 0.73
# and 1.21, are read from no double written in degrees (MuJoCo multiplies degrees by
# ``pi / 180``), so the expansion must rewrite the degree parent in radians, not the radian child in
# degrees; MuJoCo compiling the original scene is the referee. A parent whose sub-models
# are all in degrees is left in degrees, as written.


#: A sub-model in radians whose joint range no double in degrees gives.
RADIAN_CHILD = (
    '<mujoco model="finger"><compiler angle="radian"/><worldbody>'
    '<body name="finger" euler="0 1.2 0.3"><joint name="bend" range="0.73 1.21"/>'
    '<geom size="0.01"/></body></worldbody></mujoco>'
)
#: The same sub-model in degrees.
DEGREE_CHILD = RADIAN_CHILD.replace('<compiler angle="radian"/>', "")

#: A degree parent (``{compiler}`` is its own ``<compiler>``, if any) attaching ``finger``.
PARENT = (
    '<mujoco model="hand">{compiler}<asset><material name="skin"/>'
    '<model name="finger" file="finger.xml"/></asset>'
    '<worldbody><body name="palm" euler="10 20 30"><joint name="wrist" range="-30 45"/>'
    '<geom size="0.05" material="skin"/>'
    '<attach model="finger" body="finger" prefix="f_"/></body>'
    "</worldbody></mujoco>"
)


def _scene_angles(folder: Path, parent_compiler: str, child: str) -> Path:
    (folder / "finger.xml").write_text(child, encoding="utf-8")
    path = folder / "scene.xml"
    path.write_text(PARENT.format(compiler=parent_compiler), encoding="utf-8")
    return path


@pytest.mark.parametrize(
    "parent_compiler",
    ["", '<compiler autolimits="true"/>'],
    ids=["parent_without_compiler", "parent_with_compiler"],
)
def test_radian_child_in_degree_parent_compiles_as_mujocos_attach(
    tmp_path: Path, parent_compiler: str
) -> None:
    """Every compiled array of the expansion equals MuJoCo's, the child's radians exact."""
    path = _scene_angles(tmp_path, parent_compiler, RADIAN_CHILD)
    reference = mujoco.MjModel.from_xml_path(str(path))
    expanded = inlined_attachments(load(path))
    assert model_differences(reference, compiled(expanded), ignore=path_fields()) == []
    assert compiled(expanded).jnt_range[reference.joint("f_bend").id].tolist() == [0.73, 1.21]


def test_compiler_added_to_a_parent_without_one_comes_first(tmp_path: Path) -> None:
    """The parent rewritten in radians gets ``<compiler angle="radian">`` as its first section."""
    expanded = inlined_attachments(load(_scene_angles(tmp_path, "", RADIAN_CHILD)))
    first = expanded.children[0]
    assert isinstance(first, Compiler)
    assert first.angle == "radian"


def test_degree_children_leave_the_parent_in_degrees_as_written(tmp_path: Path) -> None:
    """With no sub-model in radians, the parent keeps its degrees and its numbers as written."""
    path = _scene_angles(tmp_path, "", DEGREE_CHILD)
    expanded = inlined_attachments(load(path))
    assert find(expanded, "compiler") is None
    assert find(expanded, "body", name="palm", euler=(10, 20, 30)) is not None
    assert find(expanded, "joint", name="wrist", range=(-30, 45)) is not None
    reference = mujoco.MjModel.from_xml_path(str(path))
    assert model_differences(reference, compiled(expanded), ignore=path_fields()) == []


# -- Expanding ``<attach>`` in a model whose frames have names like ``attach_0``. --------------
#
# The user's frames, whatever their names, keep their place, their pose and their
# children: MuJoCo compiling the original scene is the referee.


#: A sub-model with one body.
CUP = (
    '<mujoco model="cup"><worldbody><body name="cup"><geom size="0.1"/></body></worldbody></mujoco>'
)


def _scene_frame_names(frame_names: list[str]) -> str:
    """A scene with posed frames of these names, each holding a body, then an ``<attach>``."""
    frames = "".join(
        f'<frame name="{name}" pos="{i + 1} 0 0"><body name="in_{i}"><geom size="0.1"/></body>'
        "</frame>"
        for i, name in enumerate(frame_names)
    )
    return (
        '<mujoco><asset><model file="cup.xml"/></asset><worldbody>'
        f'{frames}<body name="table" pos="0 0 1"><attach model="cup" body="cup" prefix="a_"/>'
        "</body></worldbody></mujoco>"
    )


@pytest.mark.parametrize(
    "frame_names",
    [["attach_0"], ["attach_0", "attach_1"], ["attach_None"]],
    ids=["attach_0", "attach_0_and_1", "attach_None"],
)
def test_frames_named_like_attach_markers_are_kept(tmp_path: Path, frame_names: list[str]) -> None:
    """The expansion compiles as MuJoCo's and keeps every frame of the user, in order."""
    (tmp_path / "cup.xml").write_text(CUP, encoding="utf-8")
    path = tmp_path / "scene.xml"
    path.write_text(_scene_frame_names(frame_names), encoding="utf-8")
    reference = mujoco.MjModel.from_xml_path(str(path))
    expanded = inlined_attachments(load(path))
    assert model_differences(reference, compiled(expanded), ignore=path_fields()) == []
    frames = [get_attribute(e, "name") for _, e in walk(expanded) if e.tag == "frame"]
    assert frames == frame_names


# -- Expanding ``<attach>``: the keys MuJoCo adds for attached models that have keys. ----------
#
# MuJoCo adds one key per key of each attached model, after the parent's own keys,
# with the attached key's ``time``. The expansion writes them as plain ``<key>``
# elements; MuJoCo compiling the original scene is the referee. Where no attached model
# has keys, nothing is added and the scene need not compile.


#: A sub-model with one joint and one key, at time 0.5.
KEYED = (
    '<mujoco model="keyed"><worldbody><body name="arm"><joint name="swing"/>'
    '<geom size="0.1"/></body></worldbody>'
    '<keyframe><key name="raised" qpos="0.3" time="0.5"/></keyframe></mujoco>'
)
#: A sub-model with one joint and no keys.
PLAIN = (
    '<mujoco model="plain"><worldbody><body name="leg"><joint name="kick"/>'
    '<geom size="0.1"/></body></worldbody></mujoco>'
)
#: A scene attaching the keyed model, then the plain one; it has an unnamed and a named key.
SCENE = (
    '<mujoco model="scene"><asset><model file="keyed.xml"/><model file="plain.xml"/></asset>'
    '<worldbody><body name="base"><joint name="turn"/><geom size="0.2"/></body>'
    '<attach model="keyed" body="arm" prefix="k_"/>'
    '<attach model="plain" body="leg" prefix="p_"/></worldbody>'
    '<keyframe><key qpos="0.1 0 0"/><key name="home" qpos="0.2 0 0"/></keyframe></mujoco>'
)


@pytest.fixture
def scene(tmp_path: Path) -> Path:
    """The scene and its two sub-models, written to a folder."""
    return written(tmp_path, {"scene.xml": SCENE, "keyed.xml": KEYED, "plain.xml": PLAIN})


def test_attached_keys_compile_as_mujocos(scene: Path) -> None:
    """Every key array (and every other array) of the expansion equals MuJoCo's."""
    reference = mujoco.MjModel.from_xml_path(str(scene))
    got = compiled(inlined_attachments(load(scene)))
    assert model_differences(reference, got, ignore=path_fields()) == []
    assert compiled_names(got)["key"] == ["", "home", "k_raised"]
    assert got.key_time.tolist() == reference.key_time.tolist() == [0.0, 0.0, 0.5]


def test_attached_keys_join_the_one_keyframe_section(scene: Path) -> None:
    """The added key goes after the parent's own keys, in its only ``<keyframe>``."""
    expanded = inlined_attachments(load(scene))
    sections = [s for s in expanded.children if isinstance(s, Keyframe)]
    assert len(sections) == 1
    names = [get_attribute(k, "name") for k in sections[0].elements]
    assert names == [None, "home", "k_raised"]


def test_added_key_writes_only_the_arrays_the_model_has(scene: Path) -> None:
    """Without actuators or mocap bodies, the added key has no ``ctrl``, ``act``, ``mpos``..."""
    expanded = inlined_attachments(load(scene))
    added = [e for _, e in walk(expanded) if get_attribute(e, "name") == "k_raised"]
    assert len(added) == 1
    empty = ("ctrl", "act", "mpos", "mquat", "plastic")
    assert [name for name in empty if get_attribute(added[0], name) is not None] == []
    assert get_attribute(added[0], "time") == 0.5


def test_keyless_attachments_expand_in_a_model_mujoco_refuses(tmp_path: Path) -> None:
    """No attached model has keys: the scene is expanded without being compiled.

    MuJoCo refuses the scene (its own key is too long) and, in the same words, the expansion.
    """
    scene = (
        '<mujoco><asset><model file="plain.xml"/></asset><worldbody>'
        '<attach model="plain" body="leg" prefix="p_"/></worldbody>'
        '<keyframe><key qpos="1 2 3"/></keyframe></mujoco>'
    )
    path = written(tmp_path, {"scene.xml": scene, "plain.xml": PLAIN})
    with pytest.raises(ValueError, match="invalid qpos size"):
        mujoco.MjModel.from_xml_path(str(path))
    expanded = inlined_attachments(load(path))
    assert [get_attribute(b, "name") for b in find_all(expanded, "body")] == ["p_leg"]
    with pytest.raises(MjcfCompileError, match="invalid qpos size"):
        compiled(expanded)


# -- Expanding ``<attach>``: how sub-model files are read, and what is left of the scene. ------
#
# A sub-model's ``<include>`` is read as MuJoCo reads it, the scene's asset section
# keeps its comments and its other assets, an ``<attach>`` with an empty prefix
# copies the names as they are, a self-attach needs no asset ``<model>``, and a model
# without ``<attach>`` comes back as it is. MuJoCo compiling the original is the referee
# (MuJoCo 3.9, which requires ``model``, compiles the self-attach's copy written out).


def _differences_model_files(path: Path) -> list[str]:
    """The fields in which the expansion of ``path`` differs from MuJoCo's compilation of it."""
    reference = mujoco.MjModel.from_xml_path(str(path))
    expanded = inlined_attachments(load(path))
    return model_differences(reference, compiled(expanded), ignore=path_fields())


def test_sub_model_includes_are_read(tmp_path: Path) -> None:
    """A sub-model whose bodies are in an included file attaches them, as MuJoCo does."""
    path = written(
        tmp_path,
        {
            "scene.xml": '<mujoco><asset><model file="cup.xml"/></asset><worldbody>'
            '<body name="table"><attach model="cup" body="cup" prefix="a_"/></body>'
            "</worldbody></mujoco>",
            "cup.xml": '<mujoco model="cup"><include file="cup_body.xml"/></mujoco>',
            "cup_body.xml": '<mujoco><worldbody><body name="cup" pos="0 0 0.1">'
            '<joint name="tilt"/><geom size="0.1"/></body></worldbody></mujoco>',
        },
    )
    assert _differences_model_files(path) == []
    assert compiled_names(mujoco.MjModel.from_xml_path(str(path)))["body"][-1] == "a_cup"


def test_asset_comments_and_other_assets_stay(tmp_path: Path) -> None:
    """Removing the asset ``<model>`` keeps the asset section's comment and material."""
    path = written(
        tmp_path,
        {
            "scene.xml": '<mujoco><asset><!-- the parts --><model file="cup.xml"/>'
            '<material name="wood" rgba="0.5 0.3 0.1 1"/></asset><worldbody>'
            '<body name="table"><geom size="0.5" material="wood"/>'
            '<attach model="cup" body="cup" prefix="a_"/></body></worldbody></mujoco>',
            "cup.xml": '<mujoco model="cup"><worldbody><body name="cup">'
            '<geom size="0.1"/></body></worldbody></mujoco>',
        },
    )
    assert _differences_model_files(path) == []
    asset = inlined_attachments(load(path)).asset
    assert asset is not None
    assert [type(n) for n in asset.children][:1] == [Comment]
    assert [get_attribute(e, "name") for e in asset.elements] == ["wood"]


def test_empty_prefix_keeps_the_names(tmp_path: Path) -> None:
    """``prefix=""`` attaches the sub-model's names unchanged, as MuJoCo does."""
    path = written(
        tmp_path,
        {
            "scene.xml": '<mujoco><asset><model file="cup.xml"/></asset><worldbody>'
            '<body name="table"><attach model="cup" body="cup" prefix=""/></body>'
            "</worldbody></mujoco>",
            "cup.xml": '<mujoco model="cup"><worldbody><body name="cup">'
            '<joint name="tilt"/><geom name="rim" size="0.1"/></body></worldbody></mujoco>',
        },
    )
    assert _differences_model_files(path) == []
    names = compiled_names(compiled(inlined_attachments(load(path))))
    assert [names["body"], names["jnt"], names["geom"]] == [
        ["world", "table", "cup"],
        ["tilt"],
        ["rim"],
    ]


def test_self_attach_without_model_assets_is_expanded() -> None:
    """An ``<attach body>`` copying from the model itself is expanded without any asset model."""
    text = (
        '<mujoco><worldbody><body name="a" pos="1 0 0"><joint name="j"/><geom size="0.1"/></body>'
        '<body name="b" pos="0 1 0"><attach body="a" prefix="c_"/></body></worldbody></mujoco>'
    )
    expanded = inlined_attachments(loads(text))
    assert not any(e.tag == "attach" for _, e in walk(expanded))
    if MUJOCO_VERSION >= (4, 0):
        reference = mujoco.MjModel.from_xml_string(text)
    else:
        with pytest.raises(ValueError, match="required attribute missing: 'model'"):
            mujoco.MjModel.from_xml_string(text)
        reference = mujoco.MjModel.from_xml_string(
            text.replace(
                '<attach body="a" prefix="c_"/>',
                '<body name="c_a" pos="1 0 0"><joint name="c_j"/><geom size="0.1"/></body>',
            )
        )
    assert model_differences(reference, compiled(expanded), ignore=path_fields()) == []


def test_model_without_attach_comes_back_as_it_is() -> None:
    """With no ``<attach>`` or asset ``<model>``, the model is returned as it is, in its order."""
    model = loads(
        '<mujoco><keyframe><key qpos="0.5"/></keyframe><worldbody><body name="a">'
        '<joint/><geom size="0.1"/></body></worldbody></mujoco>'
    )
    assert inlined_attachments(model) == model
    assert [type(s) for s in inlined_attachments(model).children] == [Keyframe, Worldbody]


# -- Expanding ``<attach>``: what is refused, and what the user is told to do about it. --------
#
# Each case is first put to MuJoCo: where MuJoCo refuses the scene too, the expansion
# refuses it with its own error; where MuJoCo compiles it but the expansion cannot
# reproduce the result exactly, the message names the construct and the way out.
# MuJoCo 3.9 refuses every ``<attach>`` without ``model`` (MuJoCo 4.0's self-attach);
# the expansion gives the same refusals under either release.


#: What MuJoCo 3.9 says of an ``<attach>`` without ``model``: its schema requires
#: ``model`` and has no ``frame`` (both came in MuJoCo 4.0); which it says first depends
#: on where the ``<attach>`` stands.
BEFORE_4 = "required attribute missing: 'model'|unrecognized attribute: 'frame'"


def test_euler_angles_in_another_sequence_are_refused_with_the_way_out(tmp_path: Path) -> None:
    """The refusal names both sequences and says to write the angles as quat first."""
    (tmp_path / "child.xml").write_text(
        '<mujoco><compiler eulerseq="zyx"/><worldbody><body name="b" euler="30 0 10">'
        '<joint/><geom size="0.1"/></body></worldbody></mujoco>',
        encoding="utf-8",
    )
    path = tmp_path / "scene.xml"
    path.write_text(
        '<mujoco><asset><model name="c" file="child.xml"/></asset><worldbody>'
        '<body name="a"><attach model="c" body="b" prefix="c_"/></body></worldbody></mujoco>',
        encoding="utf-8",
    )
    mujoco.MjModel.from_xml_path(str(path))
    message = (
        r"eulerseq='zyx' into one with eulerseq='xyz': its euler angles would be rewritten "
        r"in the other sequence, exactly only to the last digit; write them as quat "
        r"\(or give both models the same eulerseq\) first"
    )
    with pytest.raises(MjcfValueError, match=message):
        inlined_attachments(load(path))


def test_attach_without_model_body_or_frame_is_refused() -> None:
    """MuJoCo and the expansion refuse a self-attach that names nothing to copy."""
    text = (
        '<mujoco><worldbody><body name="a"><geom size="1"/></body>'
        '<body name="m"><attach prefix="c_"/></body></worldbody></mujoco>'
    )
    said = "either 'body' or 'frame' attribute must be specified"
    with pytest.raises(ValueError, match=said if MUJOCO_VERSION >= (4, 0) else BEFORE_4):
        mujoco.MjModel.from_xml_string(text)
    with pytest.raises(
        MjcfValueError, match=r"^an <attach> without model must name a body or a frame to copy$"
    ):
        inlined_attachments(loads(text))


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            '<mujoco><worldbody><body name="a"><geom size="1"/><body name="m">'
            '<attach body="a" prefix="c_"/></body></body></worldbody></mujoco>',
            r"^<attach body='a'> is inside the body it copies$",
        ),
        (
            '<mujoco><worldbody><frame name="f"><body name="m"><geom size="1"/>'
            '<attach frame="f" prefix="c_"/></body></frame></worldbody></mujoco>',
            r"^<attach frame='f'> is inside the frame it copies$",
        ),
    ],
    ids=["body", "frame"],
)
def test_attach_inside_what_it_copies_is_refused(text: str, message: str) -> None:
    """MuJoCo copies what it has read so far; the expansion refuses, naming the element."""
    if MUJOCO_VERSION >= (4, 0):
        mujoco.MjModel.from_xml_string(text)
    else:
        with pytest.raises(ValueError, match=BEFORE_4):
            mujoco.MjModel.from_xml_string(text)
    with pytest.raises(MjcfValueError, match=message):
        inlined_attachments(loads(text))


@pytest.mark.parametrize("kind", ["body", "frame"])
def test_attach_of_something_written_later_is_refused(kind: str) -> None:
    """MuJoCo copies only what it has read: both refuse an element written after the attach."""
    text = (
        f'<mujoco><worldbody><body name="m"><attach {kind}="late" prefix="c_"/></body>'
        f'<{kind} name="late"><geom size="1"/></{kind}></worldbody></mujoco>'
    )
    said = f"could not find {kind} 'late'" if MUJOCO_VERSION >= (4, 0) else BEFORE_4
    with pytest.raises(ValueError, match=said):
        mujoco.MjModel.from_xml_string(text)
    message = (
        rf"<attach {kind}='late'> without model: no {kind} of that name is written before it "
        r"\(MuJoCo copies only what it has read\)"
    )
    with pytest.raises(MjcfLookupError, match=message):
        inlined_attachments(loads(text))


# -- Expanding ``<attach>`` in a model with ``<size nkey>`` and its own keys. ------------------
#
# MuJoCo 4.0 compiles ``<size nkey="2"/>`` with one ``<key name="own">`` to the keys
# ``own`` and one blank key. The expansion once set the ``<keyframe>`` aside but not
# ``nkey``: the attach wrote two blank keys and the own key came third (and with a keyed
# sub-model the expansion refused the scene, naming a wrong key order). MuJoCo 3.9
# refuses the self-attach (it requires ``model``), and keeps all ``nkey`` keys before
# an attached model's: ``own``, two blank keys, then the sub-model's.


def test_size_nkey_and_own_key_survive_a_self_attach() -> None:
    """The expansion compiles to MuJoCo's keys: ``own`` first, then one blank key."""
    text = (
        '<mujoco><size nkey="2"/><worldbody><body name="a"><joint/><geom size="1"/></body>'
        '<body name="m"><attach body="a" prefix="c_"/></body></worldbody>'
        '<keyframe><key name="own" qpos="0.5 0"/></keyframe></mujoco>'
    )
    got = compiled(inlined_attachments(loads(text)))
    if MUJOCO_VERSION < (4, 0):
        with pytest.raises(ValueError, match="required attribute missing: 'model'"):
            mujoco.MjModel.from_xml_string(text)
        text = text.replace(
            '<attach body="a" prefix="c_"/>', '<body name="c_a"><joint/><geom size="1"/></body>'
        )
    reference = mujoco.MjModel.from_xml_string(text)
    assert compiled_names(reference)["key"] == ["own", ""]
    assert model_differences(reference, got, ignore=path_fields()) == []


def test_size_nkey_and_own_key_with_a_keyed_sub_model(tmp_path: Path) -> None:
    """With a keyed sub-model, the expansion compiles to MuJoCo's keys instead of refusing."""
    (tmp_path / "keyed.xml").write_text(
        '<mujoco model="keyed"><worldbody><body name="arm"><joint/><geom size="0.1"/></body>'
        '</worldbody><keyframe><key name="raised" qpos="0.3"/></keyframe></mujoco>',
        encoding="utf-8",
    )
    path = tmp_path / "scene.xml"
    path.write_text(
        '<mujoco><size nkey="3"/><asset><model file="keyed.xml"/></asset><worldbody>'
        '<body name="p"><joint/><geom size="0.1"/></body>'
        '<attach model="keyed" body="arm" prefix="x_"/></worldbody>'
        '<keyframe><key name="own" qpos="0.1 0"/></keyframe></mujoco>',
        encoding="utf-8",
    )
    reference = mujoco.MjModel.from_xml_path(str(path))
    keys = ["own", "", "x_raised"] if MUJOCO_VERSION >= (4, 0) else ["own", "", "", "x_raised"]
    assert compiled_names(reference)["key"] == keys
    got = compiled(inlined_attachments(load(path)))
    assert model_differences(reference, got, ignore=path_fields()) == []
