"""Tests of ``mjcf_model.transforms.naming.generated_names``."""

from __future__ import annotations

import os
import re
from pathlib import Path

import attrs
import mujoco
import pytest

from mjcf_model import Body, GenericElement
from mjcf_model.bridge.compare import compile_text_beside, compiled_names, model_differences
from mjcf_model.errors import MjcfAssetError, MjcfError
from mjcf_model.nodes.base import TypedElement
from mjcf_model.serializers import dumps, from_dict, from_etree, load, loads, to_dict, to_etree
from mjcf_model.tools.check import check_file
from mjcf_model.transforms.naming.generated_names import (
    GeneratedNames,
    copy_suffix,
    model_file_name,
)
from mjcf_model.transforms.naming.renaming import declared_names, prefix_map, prefixed, renamed
from mjcf_model.tree.traversal import walk
from tests.conftest import FIXTURES, MUJOCO_VERSION
from tests.support.oracles import (
    RENAMING_FIELDS,
    compile_beside,
    prefix_problems,
    prefixed_problems,
    written,
)

# -- Prefixing names MuJoCo makes while reading: replicate copies, flexcomp bodies, attachments.
#
# MuJoCo is the referee: the original and the prefixed model must compile to the
# same arrays with every name prefixed (``prefix_problems``), or, where MuJoCo
# cannot compile a construct (MuJoCo 3.9 has no ``<attach>`` without ``model``),
# the test asserts what MuJoCo does.


NAMING = FIXTURES / "naming"
#: Every naming fixture, the attached parts in ``parts/`` included (hidden files are
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


# -- Names MuJoCo makes while reading (copies, flexcomp bodies, attachments) and renaming them.
#
# MuJoCo is the referee: each test compiles the original and the renamed or
# prefixed model and compares the names MuJoCo gives, or, for the names of asset
# ``<model>`` files, checks that MuJoCo finds the model by the name expected.


#: A child model: a root body with two bodies below it, one named like a copy suffix.
CHILD = """<mujoco model="kid"><worldbody>
  <body name="palm"><geom size="0.1"/>
    <body name="x1" pos="0 0 0.3"><geom size="0.05"/></body>
    <body name="_2" pos="0 0.3 0"><geom size="0.05"/></body>
  </body>
</worldbody></mujoco>"""


def written_generated_names(folder: Path, text: str, name: str) -> Path:
    """Write ``text`` to ``folder / name`` and return the path."""
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def body_names(model: mujoco.MjModel) -> list[str]:
    """The names MuJoCo gives the bodies, in id order."""
    return compiled_names(model)["body"]


def prefixed_problems_of(path: Path, prefix: str = "p_") -> list[str]:
    """What keeps the prefixed model at ``path`` from compiling with every name prefixed."""
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = compile_text_beside(dumps(prefixed(load(path), prefix)), path)
    return prefix_problems(original, changed, prefix)


# -- asset <model> files ------------------------------------------------------------------


def test_unreadable_model_file_message_names_the_file_and_the_error(tmp_path: Path) -> None:
    """The error names the missing file and the operating system's reason, then the remedies."""
    missing = tmp_path / "gone.xml"
    with pytest.raises(OSError) as os_error:
        missing.stat()
    expected = (
        f"cannot read the asset <model> file {str(missing)!r} to find the name MuJoCo gives it "
        f"(its root's model attribute): {os_error.value}; give the <model> a name, or load the "
        "model from its folder so that base_dir locates the file"
    )
    with pytest.raises(MjcfAssetError, match=f"^{re.escape(expected)}$") as info:
        model_file_name(missing)
    assert isinstance(info.value, MjcfError)
    path = written_generated_names(
        tmp_path, '<mujoco><asset><model file="gone.xml"/></asset></mujoco>', "m.xml"
    )
    with pytest.raises(ValueError, match=r"gone\.xml"):
        mujoco.MjModel.from_xml_path(str(path))


def attaching(folder: Path, name: str) -> Path:
    """A model attaching the unnamed asset ``<model file="child.xml">`` by the name ``name``."""
    return written_generated_names(
        folder,
        f'<mujoco><asset><model file="child.xml"/></asset><worldbody>'
        f'<attach model="{name}" body="palm" prefix="c_"/></worldbody></mujoco>',
        "scene.xml",
    )


def assert_mujoco_names_the_file(folder: Path, name: str, stale: str) -> None:
    """MuJoCo finds the child model by ``name`` and not by ``stale``."""
    assert "c_palm" in body_names(mujoco.MjModel.from_xml_path(str(attaching(folder, name))))
    with pytest.raises(ValueError, match=f"could not find model '{stale}'"):
        mujoco.MjModel.from_xml_path(str(attaching(folder, stale)))


def test_model_file_name_follows_a_rewrite_with_the_same_size(tmp_path: Path) -> None:
    """A file rewritten to the same size at a new time is read again, as MuJoCo reads it."""
    child = written_generated_names(tmp_path, CHILD.replace('"kid"', '"aa"'), "child.xml")
    assert model_file_name(child) == "aa"
    stat = child.stat()
    child.write_text(CHILD.replace('"kid"', '"bb"'), encoding="utf-8")
    os.utime(child, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9))
    assert child.stat().st_size == stat.st_size
    assert model_file_name(child) == "bb"
    assert_mujoco_names_the_file(tmp_path, "bb", "aa")


def test_model_file_name_follows_a_rewrite_with_the_same_time(tmp_path: Path) -> None:
    """A file rewritten to another size with the same time is read again."""
    child = written_generated_names(tmp_path, CHILD.replace('"kid"', '"short"'), "child.xml")
    assert model_file_name(child) == "short"
    stat = child.stat()
    child.write_text(CHILD.replace('"kid"', '"much_longer"'), encoding="utf-8")
    os.utime(child, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    assert child.stat().st_mtime_ns == stat.st_mtime_ns
    assert model_file_name(child) == "much_longer"
    assert_mujoco_names_the_file(tmp_path, "much_longer", "short")


def test_generated_names_of_a_loaded_model_read_model_files_from_its_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A loaded model knows its folder: its unnamed <model> is named by the file's root there."""
    written_generated_names(tmp_path, CHILD, "child.xml")
    path = written_generated_names(
        tmp_path,
        '<mujoco><asset><model file="child.xml"/></asset><worldbody>'
        '<attach model="kid" body="palm" prefix="c_"/></worldbody></mujoco>',
        "scene.xml",
    )
    assert "c_palm" in body_names(mujoco.MjModel.from_xml_path(str(path)))
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    assert set(GeneratedNames.of(load(path)).declared["model"]) == {"kid"}


# -- replicate copies ---------------------------------------------------------------------


def test_copy_suffix_is_the_suffix_mujoco_gives_each_copy() -> None:
    """``name + copy_suffix(replicate, i)`` is MuJoCo's name of copy i (sep, index padded)."""
    text = """<mujoco><worldbody>
      <replicate count="12" sep="_" offset="0.2 0 0"><body name="post"><geom size="0.1"/></body>
      </replicate>
      <replicate count="3" offset="0 0.3 0"><body name="cell"><geom size="0.1"/></body>
      </replicate></worldbody></mujoco>"""
    world = loads(text).worldbody
    assert world is not None
    posts, cells = world.children
    assert isinstance(posts, TypedElement | GenericElement)
    assert isinstance(cells, TypedElement | GenericElement)
    bodies = body_names(mujoco.MjModel.from_xml_string(text))
    expected = [f"post_{i:02d}" for i in range(12)] + [f"cell{i}" for i in range(3)]
    assert bodies[1:] == expected
    assert [f"post{copy_suffix(posts, i)}" for i in range(12)] == expected[:12]
    assert [f"cell{copy_suffix(cells, i)}" for i in range(3)] == expected[12:]


def test_reference_to_the_copy_of_a_single_copy_replicate_follows_it() -> None:
    """``count="1"`` still suffixes: MuJoCo names the copy b0, and a reference to b0 follows b."""
    text = """<mujoco><worldbody><body name="a"><geom size="0.1"/></body>
      <replicate count="1"><body name="b" pos="0 0 1"><geom size="0.1"/></body></replicate>
      </worldbody><contact><exclude body1="a" body2="b0"/></contact></mujoco>"""
    original = mujoco.MjModel.from_xml_string(text)
    assert body_names(original) == ["world", "a", "b0"]
    changed = mujoco.MjModel.from_xml_string(dumps(prefixed(loads(text), "p_")))
    assert prefix_problems(original, changed, "p_") == []


# -- attachments --------------------------------------------------------------------------


def test_attached_names_are_not_renamed_with_the_parent_names_they_end_with(
    tmp_path: Path,
) -> None:
    """With model, g_palm is the child's palm: prefixing makes it p_g_palm, not p_g_p_palm."""
    written_generated_names(tmp_path, CHILD, "child.xml")
    path = written_generated_names(
        tmp_path,
        """<mujoco><asset><model file="child.xml"/></asset><worldbody>
          <body name="palm"><geom size="0.1"/></body>
          <body name="mount" pos="1 0 0"><attach model="kid" body="palm" prefix="g_"/></body>
        </worldbody><contact><exclude body1="palm" body2="g_palm"/>
        <exclude body1="palm" body2="g_x1"/></contact></mujoco>""",
        "scene.xml",
    )
    assert prefixed_problems_of(path) == []


def test_attach_with_an_empty_prefix_gains_the_prefix(tmp_path: Path) -> None:
    """``prefix=""`` brings the child's names in as they are; prefixing prefixes them too."""
    written_generated_names(tmp_path, CHILD, "child.xml")
    path = written_generated_names(
        tmp_path,
        """<mujoco><asset><model file="child.xml"/></asset><worldbody>
          <body name="mount"><attach model="kid" body="palm" prefix=""/></body>
        </worldbody><contact><exclude body1="mount" body2="x1"/></contact></mujoco>""",
        "scene.xml",
    )
    assert "x1" in body_names(mujoco.MjModel.from_xml_path(str(path)))
    assert prefixed_problems_of(path) == []


def test_renaming_leaves_attached_names_alone(tmp_path: Path) -> None:
    """Renaming the parent's bodies (no attach prefix) keeps references to attached bodies."""
    written_generated_names(tmp_path, CHILD, "child.xml")
    path = written_generated_names(
        tmp_path,
        """<mujoco><asset><model file="child.xml"/></asset><worldbody>
          <body name="mount"><attach model="kid" body="palm" prefix="g_"/></body>
        </worldbody><contact><exclude body1="mount" body2="g_x1"/></contact></mujoco>""",
        "scene.xml",
    )
    original = mujoco.MjModel.from_xml_path(str(path))
    expected = ["world", "base", "g_palm", "g_x1", "g__2"]
    assert body_names(original) == ["world", "mount", *expected[2:]]
    for new in (
        renamed(load(path), {"body": {"mount": "base"}}),
        prefixed(load(path), "p_", namespaces={"body"}, exclude={"mount"}),
    ):
        changed = compile_text_beside(dumps(new), path)
        assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    changed = compile_text_beside(dumps(renamed(load(path), {"body": {"mount": "base"}})), path)
    assert body_names(changed) == expected


def test_attached_names_that_look_like_copies_are_not_copies(tmp_path: Path) -> None:
    """bx1 and b_2 are attached (prefix b), not copies of the replicated b: they keep their names.

    MuJoCo names the copies b-0 and b-1; renaming b to z renames them only.
    """
    written_generated_names(tmp_path, CHILD, "child.xml")
    path = written_generated_names(
        tmp_path,
        """<mujoco><asset><model file="child.xml"/></asset><worldbody>
          <replicate count="2" sep="-" offset="1 0 0"><body name="b"><geom size="0.1"/></body>
          </replicate>
          <replicate count="3" sep="_" offset="0 1 0"><body name="c"><geom size="0.1"/></body>
          </replicate>
          <body name="mount" pos="0 0 1"><attach model="kid" body="palm" prefix="b"/></body>
        </worldbody><contact><exclude body1="bx1" body2="b-0"/>
        <exclude body1="b_2" body2="b-1"/></contact></mujoco>""",
        "scene.xml",
    )
    original = mujoco.MjModel.from_xml_path(str(path))
    assert {"b-0", "b-1", "bx1", "b_2"} <= set(body_names(original))
    changed = compile_text_beside(dumps(renamed(load(path), {"body": {"b": "z"}})), path)
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    assert body_names(changed) == [
        {"b-0": "z-0", "b-1": "z-1"}.get(name, name) for name in body_names(original)
    ]


def test_an_attached_name_ending_like_a_copy_of_another_replicate_stays(tmp_path: Path) -> None:
    """b-1 is attached (prefix b-); b, outside every replicate, has no copies: b-1 keeps its name.

    The replicate's separator ``-`` makes b-1 look like a copy of b; MuJoCo only
    copies what a replicate holds (c-0 and c-1 here).
    """
    written_generated_names(tmp_path, CHILD.replace('name="x1"', 'name="1"'), "child.xml")
    path = written_generated_names(
        tmp_path,
        """<mujoco><asset><model file="child.xml"/></asset><worldbody>
          <body name="b"><geom size="0.1"/></body>
          <replicate count="2" sep="-" offset="1 0 0"><body name="c"><geom size="0.1"/></body>
          </replicate>
          <body name="mount" pos="0 0 1"><attach model="kid" body="1" prefix="b-"/></body>
        </worldbody><contact><exclude body1="b-1" body2="c-0"/></contact></mujoco>""",
        "scene.xml",
    )
    original = mujoco.MjModel.from_xml_path(str(path))
    assert {"b", "b-1", "c-0", "c-1"} <= set(body_names(original))
    changed = compile_text_beside(dumps(renamed(load(path), {"body": {"b": "z"}})), path)
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    assert body_names(changed) == [{"b": "z"}.get(name, name) for name in body_names(original)]


def test_reference_equal_to_an_attach_prefix_is_not_an_attached_name(tmp_path: Path) -> None:
    """Prefixing one body: a camera there aimed at the parent's body g_ keeps aiming at it.

    The body's attach has prefix g_, but g_ itself is the parent model's body, not
    one the attach brings in; the prefixed body's own names all get the prefix.
    """
    written_generated_names(tmp_path, CHILD, "child.xml")
    path = written_generated_names(
        tmp_path,
        """<mujoco><asset><model file="child.xml"/></asset><worldbody>
          <body name="g_" pos="0 0 1"><geom size="0.1"/></body>
          <body name="rig" pos="1 0 0"><geom size="0.1"/>
            <camera name="eye" mode="targetbody" target="g_"/>
            <attach model="kid" body="palm" prefix="g_"/></body>
        </worldbody></mujoco>""",
        "scene.xml",
    )
    model = load(path)
    world = model.worldbody
    assert world is not None
    rig = world.children[1]
    assert isinstance(rig, Body)
    new_world = attrs.evolve(
        world, children=tuple(prefixed(rig, "p_") if c is rig else c for c in world.children)
    )
    new = attrs.evolve(
        model, children=tuple(new_world if c is world else c for c in model.children)
    )
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = compile_text_beside(dumps(new), path)
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    assert body_names(changed) == ["world", "g_", "p_rig", "p_g_palm", "p_g_x1", "p_g__2"]
    assert compiled_names(changed)["cam"] == ["p_eye"]
    assert body_names(changed)[changed.cam_targetbodyid[0]] == "g_"


# -- flexcomp bodies ----------------------------------------------------------------------


def test_a_flexcomp_with_an_empty_name_makes_nothing_to_rename() -> None:
    """``name=""`` declares no name: MuJoCo names its bodies _0, _1...; renaming "" changes none."""
    text = """<mujoco><worldbody><body name="a"><geom size="0.03"/></body>
      <flexcomp name="" type="grid" dim="1" count="3 1 1" spacing="0.05 0.05 0.05"
                radius="0.01" mass="0.1"><edge equality="true"/></flexcomp></worldbody>
      <contact><exclude body1="a" body2="_1"/></contact></mujoco>"""
    original = mujoco.MjModel.from_xml_string(text)
    assert body_names(original) == ["world", "a", "_0", "_1", "_2"]
    new = renamed(loads(text), {"flex": {"": "cord"}, "body": {"a": "anchor"}})
    changed = mujoco.MjModel.from_xml_string(dumps(new))
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    assert body_names(changed) == ["world", "anchor", "_0", "_1", "_2"]


def test_attached_like_names_of_flexcomp_bodies_are_not_flexcomp_bodies(tmp_path: Path) -> None:
    """rope_x1 is attached (prefix rope_), not a body of the flexcomp rope: it keeps its name.

    MuJoCo names the flexcomp's bodies rope_0, rope_1, rope_2; renaming the flex
    rope to cord renames those only.
    """
    written_generated_names(tmp_path, CHILD, "child.xml")
    path = written_generated_names(
        tmp_path,
        """<mujoco><asset><model file="child.xml"/></asset><worldbody>
          <flexcomp name="rope" type="grid" dim="1" count="3 1 1" spacing="0.05 0.05 0.05"
                    radius="0.01" mass="0.1"><edge equality="true"/></flexcomp>
          <body name="mount" pos="0 0 1"><attach model="kid" body="palm" prefix="rope_"/></body>
        </worldbody><contact><exclude body1="rope_x1" body2="rope_1"/></contact></mujoco>""",
        "scene.xml",
    )
    original = mujoco.MjModel.from_xml_path(str(path))
    assert {"rope_0", "rope_1", "rope_2", "rope_x1"} <= set(body_names(original))
    changed = compile_text_beside(dumps(renamed(load(path), {"flex": {"rope": "cord"}})), path)
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    assert body_names(changed) == [
        f"cord_{name[5:]}" if name in ("rope_0", "rope_1", "rope_2") else name
        for name in body_names(original)
    ]


def test_an_excluded_name_that_starts_with_an_attach_prefix_stays(tmp_path: Path) -> None:
    """g_hand is the parent's own body: excluded, it stays, though attached names gain p_."""
    written_generated_names(tmp_path, CHILD, "child.xml")
    path = written_generated_names(
        tmp_path,
        """<mujoco><asset><model file="child.xml"/></asset><worldbody>
          <body name="g_hand"><geom size="0.1"/></body>
          <body name="mount" pos="0 0 1"><attach model="kid" body="palm" prefix="g_"/></body>
        </worldbody><contact><exclude body1="g_hand" body2="g_x1"/></contact></mujoco>""",
        "scene.xml",
    )
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = compile_text_beside(dumps(prefixed(load(path), "p_", exclude={"g_hand"})), path)
    assert prefix_problems(original, changed, "p_", kept={"g_hand"}) == []
