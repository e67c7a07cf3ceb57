"""Tests of ``mjcf_model.transforms.naming.renaming``."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import mujoco
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import Body, Geom, Mujoco, compiled
from mjcf_model.bridge.compare import compile_text_beside, compiled_names, model_differences
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.nodes.base import get_attribute
from mjcf_model.serializers import dumps, load, loads, to_dict
from mjcf_model.serializers.skins import inline_skin_files
from mjcf_model.strategies import models, names
from mjcf_model.transforms.composition.attaching import attach
from mjcf_model.transforms.naming.renaming import declared_names, prefix_map, prefixed, renamed
from mjcf_model.transforms.scaling.transform import scaled
from tests.conftest import compiling_corpus, corpus_id
from tests.support.oracles import (
    RENAMING_FIELDS,
    compile_beside,
    prefix_problems,
    prefixed_problems,
    written,
)
from tests.support.skin_files import skin_file

# -- Prefixing and renaming: exact, reference-aware, checked by MuJoCo. ------------------------


CORPUS = compiling_corpus()


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_prefixed_corpus_model_compiles_with_every_name_prefixed(path: Path) -> None:
    """A prefixed corpus model compiles to the same arrays with every name prefixed.

    Binary skin files name their bodies inside the file, so they are written inline first.
    """
    model = inline_skin_files(load(path, inline_includes=True))
    original = compiled(model)
    changed = compiled(prefixed(model, "pre_"))
    assert prefix_problems(original, changed, "pre_") == []


@given(models(), names(), names())
def test_prefixing_composes(model: Mujoco, first: str, second: str) -> None:
    """``prefixed(prefixed(m, a), b) == prefixed(m, b + a)`` and the input is untouched."""
    snapshot = to_dict(model)
    assert prefixed(prefixed(model, first), second) == prefixed(model, second + first)
    assert to_dict(model) == snapshot


@given(models(), names())
def test_prefixed_model_compiles_to_the_same_arrays(model: Mujoco, prefix: str) -> None:
    """Compiling a prefixed drawn model changes every name and nothing else."""
    original = mujoco.MjModel.from_xml_string(dumps(model))
    changed = mujoco.MjModel.from_xml_string(dumps(prefixed(model, prefix)))
    assert prefix_problems(original, changed, prefix) == []


@given(models())
def test_renaming_with_the_prefix_map_is_prefixing(model: Mujoco) -> None:
    """``renamed(m, prefix_map(m, p)) == prefixed(m, p)``."""
    assert renamed(model, prefix_map(model, "x_")) == prefixed(model, "x_")


@given(models())
def test_renaming_to_the_same_names_shares_the_tree(model: Mujoco) -> None:
    """A renaming that changes nothing returns the input itself."""
    identity = {ns: {n: n for n in found} for ns, found in declared_names(model).items()}
    assert renamed(model, identity) is model
    assert prefixed(model, "") is model


def test_references_follow_in_every_section() -> None:
    """Sensors, actuators, tendons, equality, contact, keyframes and assets follow their names."""
    model = loads(
        """<mujoco>
          <default><default class="arm"><geom material="steel"/></default></default>
          <asset><texture name="t" builtin="flat" width="8" height="8"/>
            <material name="steel" texture="t"/><mesh name="m" vertex="0 0 0 1 0 0 0 1 0 0 0 1"/>
          </asset>
          <worldbody><body name="b" childclass="arm"><joint name="j"/>
            <geom name="g" mesh="m" type="mesh"/><site name="s"/><camera name="c" target="b"/>
          </body></worldbody>
          <tendon><spatial name="tn"><site site="s"/><geom geom="g" sidesite="s"/><site site="s"/>
            </spatial>
            <fixed name="fx"><joint joint="j" coef="1"/></fixed></tendon>
          <equality><connect body1="b" anchor="0 0 0" site1="s"/><joint joint1="j"/></equality>
          <contact><pair geom1="g" geom2="g"/><exclude body1="b" body2="world"/></contact>
          <actuator><motor name="a" joint="j"/><general site="s" refsite="s"/>
            <general tendon="tn"/></actuator>
          <sensor><framepos objtype="xbody" objname="b" reftype="site" refname="s"/>
            <actuatorfrc actuator="a"/><user objtype="camera" objname="c" dim="1"/></sensor>
          <keyframe><key name="home"/></keyframe>
          <custom><tuple name="tu"><element objtype="geom" objname="g" prm="1"/></tuple></custom>
        </mujoco>"""
    )
    text = dumps(prefixed(model, "p_"))
    for attribute in [
        'class="p_arm"',
        'childclass="p_arm"',
        'material="p_steel"',
        'texture="p_t"',
        'mesh="p_m"',
        'target="p_b"',
        'site="p_s"',
        'geom="p_g"',
        'sidesite="p_s"',
        'joint="p_j"',
        'body1="p_b"',
        'site1="p_s"',
        'joint1="p_j"',
        'geom1="p_g"',
        'body2="world"',
        'refsite="p_s"',
        'tendon="p_tn"',
        'objname="p_b"',
        'refname="p_s"',
        'actuator="p_a"',
        'objname="p_c"',
        'objname="p_g"',
        'name="p_home"',
        'name="p_tu"',
    ]:
        assert attribute in text, attribute


def test_file_named_assets_get_an_explicit_prefixed_name() -> None:
    """A mesh named by its file stem is named explicitly, and geoms follow."""
    model = loads(
        '<mujoco><asset><mesh file="parts/hand.stl"/></asset>'
        '<worldbody><geom type="mesh" mesh="hand"/></worldbody></mujoco>'
    )
    new = prefixed(model, "r_")
    assert new.asset is not None and new.asset.meshes[0].name == "r_hand"
    assert new.worldbody is not None and new.worldbody.geoms[0].mesh == "r_hand"


def test_flex_body_lists_are_prefixed_name_by_name() -> None:
    """Space-separated reference lists (flex ``body``) are prefixed item by item."""
    model = loads(
        '<mujoco><worldbody><body name="a"/><body name="b"/></worldbody>'
        '<deformable><flex name="f" dim="1" body="a  b" vertex="0 0 0 1 0 0" element="0 1"/>'
        "</deformable></mujoco>"
    )
    flex = prefixed(model, "p_").children[1].children[0]
    assert flex.body == "p_a p_b"


def test_attach_prefix_gains_the_prefix() -> None:
    """Names an ``<attach>`` brings in are prefixed through its ``prefix`` attribute."""
    model = loads(
        '<mujoco><asset><model name="arm" file="arm.xml"/></asset>'
        '<worldbody><body name="b"><attach model="arm" body="base" prefix="left/"/></body>'
        "</worldbody></mujoco>"
    )
    attach = prefixed(model, "p_").worldbody.bodies[0].children[0]
    assert (attach.model, attach.body, attach.prefix) == ("p_arm", "base", "p_left/")
    only_bodies = prefixed(model, "p_", namespaces={"body"}).worldbody.bodies[0]
    assert only_bodies.children[0].prefix == "left/"


def test_undeclared_references_stay_unless_asked() -> None:
    """References into a parent model are kept, or prefixed with ``undeclared=True``."""
    body = Body(name="b", children=[Geom(name="g", material="outside")])
    assert prefixed(body, "p_").geoms[0].material == "outside"
    assert prefixed(body, "p_", undeclared=True).geoms[0].material == "p_outside"


def test_exclude_and_namespaces_limit_prefixing() -> None:
    """``exclude`` (names or a predicate) and ``namespaces`` choose what is prefixed."""
    body = Body(name="b", children=[Geom(name="g"), Geom(name="keep")])
    assert [g.name for g in prefixed(body, "p_", exclude={"keep"}).geoms] == ["p_g", "keep"]
    assert [g.name for g in prefixed(body, "p_", exclude=lambda n: n == "g").geoms] == [
        "g",
        "p_keep",
    ]
    only_geoms = prefixed(body, "p_", namespaces={"geom"})
    assert only_geoms.name == "b"
    with pytest.raises(MjcfValueError, match=r"unknown namespace.*'bodies'"):
        prefixed(body, "p_", namespaces={"bodies"})


def test_main_default_class_is_never_renamed() -> None:
    """MuJoCo refuses to rename the top-level class ``main``; prefixing leaves it."""
    model = loads(
        '<mujoco><default class="main"><default class="arm"/></default>'
        '<worldbody><geom class="arm" size="1"/></worldbody></mujoco>'
    )
    text = dumps(prefixed(model, "p_"))
    assert 'class="main"' in text and 'class="p_arm"' in text
    mujoco.MjModel.from_xml_string(text)


def test_flat_renaming_applies_in_every_namespace() -> None:
    """A flat map renames a name in every namespace it is declared in."""
    body = Body(name="x", children=[Geom(name="x")])
    new = renamed(body, {"x": "y"})
    assert (new.name, new.geoms[0].name) == ("y", "y")


def test_includes_are_refused() -> None:
    """A model with kept includes cannot be prefixed: the included names are not in the tree."""
    model = loads('<mujoco><include file="other.xml"/></mujoco>')
    with pytest.raises(MjcfValueError, match="inline_includes=True"):
        prefixed(model, "p_")


@pytest.mark.parametrize(
    ("transform", "action"),
    [
        (lambda m: prefixed(m, "p_"), "rename names in"),
        (lambda m: scaled(m, 2), "scale"),
        (lambda m: attach(loads("<mujoco/>"), m, prefix="p_"), "attach"),
    ],
)
def test_composites_are_refused(transform: Any, action: str) -> None:
    """A <composite> makes names and sizes outside the tree: every transform says so."""
    model = loads(
        '<mujoco><worldbody><body name="rope"><composite type="cable" prefix="r" count="5 1 1" '
        'size="1" curve="s"><geom type="capsule" size=".01"/></composite></body></worldbody>'
        "</mujoco>"
    )
    with pytest.raises(MjcfValueError, match=f"cannot {action} .*<composite>.*<replicate>"):
        transform(model)


@given(st.text(min_size=1, max_size=5))
def test_prefix_map_lists_only_declared_names(prefix: str) -> None:
    """The prefix map has one entry per declared, non-excluded name."""
    body = Body(name="b", children=[Geom(name="g"), Geom(material="m")])
    assert prefix_map(body, prefix) == {"body": {"b": prefix + "b"}, "geom": {"g": prefix + "g"}}


# -- Prefixing part of a model: chosen namespaces, excluded names, partial renaming maps. ------
#
# MuJoCo is the referee: each renamed model is compiled and the names MuJoCo gives
# are compared with the original's, prefixed or mapped by the rule asked for
# (names outside the chosen namespaces and excluded names stay as they are).


ARM = """<mujoco><asset><material name="red" rgba="1 0 0 1"/></asset><worldbody>
  <body name="arm"><joint name="elbow"/><geom name="upper" size="0.1" material="red"/>
    <body name="hand" pos="0 0 0.3"><joint name="wrist"/><geom name="palm" size="0.05"/></body>
  </body></worldbody>
  <actuator><motor name="lift" joint="elbow"/><motor name="turn" joint="wrist"/></actuator>
</mujoco>"""

#: MuJoCo's kinds of names, and the namespace of each.
NAMESPACE_OF_KIND = {
    "body": "body",
    "jnt": "joint",
    "geom": "geom",
    "mat": "material",
    "actuator": "actuator",
}


def mujoco_names(model: mujoco.MjModel) -> dict[str, list[str]]:
    """The names MuJoCo gives, by namespace (the kinds of ``NAMESPACE_OF_KIND``)."""
    names = compiled_names(model)
    return {namespace: names[kind] for kind, namespace in NAMESPACE_OF_KIND.items()}


def expected_names(
    original: mujoco.MjModel, prefix: str, namespaces: set[str], excluded: set[str]
) -> dict[str, list[str]]:
    """The original's names with ``prefix`` in the chosen namespaces, except excluded ones."""
    return {
        namespace: [
            prefix + name
            if namespace in namespaces and name not in excluded and name not in ("", "world")
            else name
            for name in names
        ]
        for namespace, names in mujoco_names(original).items()
    }


def test_prefix_map_lists_the_chosen_names_mujoco_declares() -> None:
    """The map holds each chosen namespace's names but excluded ones; none with nothing left."""
    original = mujoco.MjModel.from_xml_string(ARM)
    model = loads(ARM)
    chosen, excluded = {"body", "geom", "material"}, {"hand", "upper", "red"}
    expected = {
        namespace: {name: "p_" + name for name in names if name not in excluded | {"world"}}
        for namespace, names in mujoco_names(original).items()
        if namespace in chosen
    }
    expected = {namespace: names for namespace, names in expected.items() if names}
    assert expected == {"body": {"arm": "p_arm"}, "geom": {"palm": "p_palm"}}
    mapping = prefix_map(model, "p_", namespaces=chosen, exclude=excluded)
    assert mapping == expected
    changed = mujoco.MjModel.from_xml_string(dumps(renamed(model, mapping)))
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    assert mujoco_names(changed) == expected_names(original, "p_", chosen, excluded)


@pytest.mark.parametrize(
    ("namespaces", "excluded"),
    [({"body", "joint"}, set()), ({"body", "joint", "geom"}, {"upper", "wrist"})],
    ids=["namespaces", "excluded"],
)
def test_prefixing_undeclared_references_keeps_what_is_not_chosen(
    namespaces: set[str], excluded: set[str]
) -> None:
    """With ``undeclared=True`` too, only chosen namespaces change, and excluded names stay."""
    original = mujoco.MjModel.from_xml_string(ARM)
    new = prefixed(loads(ARM), "p_", namespaces=namespaces, exclude=excluded, undeclared=True)
    changed = mujoco.MjModel.from_xml_string(dumps(new))
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    assert mujoco_names(changed) == expected_names(original, "p_", namespaces, excluded)


@pytest.mark.parametrize(
    "mapping",
    [
        {"arm": "base", "elbow": "shoulder"},
        {"body": {"arm": "base"}, "joint": {"elbow": "shoulder"}},
    ],
    ids=["flat", "by-namespace"],
)
def test_names_a_renaming_does_not_mention_stay(mapping: dict[str, object]) -> None:
    """Names missing from the map (geoms, the material, the motors, hand, wrist) keep theirs."""
    original = mujoco.MjModel.from_xml_string(ARM)
    changed = mujoco.MjModel.from_xml_string(dumps(renamed(loads(ARM), mapping)))  # type: ignore[arg-type]
    assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
    expected = mujoco_names(original)
    expected["body"] = ["world", "base", "hand"]
    expected["joint"] = ["shoulder", "wrist"]
    assert mujoco_names(changed) == expected


def test_excluding_a_name_still_prefixes_attached_names(tmp_path: Path) -> None:
    """With every namespace and an exclusion, the attach prefix gains the prefix as well."""
    (tmp_path / "child.xml").write_text(
        '<mujoco model="kid"><worldbody><body name="palm"><geom size="0.1"/>'
        '<body name="x1" pos="0 0 0.3"><geom size="0.05"/></body></body></worldbody></mujoco>',
        encoding="utf-8",
    )
    path = tmp_path / "scene.xml"
    path.write_text(
        """<mujoco><asset><model file="child.xml"/></asset><worldbody>
          <body name="mount"><geom name="base" size="0.1"/>
            <attach model="kid" body="palm" prefix="g_"/></body>
        </worldbody><contact><exclude body1="mount" body2="g_x1"/></contact></mujoco>""",
        encoding="utf-8",
    )
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = compile_text_beside(dumps(prefixed(load(path), "p_", exclude={"base"})), path)
    assert prefix_problems(original, changed, "p_", kept={"base"}) == []


def test_excluding_with_a_namespace_that_declares_nothing() -> None:
    """A camera aimed at the world body (no body is declared) compiles after prefixing."""
    text = """<mujoco><worldbody><geom name="floor" type="plane" size="1 1 0.1"/>
      <camera name="eye" mode="targetbody" target="world"/></worldbody></mujoco>"""
    original = mujoco.MjModel.from_xml_string(text)
    changed = mujoco.MjModel.from_xml_string(dumps(prefixed(loads(text), "p_", exclude={"x"})))
    assert prefix_problems(original, changed, "p_") == []
    assert changed.cam_targetbodyid[0] == 0


def test_a_name_list_renaming_leaves_alone_is_the_input_node() -> None:
    """A flex's body list with nothing renamed stays the same node (unchanged parts are shared).

    Its two spaces are kept too: only a list holding a renamed name is written again.
    """
    text = """<mujoco><worldbody>
      <body name="b1"><joint type="free"/><geom size="0.1"/></body>
      <body name="b2" pos="0 1 0"><joint type="free"/><geom size="0.1"/></body></worldbody>
      <deformable><flex name="f" dim="1" body="b1  b2" element="0 1" vertex="0 0 0 0 0 0"/>
      </deformable></mujoco>"""
    model = loads(text)
    flex = model.deformable.children[0]
    unchanged = renamed(model, {"geom": {"nothing": "else"}, "body": {"b3": "b4"}})
    assert unchanged.deformable.children[0] is flex
    changed = renamed(model, {"body": {"b1": "z1"}})
    assert get_attribute(changed.deformable.children[0], "body") == "z1 b2"
    names = compiled_names(mujoco.MjModel.from_xml_string(dumps(changed)))["body"]
    assert names == ["world", "z1", "b2"]


# -- Renaming bodies whose names a skin reads from its ``.skn`` file. --------------------------
#
# A skin file names the bodies its bones bind to. MuJoCo is the referee: when a
# renaming changes one of those bodies (a flexcomp's bodies, or attached bodies
# through the attach prefix), the renamed text fails in MuJoCo with the skin's
# bodies unknown, so the renaming must refuse; when it changes none, the result
# compiles in MuJoCo.


#: A flexcomp whose three bodies a file skin binds (no named body besides).
ROPE = """<mujoco><asset><skin name="hide" file="rope.skn"/></asset><worldbody>
  <geom name="floor" type="plane" size="1 1 0.1"/>
  <flexcomp name="rope" type="grid" dim="1" count="3 1 1" spacing="0.05 0.05 0.05"
            radius="0.01" mass="0.1"><edge equality="true"/></flexcomp>
</worldbody></mujoco>"""

#: An attached child whose bodies a file skin binds.
CHILD = """<mujoco model="kid"><worldbody>
  <body name="palm"><geom size="0.1"/><body name="x1" pos="0 0 0.3"><geom size="0.05"/></body>
  </body></worldbody></mujoco>"""
ATTACHED = """<mujoco><asset><model name="kid" file="child.xml"/><skin name="hide" file="hand.skn"/>
</asset><worldbody><geom name="floor" type="plane" size="1 1 0.1"/>
  <body name="mount" pos="0 0 1"><attach model="kid" body="palm" prefix="g_"/></body>
</worldbody></mujoco>"""


def refusal(file: str) -> str:
    """The whole message of the refusal to rename bodies a skin read from ``file`` binds."""
    return (
        f"cannot rename the bodies of a model where skin 'hide' is read from {file!r}: the file "
        "names the bodies its bones bind to, and MuJoCo would not find them; write the skin "
        "inline first with mjcf_model.serializers.skins.inline_skin_files(model, model_folder)"
    )


@pytest.fixture
def rope(tmp_path: Path) -> Path:
    """The flexcomp model and its skin file, bound to rope_0, rope_1 and rope_2."""
    skin_file(tmp_path / "rope.skn", ("rope_0", "rope_1", "rope_2"))
    path = tmp_path / "rope.xml"
    path.write_text(ROPE, encoding="utf-8")
    return path


@pytest.fixture
def attached(tmp_path: Path) -> Path:
    """The attaching model, its child and its skin file, bound to g_palm, g_x1 and g_palm."""
    skin_file(tmp_path / "hand.skn", ("g_palm", "g_x1", "g_palm"))
    (tmp_path / "child.xml").write_text(CHILD, encoding="utf-8")
    path = tmp_path / "attached.xml"
    path.write_text(ATTACHED, encoding="utf-8")
    return path


def test_renaming_a_flexcomp_bound_by_a_file_skin_is_refused(rope: Path) -> None:
    """Renaming the flexcomp renames its bodies: MuJoCo would not find the skin's bones."""
    mujoco.MjModel.from_xml_path(str(rope))
    with pytest.raises(ValueError, match="unknown body 'rope_0' in skin"):
        compile_text_beside(ROPE.replace('name="rope"', 'name="cord"'), rope)
    with pytest.raises(MjcfValueError, match=f"^{re.escape(refusal('rope.skn'))}$") as info:
        renamed(loads(ROPE), {"flex": {"rope": "cord"}})
    assert isinstance(info.value, MjcfError)


def test_renaming_no_body_beside_a_file_skin_compiles(rope: Path, attached: Path) -> None:
    """Renaming only geoms changes no skin body: no refusal, and MuJoCo compiles the result."""
    for path, text in ((rope, ROPE), (attached, ATTACHED)):
        original = mujoco.MjModel.from_xml_path(str(path))
        for new in (
            renamed(loads(text), {"geom": {"floor": "ground"}}),
            prefixed(loads(text), "p_", namespaces={"geom"}),
        ):
            changed = compile_text_beside(dumps(new), path)
            assert model_differences(original, changed, ignore=RENAMING_FIELDS) == []
            assert compiled_names(changed)["body"] == compiled_names(original)["body"]


def test_prefixing_attach_prefixes_bound_by_a_file_skin_is_refused(attached: Path) -> None:
    """Prefixing the attach prefix renames attached bodies even when no declared body changes."""
    assert "g_x1" in compiled_names(mujoco.MjModel.from_xml_path(str(attached)))["body"]
    with pytest.raises(ValueError, match="unknown body 'g_palm' in skin"):
        compile_text_beside(ATTACHED.replace('prefix="g_"', 'prefix="p_g_"'), attached)
    with pytest.raises(MjcfValueError, match=f"^{re.escape(refusal('hand.skn'))}$"):
        prefixed(loads(ATTACHED), "p_", exclude={"mount", "floor", "kid", "hide"})


# -- An ``<include>`` anywhere in a tree is read as an include, and renaming refuses it. -------
#
# Its file's elements are not in the tree, so their names could not be renamed: the
# refusal says how to load the model instead.


SAID = r"cannot rename names in a model with <include> elements: .*inline_includes=True"


@pytest.mark.parametrize(
    "where",
    ["<worldbody><body name='b'>{}</body></worldbody>", "<asset>{}</asset>", "{}"],
    ids=["in a body", "in a section", "at the top"],
)
def test_an_include_is_refused_wherever_it_stands(where: str) -> None:
    """Prefixing a model holding an ``<include>`` raises, saying to inline includes."""
    include = '<include file="part.xml"/>'
    model = loads(f"<mujoco>{where.format(include)}</mujoco>")
    with pytest.raises(MjcfValueError, match=SAID):
        prefixed(model, "p_")


# -- Prefixing names MuJoCo makes while reading: replicate copies, flexcomp bodies, attachments.
#
# MuJoCo is the referee: the original and the prefixed model must compile to the
# same arrays with every name prefixed (``prefix_problems``), or, where MuJoCo
# cannot compile a construct (MuJoCo 3.9 has no ``<attach>`` without ``model``),
# the test asserts what MuJoCo does.


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
