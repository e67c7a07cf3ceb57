"""Prefixing names MuJoCo makes while reading: replicate copies, flexcomp bodies, attachments.

MuJoCo is the referee: the original and the prefixed model must compile to the
same arrays with every name prefixed (``prefix_problems``), or, where MuJoCo
cannot compile a construct (MuJoCo 3.9 has no ``<attach>`` without ``model``),
the test asserts what MuJoCo does.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import GenericElement
from mjcf_model.bridge.compare import compile_text_beside, compiled_names, model_differences
from mjcf_model.errors import MjcfAssetError, MjcfValueError
from mjcf_model.tools.check import check_file
from mjcf_model.transforms.naming.renaming import declared_names, prefix_map, prefixed, renamed
from mjcf_model.tree.traversal import walk
from serializers import dumps, from_dict, from_etree, load, loads, to_dict, to_etree
from serializers.skins import inline_skin_files
from tests.conftest import FIXTURES, MUJOCO_VERSION
from tests.support.oracles import (
    RENAMING_FIELDS,
    compile_beside,
    prefix_problems,
    prefixed_problems,
    written,
)
from tests.support.skin_files import skin_file

NAMING = FIXTURES / "naming"
#: Every fixture of this module, the attached parts in ``parts/`` included (hidden files are
#: the temporary copies ``compile_text_beside`` writes while other workers run).
NAMING_FIXTURES = sorted(p for p in NAMING.rglob("*.xml") if not p.name.startswith("."))
naming_fixture = pytest.mark.parametrize(
    "path", NAMING_FIXTURES, ids=[str(p.relative_to(NAMING)) for p in NAMING_FIXTURES]
)


# -- the fixtures -------------------------------------------------------------------------


@naming_fixture
def test_prefix_oracle_passes_on_fixture(path: Path) -> None:
    """A prefixed fixture compiles to the original's arrays with every name prefixed."""
    assert prefixed_problems(load(path), path) == []


@naming_fixture
@pytest.mark.parametrize("inline_includes", [False, True], ids=["kept", "inlined"])
def test_fixture_round_trips_to_the_identical_model(path: Path, inline_includes: bool) -> None:
    """Each fixture's written text compiles to a model identical to the original."""
    result = check_file(path, inline_includes=inline_includes)
    assert (result.status, result.differences, result.message) == ("identical", (), "")


@naming_fixture
def test_fixture_survives_every_serializer(path: Path) -> None:
    """Each fixture reads back equal from text, ElementTree and dict, every element typed."""
    model = load(path)
    assert loads(dumps(model)) == model
    assert from_etree(to_etree(model)) == model
    assert from_dict(to_dict(model)) == model
    assert [e.tag for _, e in walk(model) if isinstance(e, GenericElement)] == []


@naming_fixture
def test_prefixing_a_fixture_composes(path: Path) -> None:
    """``prefixed(prefixed(m, a), b) == prefixed(m, b + a)`` on models with generated names."""
    model = load(path)
    assert prefixed(prefixed(model, "a_"), "b_") == prefixed(model, "b_a_")


@pytest.mark.parametrize("name", ["flexcomp.xml", "replicate.xml"])
def test_renaming_with_the_prefix_map_prefixes_generated_names(name: str) -> None:
    """Renaming the generators through ``prefix_map`` renames what they make, as prefixing does."""
    path = NAMING / name
    model = load(path)
    new = renamed(model, prefix_map(model, "q_"))
    assert new == prefixed(model, "q_")
    original = compile_beside(model, path)
    assert prefix_problems(original, compile_beside(new, path), "q_") == []


# -- flexcomp -----------------------------------------------------------------------------


def test_flexcomp_bodies_are_named_by_index_in_mujoco() -> None:
    """MuJoCo names flexcomp bodies <name>_<i> (pinned: none), <name>_<i>_<j>_<k> if trilinear."""
    compiled = compile_beside(load(NAMING / "flexcomp.xml"), NAMING / "flexcomp.xml")
    bodies = compiled_names(compiled)["body"]
    assert [b for b in bodies if b.startswith("rope_") and b != "rope_holder"] == [
        f"rope_{i}" for i in range(5)
    ]
    assert [b for b in bodies if b.startswith("cloth_") and b != "cloth_frame"] == [
        f"cloth_{i}" for i in range(16) if i not in (0, 3)
    ]
    assert "jelly_1_1_1" in bodies and "jelly_0_0_0" not in bodies


def test_reference_to_a_flexcomp_body_follows_the_flexcomp() -> None:
    """A reference to rope_3 becomes p_rope_3, the body the prefixed flexcomp makes."""
    text = """<mujoco><worldbody><body name="anchor"><geom size="0.03"/></body>
      <flexcomp name="rope" type="grid" dim="1" count="5 1 1" spacing="0.05 0.05 0.05"
                radius="0.01" mass="0.1"><edge equality="true"/></flexcomp></worldbody>
      <contact><exclude body1="anchor" body2="rope_3"/></contact></mujoco>"""
    model = loads(text)
    new = prefixed(model, "p_")
    assert 'body2="p_rope_3"' in dumps(new)
    original = mujoco.MjModel.from_xml_string(text)
    assert prefix_problems(original, mujoco.MjModel.from_xml_string(dumps(new)), "p_") == []


def test_flexcomp_inside_a_replicate() -> None:
    """MuJoCo 4.0 names a replicated flexcomp's bodies rope_<i><copy>; MuJoCo 3.9 rejects it."""
    text = """<mujoco><worldbody><replicate count="2" offset="1 0 0">
      <body name="hook"><flexcomp name="rope" type="grid" dim="1" count="3 1 1"
        spacing="0.05 0.05 0.05" radius="0.01" mass="0.1"><edge equality="true"/></flexcomp>
      </body></replicate><body name="wall"><geom size="0.1"/></body></worldbody>
      <contact><exclude body1="wall" body2="rope_21"/></contact></mujoco>"""
    model = loads(text)
    assert 'body2="p_rope_21"' in dumps(prefixed(model, "p_"))
    if MUJOCO_VERSION < (4, 0):
        with pytest.raises(ValueError, match="unknown body 'rope_0' in flex"):
            mujoco.MjModel.from_xml_string(text)
        return
    original = mujoco.MjModel.from_xml_string(text)
    assert "rope_21" in compiled_names(original)["body"]
    changed = mujoco.MjModel.from_xml_string(dumps(prefixed(model, "p_")))
    assert prefix_problems(original, changed, "p_") == []


# -- replicate ----------------------------------------------------------------------------


def test_replicate_suffixes_in_mujoco() -> None:
    """MuJoCo pads the copy index to the width of count and puts the inner suffix first."""
    compiled = compile_beside(load(NAMING / "replicate.xml"), NAMING / "replicate.xml")
    bodies = compiled_names(compiled)["body"]
    assert bodies[1:13] == [f"post{i:02d}" for i in range(12)]
    assert bodies[13:] == [f"cell_{i}x{j}" for j in range(3) for i in range(2)]
    assert "cube_acc_1x2" in compiled_names(compiled)["sensor"]


def test_references_to_copies_follow_their_original() -> None:
    """References to post03 and cell_1x2 become p_post03 and p_cell_1x2; out-of-range ones stay."""
    model = load(NAMING / "replicate.xml")
    text = dumps(prefixed(model, "p_"))
    for reference in ('body1="p_post03"', 'body2="p_cell_1x2"', 'joint="p_post_slide05"'):
        assert reference in text
    wrong = loads(
        '<mujoco><worldbody><replicate count="3"><body name="b"/></replicate></worldbody>'
        '<contact><exclude body1="b3" body2="b1"/></contact></mujoco>'
    )
    assert 'body1="b3" body2="p_b1"' in dumps(prefixed(wrong, "p_"))


# -- asset <model> files and <attach> -----------------------------------------------------


def test_unnamed_model_asset_is_named_by_the_file_root(tmp_path: Path) -> None:
    """MuJoCo names an unnamed asset <model> by its file's root model attribute, not the stem."""
    written(
        tmp_path,
        '<mujoco model="kid"><worldbody><body name="b"/></worldbody></mujoco>',
        "sub/child.xml",
    )
    for reference, compiles in (("kid", True), ("child", False)):
        path = written(
            tmp_path,
            f'<mujoco><asset><model file="sub/child.xml"/></asset><worldbody>'
            f'<attach model="{reference}" body="b" prefix="c_"/></worldbody></mujoco>',
        )
        if compiles:
            mujoco.MjModel.from_xml_path(str(path))
        else:
            with pytest.raises(ValueError, match="could not find model 'child'"):
                mujoco.MjModel.from_xml_path(str(path))
    model = load(tmp_path / "model.xml")
    assert declared_names(model)["model"] == frozenset({"kid"})


def test_model_file_without_root_name_is_named_mujoco_model(tmp_path: Path) -> None:
    """A sub-model file whose root has no model attribute is named "MuJoCo Model" by MuJoCo."""
    written(tmp_path, '<mujoco><worldbody><body name="b"/></worldbody></mujoco>', "anon.xml")
    path = written(
        tmp_path,
        '<mujoco><asset><model file="anon.xml"/></asset><worldbody>'
        '<attach model="MuJoCo Model" body="b" prefix="c_"/></worldbody></mujoco>',
    )
    assert prefixed_problems(load(path), path) == []
    assert 'name="p_MuJoCo Model"' in dumps(prefixed(load(path), "p_"))


def test_attach_keeps_pointing_at_the_prefixed_model_asset() -> None:
    """After prefixing, each asset is named p_<root model> and every attach refers to it."""
    new = prefixed(load(NAMING / "attach_scene.xml"), "p_")
    text = dumps(new)
    assert '<model file="parts/gripper_v2.xml" name="p_two_finger_gripper"/>' in text
    assert '<model file="parts/rope_kid.xml" name="p_hanging_rope"/>' in text
    assert text.count('model="p_two_finger_gripper"') == 3
    assert 'body="palm" prefix="p_g1_"' in text and 'joint="p_g1_right_slide"' in text


def test_attached_generated_names_follow_the_attach_prefix() -> None:
    """MuJoCo names attached flexcomp bodies and replicated attachments prefix + name (+ copy)."""
    path = NAMING / "attach_scene.xml"
    bodies = compiled_names(compile_beside(load(path), path))["body"]
    assert {"r_rope_2", "h_left1", "h_palm0"} <= set(bodies)
    text = dumps(prefixed(load(path), "p_"))
    assert 'body1="p_pole" body2="p_r_rope_2"' in text
    assert 'body1="p_hook0" body2="p_h_left1"' in text


def test_model_without_base_dir_reads_from_the_working_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A model read from text finds its sub-model file in the working folder."""
    source = (NAMING / "attach_scene.xml").read_text(encoding="utf-8")
    monkeypatch.chdir(NAMING)
    model = loads(source)
    assert model.base_dir is None
    assert prefixed_problems(model, NAMING / "attach_scene.xml") == []
    monkeypatch.chdir(tmp_path)
    with pytest.raises(MjcfAssetError, match=r"cannot read the asset <model> file .*gripper_v2"):
        prefixed(model, "p_")


def test_unreadable_model_file_raises(tmp_path: Path) -> None:
    """An unnamed asset <model> whose file cannot be read raises, naming the file."""
    path = written(
        tmp_path,
        '<mujoco><asset><model file="gone.xml"/></asset><worldbody/></mujoco>',
    )
    with pytest.raises(MjcfAssetError, match=r"gone\.xml.*give the <model> a name") as info:
        prefixed(load(path), "p_")
    assert isinstance(info.value, OSError)
    with pytest.raises(ValueError, match=r"gone\.xml"):
        mujoco.MjModel.from_xml_path(str(path))


def test_attach_with_model_leaves_body_and_frame_alone() -> None:
    """With model, attach body names the child's body: it is not prefixed, the model is."""
    new = prefixed(load(NAMING / "attach_scene.xml"), "p_")
    text = dumps(new)
    assert 'body="left" prefix="p_g2_"' in text and 'body="palm"' in text


SAME_MODEL = """<mujoco>
  <worldbody>
    <frame name="shelf">
      <body name="src" pos="1 0 0">
        <joint name="hinge" axis="0 0 1"/>
        <geom name="block" size="0.1"/>
        <body name="inner" pos="0 0 0.3"><geom size="0.05"/></body>
      </body>
    </frame>
    <body name="mount" pos="0 1 0">
      <attach body="src" prefix="c_"/>
    </body>
    <body name="rack" pos="0 -1 0">
      <attach frame="shelf" prefix="f_"/>
    </body>
  </worldbody>
  <contact><exclude body1="c_inner" body2="src"/></contact>
  <actuator><motor name="spin" joint="c_hinge"/></actuator>
</mujoco>
"""


def test_attach_without_model_copies_from_the_same_model() -> None:
    """Without model, body and frame name this model's elements and are prefixed with it.

    MuJoCo 4.0 copies the body or frame; MuJoCo 3.9 requires model (and has no
    frame attribute). Copies are named prefix + attach prefix + prefixed name:
    every name still starts with the prefix, and references to copies follow.
    """
    model = loads(SAME_MODEL)
    new = prefixed(model, "p_")
    text = dumps(new)
    assert '<attach body="p_src" prefix="p_c_"/>' in text
    assert '<attach frame="p_shelf" prefix="p_f_"/>' in text
    assert 'body1="p_c_p_inner" body2="p_src"' in text and 'joint="p_c_p_hinge"' in text
    if MUJOCO_VERSION < (4, 0):
        with pytest.raises(ValueError, match="unrecognized attribute: 'frame'"):
            mujoco.MjModel.from_xml_string(SAME_MODEL)
        body_only = SAME_MODEL.replace('<attach frame="shelf" prefix="f_"/>', "")
        with pytest.raises(ValueError, match="required attribute missing: 'model'"):
            mujoco.MjModel.from_xml_string(body_only)
        return
    original = mujoco.MjModel.from_xml_string(SAME_MODEL)
    changed = mujoco.MjModel.from_xml_string(text)
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    copies = ("c_", "f_")
    expected = {
        kind: [
            ""
            if not old
            else "world"
            if (kind, old) == ("body", "world")
            else "p_" + old[:2] + "p_" + old[2:]
            if old.startswith(copies)
            else "p_" + old
            for old in names
        ]
        for kind, names in compiled_names(original).items()
    }
    assert compiled_names(changed) == expected
    assert "c_inner" in compiled_names(original)["body"]


# -- skins read from files ----------------------------------------------------------------


SKINNED = """<mujoco><asset><skin name="sheet" file="sheet.skn"/></asset><worldbody>
  <body name="a"><geom name="ga" size="0.05"/></body>
  <body name="b" pos="0.1 0 0"><geom name="gb" size="0.05"/></body>
  <body name="c" pos="0 0.1 0"><geom name="gc" size="0.05"/></body>
</worldbody></mujoco>"""


def test_file_skin_refuses_renaming_its_bodies(tmp_path: Path) -> None:
    """Without its folder a .skn skin cannot be read: prefixing its bodies says to inline it."""
    skin_file(tmp_path / "sheet.skn", ("a", "b", "c"))
    path = written(tmp_path, SKINNED)
    model = load(path)
    compile_beside(model, path)
    with pytest.raises(
        MjcfValueError, match=r"skin 'sheet' is read from 'sheet\.skn'.*inline_skin_files"
    ):
        prefixed(loads(SKINNED), "p_")
    with pytest.raises(MjcfValueError, match="inline_skin_files"):
        renamed(model, {"body": {"a": "z"}})
    naive = dumps(model).replace('name="a"', 'name="p_a"')
    with pytest.raises(ValueError, match="unknown body 'a' in skin"):
        compile_text_beside(naive, path)


def test_file_skin_allows_renaming_other_namespaces(tmp_path: Path) -> None:
    """Renaming only geoms leaves the skin's bodies alone: no error, MuJoCo compiles it."""
    skin_file(tmp_path / "sheet.skn", ("a", "b", "c"))
    path = written(tmp_path, SKINNED)
    model = load(path)
    original = compile_beside(model, path)
    changed = compile_beside(prefixed(model, "p_", namespaces={"geom", "skin"}), path)
    assert compiled_names(changed)["geom"] == ["p_ga", "p_gb", "p_gc"]
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []


def test_inlined_file_skin_prefixes(tmp_path: Path) -> None:
    """After inline_skin_files the skin's bones are in the tree and prefixing passes the oracle."""
    skin_file(tmp_path / "sheet.skn", ("a", "b", "c"))
    path = written(tmp_path, SKINNED)
    model = inline_skin_files(load(path), tmp_path)
    assert prefixed_problems(model, path) == []


def test_a_loaded_model_has_its_file_skin_inlined_before_prefixing(tmp_path: Path) -> None:
    """A loaded model knows where its .skn file is: prefixing inlines it, then renames."""
    skin_file(tmp_path / "sheet.skn", ("a", "b", "c"))
    path = written(tmp_path, SKINNED)
    inlined = inline_skin_files(load(path))
    assert prefixed(load(path), "p_") == prefixed(inlined, "p_")
    assert prefixed_problems(inlined, path) == []
