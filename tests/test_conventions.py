"""A child rewritten into a parent's compiler conventions compiles as the child alone.

Every test compiles the child alone under its own ``<compiler>`` (the model-wide
settings being the parent's) and the rewritten child under the parent's, and
compares what MuJoCo made of every body, joint, geom, site, camera, tendon and
actuator.
"""

from __future__ import annotations

from pathlib import Path

import attrs
import mujoco
import numpy as np
import pytest

from mjcf_model import compiled, find
from mjcf_model.bridge.compare import compiled_names, model_differences
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.nodes.base import Node, attribute_items, get_attribute, with_attributes
from mjcf_model.nodes.compiler import Compiler
from mjcf_model.nodes.node_info import BASE_FIELDS
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.transforms.composition.conventions import (
    CONVERTED_SETTINGS,
    MODEL_WIDE_SETTINGS,
    PATH_SETTINGS,
    compiler_settings,
    in_conventions,
)
from mjcf_model.tree.traversal import with_children
from serializers import load, loads
from tests.conftest import FIXTURES, MUJOCO_VERSION, compiling_corpus, corpus_id, printed_schema

HERE = FIXTURES / "conventions"

#: What MuJoCo made of each object the comparison covers, by ``MjModel`` prefix.
_FIELDS = {
    "body": ("pos", "quat", "ipos", "iquat", "mass", "inertia"),
    "jnt": ("type", "range", "axis", "pos", "stiffness", "limited", "actfrclimited", "actfrcrange"),
    "qpos": ("0", "_spring"),
    "geom": ("type", "size", "pos", "quat"),
    "site": ("type", "size", "pos", "quat"),
    "cam": ("pos", "quat"),
    "light": ("pos", "dir"),
    "flex": ("vert0",),
    "tendon": ("range", "limited", "actfrclimited", "actfrcrange"),
    "actuator": ("ctrlrange", "forcerange", "actrange", "gear", "ctrllimited", "forcelimited"),
}
COMPARED = [
    *(
        f"{kind}{'' if kind == 'qpos' else '_'}{name}"
        for kind, names in _FIELDS.items()
        for name in names
    ),
    "actuator_actlimited",
    *(["jnt_springyield"] if MUJOCO_VERSION >= (4, 0) else []),
]


def _compilers(model: Mujoco, keep: set[str] | frozenset[str]) -> list[Compiler]:
    """``model``'s compiler sections reduced to the settings in ``keep``."""
    return [
        with_attributes(Compiler(), {k: v for k, v in attribute_items(c) if k in keep})
        for c in model.elements
        if isinstance(c, Compiler)
    ]


def _without_compilers(model: Mujoco) -> list[Node]:
    return [c for c in model.children if not isinstance(c, Compiler)]


def _without(model: Mujoco) -> Mujoco:
    return with_children(model, _without_compilers(model))


def _alone(child: Mujoco, parent: Mujoco) -> Mujoco:
    """The child under its own compiler, the model-wide settings being the parent's."""
    own = _compilers(child, set(CONVERTED_SETTINGS) | PATH_SETTINGS)
    theirs = _compilers(parent, MODEL_WIDE_SETTINGS)
    return with_children(child, [*own, *theirs, *_without_compilers(child)])


def _under(converted: Mujoco, child: Mujoco, parent: Mujoco) -> Mujoco:
    """The rewritten child under the parent's compiler (its files still found where they are)."""
    assert not any(isinstance(c, Compiler) for c in converted.children)
    theirs = _compilers(parent, set(CONVERTED_SETTINGS) | MODEL_WIDE_SETTINGS)
    paths = _compilers(child, PATH_SETTINGS)
    return with_children(converted, [*theirs, *paths, *converted.children])


def _differences(expected: mujoco.MjModel, found: mujoco.MjModel) -> list[str]:
    """The compared fields in which two compiled models differ (rtol 1e-9), and their names."""
    names = [] if compiled_names(expected) == compiled_names(found) else ["names"]
    return names + [
        field
        for field in COMPARED
        if getattr(expected, field).shape != getattr(found, field).shape
        or not np.allclose(getattr(expected, field), getattr(found, field), rtol=1e-9, atol=1e-12)
    ]


def _child(name: str, **settings: str) -> Mujoco:
    model = load(HERE / name)
    return with_children(model, [with_attributes(Compiler(), settings), *model.children])


def _parent(**settings: str) -> Mujoco:
    return Mujoco(children=[with_attributes(Compiler(), settings)])


def _check(child: Mujoco, parent: Mujoco) -> Mujoco:
    """Assert the rewritten child compiles under the parent as the child alone; return it."""
    expected = compiled(_alone(child, parent))
    converted = in_conventions(child, parent)
    assert _differences(expected, compiled(_under(converted, child, parent))) == []
    return converted


ANGLE_PAIRS = [
    ({"angle": "degree"}, {"angle": "radian"}),
    ({"angle": "radian"}, {"angle": "degree"}),
    ({"eulerseq": "xyz"}, {"eulerseq": "zyx"}),
    ({"angle": "radian", "eulerseq": "XYZ"}, {"eulerseq": "xyz"}),
    ({"eulerseq": "xYz"}, {"angle": "radian", "eulerseq": "zxz"}),
    ({"eulerseq": "zxz"}, {"eulerseq": "YZY"}),
    ({"angle": "radian", "eulerseq": "yxz"}, {"eulerseq": "Zyx"}),
]


@pytest.mark.parametrize(("mine", "theirs"), ANGLE_PAIRS, ids=str)
def test_angles_and_euler_sequences(mine: dict[str, str], theirs: dict[str, str]) -> None:
    """Orientations, hinge and ball values and replicate turns keep their compiled values.

    A geom its class orients keeps the Euler notation; a body in another
    sequence gets the exact quaternion.
    """
    child, parent = _child("angles.xml", **mine), _parent(**theirs)
    converted = _check(child, parent)
    body, geom = find(converted, "body", name="base"), find(converted, "geom", name="arm_geom")
    assert body is not None and geom is not None and get_attribute(geom, "euler") is not None
    if compiler_settings(child)["eulerseq"] != compiler_settings(parent)["eulerseq"]:
        assert get_attribute(body, "euler") is None and get_attribute(body, "quat") is not None


def test_degrees_become_the_radians_mujoco_makes_of_them() -> None:
    """From degrees to radians the values are MuJoCo's own: the compiled model is identical."""
    child, parent = _child("angles.xml"), _parent(angle="radian")
    converted = in_conventions(child, parent)
    expected = compiled(_alone(child, parent))
    assert model_differences(expected, compiled(_under(converted, child, parent))) == []


@pytest.mark.parametrize(
    ("mine", "theirs"),
    [({"angle": "degree"}, {"angle": "radian"}), ({"angle": "radian"}, {})],
    ids=str,
)
def test_spring_yield_is_an_angle_in_mujoco_4(mine: dict[str, str], theirs: dict[str, str]) -> None:
    """A hinge's springyield (MuJoCo 4.0) is converted; a slide's is not."""
    name = "springyield.xml" if MUJOCO_VERSION >= (4, 0) else "angles.xml"
    _check(_child(name, **mine), _parent(**theirs))


def test_inherited_joint_angles_are_written_on_the_joint() -> None:
    """A hinge that takes its range from a class gets it written; the class keeps its value."""
    converted = in_conventions(_child("angles.xml", angle="radian"), _parent())
    wide = find(converted, "default", **{"class": "wide"})
    assert wide is not None and get_attribute(wide.elements[0], "range") == (-100.0, 100.0)
    joint = find(converted, "joint", name="hinge_wide")
    assert joint is not None
    assert get_attribute(joint, "range") == tuple(np.degrees([-100.0, 100.0]))
    found = compiled(_under(converted, _child("angles.xml"), _parent())).joint("hinge_wide")
    assert np.allclose(found.range, [-100, 100])


@pytest.mark.parametrize(
    "theirs", [{"angle": "radian"}, {"eulerseq": "XYZ"}, {"autolimits": "false"}], ids=str
)
def test_an_attached_model_keeps_its_own_compiler(theirs: dict[str, str]) -> None:
    """What <attach> brings in is read under its own file's compiler: it is left as it is."""
    child = _child("attaching.xml")
    converted = _check(child, _parent(**theirs))
    assert converted.asset == child.asset


@pytest.mark.parametrize("sequence", ["xxy", "YXY"])
def test_a_sequence_that_cannot_express_a_turn_is_refused(sequence: str) -> None:
    """Refused, naming eulerseq, where the parent's sequence cannot say the child's turns.

    "xxy" repeats an axis; "YXY" has no angles whose multiples turn a replicate about z.
    """
    with pytest.raises(MjcfValueError, match="eulerseq"):
        in_conventions(_child("angles.xml", eulerseq="zxz"), _parent(eulerseq=sequence))


@pytest.mark.parametrize(
    ("name", "mine", "theirs"),
    [
        ("limits.xml", {}, {"autolimits": "false"}),
        ("limits_flagged.xml", {"autolimits": "false"}, {}),
        ("limits.xml", {"angle": "radian"}, {"autolimits": "false", "angle": "degree"}),
    ],
    ids=str,
)
def test_limit_flags(name: str, mine: dict[str, str], theirs: dict[str, str]) -> None:
    """Joints, tendons and actuators keep their limits, through classes and inheritrange."""
    _check(_child(name, **mine), _parent(**theirs))


INTEGRATED = (
    '<worldbody><body><joint name="j"/><geom size="1"/></body></worldbody>'
    '<actuator><intvelocity joint="j" kp="1" {}/></actuator>'
)


def test_an_integrated_velocity_keeps_its_activation_limits() -> None:
    """An intvelocity sets actlimited itself: nothing is written on it (3.9 has no such flag)."""
    checked = 0
    for actrange in ('actrange="-1 1"', ""):  # MuJoCo 3.9 needs a range here, 4.0 rejects one
        text = '<mujoco><compiler autolimits="false"/>' + INTEGRATED.format(actrange) + "</mujoco>"
        child = loads(text)
        try:
            compiled(child)
        except MjcfError:
            continue
        _check(child, _parent())
        checked += 1
    assert checked == 1


def test_an_integrated_velocity_range_under_autolimits_false() -> None:
    """MuJoCo 4.0 rejects an intvelocity actrange under autolimits="false": refused, naming it."""
    child = loads("<mujoco>" + INTEGRATED.format('actrange="-1 1"') + "</mujoco>")
    parent = _parent(autolimits="false")
    try:
        compiled(_under(_without(child), child, parent))
    except MjcfError:
        with pytest.raises(MjcfValueError, match="autolimits"):
            in_conventions(child, parent)
    else:
        _check(child, parent)


INERTIA_PAIRS = [
    ({"inertiafromgeom": "true"}, {}),
    ({}, {"inertiafromgeom": "false"}),
    ({"inertiagrouprange": "0 2"}, {}),
    ({}, {"inertiagrouprange": "0 1"}),
    ({"boundmass": "0.01"}, {}),
    ({"boundinertia": "0.0001"}, {"angle": "radian"}),
    ({"inertiafromgeom": "true", "alignfree": "true"}, {"inertiafromgeom": "false"}),
    ({}, {"balanceinertia": "true", "inertiagrouprange": "0 4"}),
    ({"settotalmass": "3"}, {}),
]


@pytest.mark.parametrize(("mine", "theirs"), INERTIA_PAIRS, ids=str)
def test_inertia_settings(mine: dict[str, str], theirs: dict[str, str]) -> None:
    """Masses, centres and inertias stay, unnamed and replicated bodies included."""
    _check(_child("inertia.xml", **mine), _parent(**theirs))


def test_a_balanced_inertia_is_written_out() -> None:
    """An inertia only balanceinertia makes valid compiles under a parent without it."""
    converted = _check(_child("unbalanced.xml", balanceinertia="true"), _parent())
    assert converted.worldbody is not None
    inertial = converted.worldbody.bodies[0].elements[0]
    assert inertial.tag == "inertial"
    assert np.allclose(get_attribute(inertial, "diaginertia"), 0.7 / 3)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("theirs", "setting"),
    [
        ({"inertiafromgeom": "true"}, "inertiafromgeom"),
        ({"boundmass": "0.5"}, "boundmass"),
        ({"settotalmass": "7"}, "settotalmass"),
    ],
)
def test_inertia_the_parent_would_still_change_is_refused(
    theirs: dict[str, str], setting: str
) -> None:
    """Refused, naming the setting, where an explicit inertial cannot hold the child's."""
    child = _child("inertia.xml")
    differing = compiled(_under(_without(child), child, _parent(**theirs)))
    assert _differences(compiled(child), differing)  # the parent's setting does matter
    with pytest.raises(MjcfValueError, match=setting):
        in_conventions(child, _parent(**theirs))


@pytest.mark.parametrize(
    ("mine", "theirs"),
    [({"alignfree": "true"}, {}), ({}, {"alignfree": "true"})],
    ids=str,
)
def test_free_joint_alignment(mine: dict[str, str], theirs: dict[str, str]) -> None:
    """Free bodies keep their frames: align is written where the child leaves it unset."""
    child = _child("alignfree.xml", **mine)
    assert _differences(
        compiled(child), compiled(_under(_without(child), child, _parent(**theirs)))
    )
    _check(child, _parent(**theirs))


def test_a_free_joint_written_as_a_joint_is_refused() -> None:
    """A <joint type="free"> cannot carry align: refused, naming alignfree."""
    child = loads(
        '<mujoco><compiler alignfree="true"/><worldbody><body pos="1 0 0">'
        '<joint type="free"/><geom size=".1" pos=".2 0 0"/></body></worldbody></mujoco>'
    )
    with pytest.raises(MjcfValueError, match="alignfree"):
        in_conventions(child, _parent())


def test_a_geom_fitted_to_a_mesh_refuses_another_fitaabb() -> None:
    """A fitted geom's size depends on fitaabb: refused, naming fitaabb."""
    child = _child("fitaabb.xml", fitaabb="true")
    assert _differences(compiled(child), compiled(_under(_without(child), child, _parent())))
    with pytest.raises(MjcfValueError, match="fitaabb"):
        in_conventions(child, _parent())


def test_fitaabb_without_fitted_geoms_passes() -> None:
    """A mesh geom that is not fitted compiles the same under either fitaabb."""
    _check(_child("meshes.xml", fitaabb="true"), _parent())


def test_same_settings_change_nothing_but_the_compiler() -> None:
    """Equal settings leave every other section as it is (shared, not copied)."""
    child = _child("angles.xml", angle="radian", meshdir="parts", settotalmass="3")
    parent = _parent(angle="radian", texturedir="images", settotalmass="3")
    converted = in_conventions(child, parent)
    assert converted.children == tuple(_without_compilers(child))
    assert converted.worldbody is child.worldbody


def test_includes_are_refused_when_something_is_converted() -> None:
    """A kept <include> cannot be converted: the error says to inline it."""
    child = load(FIXTURES / "includes.xml")
    with pytest.raises(MjcfValueError, match="inline_includes"):
        in_conventions(child, _parent(angle="radian" if _degree(child) else "degree"))


def _degree(model: Mujoco) -> bool:
    return compiler_settings(model)["angle"] == "degree"


def test_the_settings_lists_cover_every_compiler_setting() -> None:
    """Each compiler attribute and child element is converted, a path, or model-wide."""
    listed = set(CONVERTED_SETTINGS) | PATH_SETTINGS | MODEL_WIDE_SETTINGS
    children = {key.split("/")[1] for key in SCHEMA if key.startswith("compiler/")}
    fields = {f.name for f in attrs.fields(Compiler)} - BASE_FIELDS
    assert listed == fields | children
    assert listed == set(SCHEMA["compiler"].attributes) | children
    installed = printed_schema()
    assert set(installed["compiler"]) | {"lengthrange"} <= listed
    assert not set(CONVERTED_SETTINGS) & PATH_SETTINGS
    assert not (set(CONVERTED_SETTINGS) | PATH_SETTINGS) & MODEL_WIDE_SETTINGS


#: The parent compilers every corpus model is converted to: one in radians, one in degrees,
#: so that every model's angles are converted by one of them, whatever its own unit.
CORPUS_PARENTS = {
    "radian-no-autolimits": {"angle": "radian", "autolimits": "false"},
    "degree-zyx-no-inertiafromgeom": {
        "angle": "degree",
        "eulerseq": "zyx",
        "inertiafromgeom": "false",
    },
}
#: The corpus models (and parent) the conversion refuses, with the setting it names: none.
KNOWN_REFUSALS: dict[str, str] = {}


@pytest.mark.parametrize("path", compiling_corpus(), ids=corpus_id)
def test_corpus_models_keep_their_meaning(path: Path) -> None:
    """Each robosuite and dm_control model, under two parent compilers, compiles the same."""
    # MuJoCo's asset cache is full of the corpus compiled from files at collection: emptied,
    # it keeps this model's meshes for the next compiles (a third of the time).
    mujoco.mj_clearCache(mujoco.mj_getCache())
    child = load(path, inline_includes=True)
    expected = compiled(_alone(child, _parent()))
    for label, settings in CORPUS_PARENTS.items():
        parent = _parent(**settings)
        try:
            converted = in_conventions(child, parent)
        except MjcfError as error:
            setting = KNOWN_REFUSALS.get(f"{corpus_id(path)} {label}")
            assert setting is not None and setting in str(error), error
            continue
        found = compiled(_under(converted, child, parent))
        assert _differences(expected, found) == [], label
