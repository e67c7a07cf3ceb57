"""Expanding ``<attach>``: the expanded model compiles to MuJoCo's own ``<attach>`` result.

The fixtures in ``tests/fixtures/attachments`` each hold a scene and the models it
attaches, in folders of their own with their own ``<compiler>``. For each, MuJoCo
compiles the original (its ``<attach>``) and the expansion; every array must be
equal (the recorded file paths aside). The expansion is then dumped elsewhere,
prefixed and scaled, and MuJoCo referees those too.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from mjcf_model import attach, compiled, inlined_attachments, prefixed, scaled
from mjcf_model.bridge.compare import compiled_names, model_differences, path_fields
from mjcf_model.errors import (
    MjcfIncludeCycleError,
    MjcfLookupError,
    MjcfValueError,
)
from mjcf_model.tree.queries import find, find_all, parent_of
from mjcf_model.tree.traversal import walk
from serializers import dump, load, loads
from tests.conftest import FIXTURES, MUJOCO_VERSION, compiling_corpus, corpus_id
from tests.support.attach_files import written
from tests.support.oracles import prefix_problems, scaled_problems

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
#: ``tests/test_scaling_fixes.py``), so mesh vertices and mesh geom sizes are compared
#: from 4.0 on.
LENGTHS = ("body_pos", "body_ipos", "geom_pos", "site_pos", "site_size", "jnt_pos", "flex_vert")
MESHES_COMPARABLE = MUJOCO_VERSION >= (4, 0)


def _id(path: Path) -> str:
    return corpus_id(path) if "fixtures" not in path.parts else str(path.relative_to(FIXTURES))


def _differences(path: Path, model: mujoco.MjModel) -> list[str]:
    """The fields in which ``model`` differs from MuJoCo's compilation of ``path``."""
    reference = mujoco.MjModel.from_xml_path(str(path))
    return model_differences(reference, model, ignore=path_fields())


@pytest.mark.parametrize("path", SCENES, ids=_id)
def test_expansion_compiles_as_mujocos_attach(path: Path) -> None:
    """Every array of the expansion equals MuJoCo's compilation of the ``<attach>`` scene."""
    assert _differences(path, compiled(inlined_attachments(load(path)))) == []


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
    assert _differences(path, mujoco.MjModel.from_xml_path(str(target))) == []


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
        assert _differences(SAME_MODEL, compiled(expanded)) == []
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
            _differences(REPLICATED_KEYS, compiled(inlined_attachments(load(REPLICATED_KEYS))))
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
    assert _differences(path, compiled(from_text)) == []


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
    assert _differences(path, compiled(expanded)) == []


def test_parent_defaults_do_not_reach_the_child(tmp_path: Path) -> None:
    """``attach`` keeps the parent's top-level defaults off the child, as ``MjSpec`` does."""
    parent_text = (
        '<mujoco><default><geom rgba="1 0 0 1"/><joint damping="3"/></default>'
        '<worldbody><body name="a"><geom size="1"/><site name="s"/></body></worldbody></mujoco>'
    )
    child_text = (
        '<mujoco><worldbody><body name="b"><joint/><geom size="1"/></body></worldbody></mujoco>'
    )
    spec = mujoco.MjSpec.from_string(parent_text)
    spec.attach(mujoco.MjSpec.from_string(child_text), site=spec.site("s"), prefix="c_")
    ours = compiled(attach(loads(parent_text), loads(child_text), at="s", prefix="c_"))
    assert model_differences(spec.compile(), ours) == []


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
    assert _differences(path, compiled(inlined_attachments(load(path)))) == []


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
