"""Prefixing and renaming: exact, reference-aware, checked by MuJoCo."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import mujoco
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import Body, Geom, Mujoco, compiled
from mjcf_model.errors import MjcfValueError
from mjcf_model.strategies import models, names
from mjcf_model.transforms.composition.attaching import attach
from mjcf_model.transforms.naming.renaming import declared_names, prefix_map, prefixed, renamed
from mjcf_model.transforms.scaling.transform import scaled
from serializers import dumps, load, loads, to_dict
from serializers.skins import inline_skin_files
from tests.conftest import compiling_corpus, corpus_id
from tests.support.oracles import prefix_problems

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
