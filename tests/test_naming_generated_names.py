"""Names MuJoCo makes while reading (copies, flexcomp bodies, attachments) and renaming them.

MuJoCo is the referee: each test compiles the original and the renamed or
prefixed model and compares the names MuJoCo gives, or, for the names of asset
``<model>`` files, checks that MuJoCo finds the model by the name expected.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import attrs
import mujoco
import pytest

from mjcf_model import Body
from mjcf_model.bridge.compare import compile_text_beside, compiled_names, model_differences
from mjcf_model.errors import MjcfAssetError, MjcfError
from mjcf_model.nodes.base import GenericElement, TypedElement
from mjcf_model.transforms.naming.generated_names import (
    GeneratedNames,
    copy_suffix,
    model_file_name,
)
from mjcf_model.transforms.naming.renaming import prefixed, renamed
from serializers import dumps, load, loads
from tests.support.oracles import RENAMING_FIELDS, prefix_problems

#: A child model: a root body with two bodies below it, one named like a copy suffix.
CHILD = """<mujoco model="kid"><worldbody>
  <body name="palm"><geom size="0.1"/>
    <body name="x1" pos="0 0 0.3"><geom size="0.05"/></body>
    <body name="_2" pos="0 0.3 0"><geom size="0.05"/></body>
  </body>
</worldbody></mujoco>"""


def written(folder: Path, text: str, name: str) -> Path:
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
    path = written(tmp_path, '<mujoco><asset><model file="gone.xml"/></asset></mujoco>', "m.xml")
    with pytest.raises(ValueError, match=r"gone\.xml"):
        mujoco.MjModel.from_xml_path(str(path))


def attaching(folder: Path, name: str) -> Path:
    """A model attaching the unnamed asset ``<model file="child.xml">`` by the name ``name``."""
    return written(
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
    child = written(tmp_path, CHILD.replace('"kid"', '"aa"'), "child.xml")
    assert model_file_name(child) == "aa"
    stat = child.stat()
    child.write_text(CHILD.replace('"kid"', '"bb"'), encoding="utf-8")
    os.utime(child, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9))
    assert child.stat().st_size == stat.st_size
    assert model_file_name(child) == "bb"
    assert_mujoco_names_the_file(tmp_path, "bb", "aa")


def test_model_file_name_follows_a_rewrite_with_the_same_time(tmp_path: Path) -> None:
    """A file rewritten to another size with the same time is read again."""
    child = written(tmp_path, CHILD.replace('"kid"', '"short"'), "child.xml")
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
    written(tmp_path, CHILD, "child.xml")
    path = written(
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
    written(tmp_path, CHILD, "child.xml")
    path = written(
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
    written(tmp_path, CHILD, "child.xml")
    path = written(
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
    written(tmp_path, CHILD, "child.xml")
    path = written(
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
    written(tmp_path, CHILD, "child.xml")
    path = written(
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
    written(tmp_path, CHILD.replace('name="x1"', 'name="1"'), "child.xml")
    path = written(
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
    written(tmp_path, CHILD, "child.xml")
    path = written(
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
    written(tmp_path, CHILD, "child.xml")
    path = written(
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
    written(tmp_path, CHILD, "child.xml")
    path = written(
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
