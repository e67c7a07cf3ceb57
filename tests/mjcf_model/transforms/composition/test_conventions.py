"""Tests of ``mjcf_model.transforms.composition.conventions``."""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import mujoco
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import compiled, find
from mjcf_model.bridge.compare import compiled_names, model_differences
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.nodes.base import Node, attribute_items, get_attribute, with_attributes
from mjcf_model.nodes.compiler import Compiler
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.transforms.composition.attaching import attach
from mjcf_model.transforms.composition.conventions import (
    CONVERTED_SETTINGS,
    MODEL_WIDE_SETTINGS,
    PATH_SETTINGS,
    compiler_settings,
    in_conventions,
)
from mjcf_model.tree.traversal import with_children
from tests.conftest import FIXTURES, MUJOCO_VERSION, compiling_corpus, corpus_id

# -- A child rewritten into a parent's compiler conventions compiles as the child alone. -------
#
# Every test compiles the child alone under its own ``<compiler>`` (the model-wide
# settings being the parent's) and the rewritten child under the parent's, and
# compares what MuJoCo made of every body, joint, geom, site, camera, tendon and
# actuator.


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


def _under_conventions(converted: Mujoco, child: Mujoco, parent: Mujoco) -> Mujoco:
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


def _child_conventions(name: str, **settings: str) -> Mujoco:
    model = load(HERE / name)
    return with_children(model, [with_attributes(Compiler(), settings), *model.children])


def _parent(**settings: str) -> Mujoco:
    return Mujoco(children=[with_attributes(Compiler(), settings)])


def _check(child: Mujoco, parent: Mujoco) -> Mujoco:
    """Assert the rewritten child compiles under the parent as the child alone; return it."""
    expected = compiled(_alone(child, parent))
    converted = in_conventions(child, parent)
    assert _differences(expected, compiled(_under_conventions(converted, child, parent))) == []
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
    child, parent = _child_conventions("angles.xml", **mine), _parent(**theirs)
    converted = _check(child, parent)
    body, geom = find(converted, "body", name="base"), find(converted, "geom", name="arm_geom")
    assert body is not None and geom is not None and get_attribute(geom, "euler") is not None
    if compiler_settings(child)["eulerseq"] != compiler_settings(parent)["eulerseq"]:
        assert get_attribute(body, "euler") is None and get_attribute(body, "quat") is not None


def test_degrees_become_the_radians_mujoco_makes_of_them() -> None:
    """From degrees to radians the values are MuJoCo's own: the compiled model is identical."""
    child, parent = _child_conventions("angles.xml"), _parent(angle="radian")
    converted = in_conventions(child, parent)
    expected = compiled(_alone(child, parent))
    assert model_differences(expected, compiled(_under_conventions(converted, child, parent))) == []


@pytest.mark.parametrize(
    ("mine", "theirs"),
    [({"angle": "degree"}, {"angle": "radian"}), ({"angle": "radian"}, {})],
    ids=str,
)
def test_spring_yield_is_an_angle_in_mujoco_4(mine: dict[str, str], theirs: dict[str, str]) -> None:
    """A hinge's springyield (MuJoCo 4.0) is converted; a slide's is not."""
    name = "springyield.xml" if MUJOCO_VERSION >= (4, 0) else "angles.xml"
    _check(_child_conventions(name, **mine), _parent(**theirs))


def test_inherited_joint_angles_are_written_on_the_joint() -> None:
    """A hinge that takes its range from a class gets it written; the class keeps its value."""
    converted = in_conventions(_child_conventions("angles.xml", angle="radian"), _parent())
    wide = find(converted, "default", **{"class": "wide"})
    assert wide is not None and get_attribute(wide.elements[0], "range") == (-100.0, 100.0)
    joint = find(converted, "joint", name="hinge_wide")
    assert joint is not None
    assert get_attribute(joint, "range") == tuple(np.degrees([-100.0, 100.0]))
    found = compiled(
        _under_conventions(converted, _child_conventions("angles.xml"), _parent())
    ).joint("hinge_wide")
    assert np.allclose(found.range, [-100, 100])


@pytest.mark.parametrize(
    "theirs", [{"angle": "radian"}, {"eulerseq": "XYZ"}, {"autolimits": "false"}], ids=str
)
def test_an_attached_model_keeps_its_own_compiler(theirs: dict[str, str]) -> None:
    """What <attach> brings in is read under its own file's compiler: it is left as it is."""
    child = _child_conventions("attaching.xml")
    converted = _check(child, _parent(**theirs))
    assert converted.asset == child.asset


@pytest.mark.parametrize("sequence", ["xxy", "YXY"])
def test_a_sequence_that_cannot_express_a_turn_is_refused(sequence: str) -> None:
    """Refused, naming eulerseq, where the parent's sequence cannot say the child's turns.

    "xxy" repeats an axis; "YXY" has no angles whose multiples turn a replicate about z.
    """
    with pytest.raises(MjcfValueError, match="eulerseq"):
        in_conventions(_child_conventions("angles.xml", eulerseq="zxz"), _parent(eulerseq=sequence))


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
    _check(_child_conventions(name, **mine), _parent(**theirs))


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
        compiled(_under_conventions(_without(child), child, parent))
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
    _check(_child_conventions("inertia.xml", **mine), _parent(**theirs))


def test_a_balanced_inertia_is_written_out() -> None:
    """An inertia only balanceinertia makes valid compiles under a parent without it."""
    converted = _check(_child_conventions("unbalanced.xml", balanceinertia="true"), _parent())
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
    child = _child_conventions("inertia.xml")
    differing = compiled(_under_conventions(_without(child), child, _parent(**theirs)))
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
    child = _child_conventions("alignfree.xml", **mine)
    assert _differences(
        compiled(child), compiled(_under_conventions(_without(child), child, _parent(**theirs)))
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
    child = _child_conventions("fitaabb.xml", fitaabb="true")
    assert _differences(
        compiled(child), compiled(_under_conventions(_without(child), child, _parent()))
    )
    with pytest.raises(MjcfValueError, match="fitaabb"):
        in_conventions(child, _parent())


def test_fitaabb_without_fitted_geoms_passes() -> None:
    """A mesh geom that is not fitted compiles the same under either fitaabb."""
    _check(_child_conventions("meshes.xml", fitaabb="true"), _parent())


def test_same_settings_change_nothing_but_the_compiler() -> None:
    """Equal settings leave every other section as it is (shared, not copied)."""
    child = _child_conventions("angles.xml", angle="radian", meshdir="parts", settotalmass="3")
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
        found = compiled(_under_conventions(converted, child, parent))
        assert _differences(expected, found) == [], label


# -- Which notation an orientation is written in when a child takes another model's conventions.
#
# The module documentation of the conversion says: an angle in another unit stays
# ``euler`` (converted), a ``<default>``'s ``euler`` in another sequence stays
# ``euler`` (in the parent's sequence), and an orientation is left alone when
# neither ``angle`` nor ``eulerseq`` differs. MuJoCo, compiling the child alone,
# referees what the rewritten child means under the parent's ``<compiler>``.


def _under_euler_notation(converted: Mujoco, parent: Mujoco) -> Mujoco:
    """The rewritten child with the parent's ``<compiler>`` in front of it."""
    return with_children(converted, [*parent.children, *converted.children])


def _converted(child_text: str, parent_text: str) -> tuple[Mujoco, Mujoco, Mujoco]:
    child, parent = loads(child_text), loads(parent_text)
    return child, in_conventions(child, parent), parent


def test_an_orientation_is_left_as_written_when_only_autolimits_differs() -> None:
    """Degrees that do not round-trip through radians stay as written if angle does not differ."""
    child, converted, parent = _converted(
        '<mujoco><compiler autolimits="false"/><worldbody>'
        '<body name="b" euler="0 0 -357"><geom size="1"/></body></worldbody></mujoco>',
        "<mujoco/>",
    )
    body = find(converted, "body", name="b")
    assert body is not None
    assert get_attribute(body, "euler") == (0.0, 0.0, -357.0)
    assert get_attribute(body, "quat") is None
    assert (
        model_differences(compiled(child), compiled(_under_euler_notation(converted, parent))) == []
    )


def test_degrees_to_radians_stay_euler_in_the_same_sequence() -> None:
    """Under the same eulerseq, an angle unit change keeps euler: the radians MuJoCo makes."""
    child, converted, parent = _converted(
        '<mujoco><worldbody><body name="b" euler="10 20 30"><geom size="1"/></body>'
        "</worldbody></mujoco>",
        '<mujoco><compiler angle="radian"/></mujoco>',
    )
    body = find(converted, "body", name="b")
    assert body is not None and get_attribute(body, "quat") is None
    euler = get_attribute(body, "euler")
    assert euler == tuple(d / 180 * np.pi for d in (10.0, 20.0, 30.0))  # MuJoCo's d / 180 * pi
    assert (
        model_differences(compiled(child), compiled(_under_euler_notation(converted, parent))) == []
    )


def test_radians_to_degrees_stay_euler_in_the_same_sequence() -> None:
    """Radians that degrees read back exactly stay euler, in degrees, under the same eulerseq."""
    child, converted, parent = _converted(
        '<mujoco><compiler angle="radian"/><worldbody>'
        '<body name="b" euler="0.5 -0.25 1"><geom size="1"/></body></worldbody></mujoco>',
        "<mujoco/>",
    )
    body = find(converted, "body", name="b")
    assert body is not None and get_attribute(body, "quat") is None
    euler = get_attribute(body, "euler")
    assert isinstance(euler, tuple)
    assert np.allclose(euler, np.degrees([0.5, -0.25, 1.0]), rtol=1e-15, atol=0)
    assert (
        model_differences(compiled(child), compiled(_under_euler_notation(converted, parent))) == []
    )


def test_a_default_class_euler_stays_euler_in_the_parent_sequence() -> None:
    """A <default>'s euler in another eulerseq is rewritten as euler, never as quat."""
    child, converted, parent = _converted(
        '<mujoco><compiler eulerseq="zyx"/><default><geom euler="0 30 60"/></default>'
        '<worldbody><body name="b"><geom name="g" size="1"/></body></worldbody></mujoco>',
        '<mujoco><compiler eulerseq="xyz"/></mujoco>',
    )
    setting = find(converted, "default")
    assert setting is not None
    geom_default = setting.elements[0]
    assert get_attribute(geom_default, "quat") is None
    assert get_attribute(geom_default, "euler") is not None
    expected, found = compiled(child), compiled(_under_euler_notation(converted, parent))
    assert np.allclose(found.geom_quat, expected.geom_quat, rtol=0, atol=1e-12)


# -- Euler angles attached under another ``eulerseq`` or angle unit keep their exact
#    quaternions.
#
# Each test compiles the child alone and the parent with the child attached, and
# compares the quaternions MuJoCo made of every body, inertial, geom, site and
# camera (through a frame too): no digit is lost, even at gimbal lock.


#: The compiled quaternions compared, one per kind of element that takes ``euler``.
QUATS = ("body_quat", "body_iquat", "geom_quat", "site_quat", "cam_quat")
#: Sequences a child or a parent may read Euler angles in.
SEQUENCES = ("xyz", "zyx", "XYZ", "xYz", "zxz", "YZY")
#: Angles at and next to gimbal lock, where converting Euler angles loses digits.
LOCKED = (math.pi / 2, -math.pi / 2, 1.5708, 3.14159, math.pi, 0.0)


def _child_exact(euler: str, angle: str, eulerseq: str) -> str:
    """A child whose body, inertial, geom, site, camera and framed site all say ``euler``."""
    return (
        f'<mujoco><compiler angle="{angle}" eulerseq="{eulerseq}"/><worldbody>'
        f'<body name="b" euler="{euler}">'
        f'<inertial pos="0 0 0" mass="1" diaginertia="1 2 3" euler="{euler}"/>'
        f'<geom size="0.1" euler="{euler}"/><site euler="{euler}"/><camera euler="{euler}"/>'
        f'<frame euler="{euler}"><site/></frame></body></worldbody></mujoco>'
    )


def _largest_difference(child_text: str, parent_text: str) -> float:
    """The largest difference in a compared quaternion between the child alone and attached."""
    child = loads(child_text)
    alone, attached = compiled(child), compiled(attach(loads(parent_text), child))
    return max(float(np.abs(getattr(alone, q) - getattr(attached, q)).max()) for q in QUATS)


def test_gimbal_lock_keeps_every_digit() -> None:
    """A zyx site at gimbal lock attached to an xyz parent compiles to its own quaternion."""
    child = _child_exact("0 1.5708 3.14159", "radian", "zyx")
    assert _largest_difference(child, "<mujoco/>") <= 1e-15


def test_the_turn_is_written_as_quat() -> None:
    """Where no class orients an element, its turn in another sequence becomes a quat."""
    child = loads(_child_exact("0 90 180", "degree", "zyx"))
    site = find(attach(loads("<mujoco/>"), child), "site")
    assert site is not None and get_attribute(site, "euler") is None
    assert get_attribute(site, "quat") is not None


def test_a_class_orientation_keeps_the_euler_notation() -> None:
    """A site its class orients keeps euler (MuJoCo 3.9 would prefer the class's to a quat)."""
    child = loads(
        '<mujoco><compiler eulerseq="zyx"/><default><site euler="0 0 10"/></default>'
        '<worldbody><site name="s" euler="0 90 180"/></worldbody></mujoco>'
    )
    attached = attach(loads("<mujoco/>"), child)
    site = find(attached, "site", name="s")
    assert site is not None and get_attribute(site, "quat") is None
    assert get_attribute(site, "euler") is not None
    assert np.allclose(compiled(attached).site_quat, compiled(child).site_quat, atol=1e-9)


angles = st.one_of(
    st.floats(-2 * math.pi, 2 * math.pi, allow_nan=False, allow_subnormal=False),
    st.sampled_from(LOCKED).flatmap(lambda a: st.sampled_from([a, math.nextafter(a, 4)])),
).filter(lambda a: a == 0 or abs(a) >= sys.float_info.min)  # MuJoCo 3.9 refuses subnormals


@given(
    euler=st.tuples(angles, angles, angles),
    mine=st.tuples(st.sampled_from(("radian", "degree")), st.sampled_from(SEQUENCES)),
    theirs=st.tuples(st.sampled_from(("radian", "degree")), st.sampled_from(SEQUENCES)),
)
def test_attached_euler_angles_compile_to_the_same_quaternions(
    euler: tuple[float, float, float], mine: tuple[str, str], theirs: tuple[str, str]
) -> None:
    """Any angles, in either unit and any sequence, compile attached as the child alone."""
    scale = 180 / math.pi if mine[0] == "degree" else 1.0
    text = " ".join(repr(a * scale) for a in euler)
    parent = f'<mujoco><compiler angle="{theirs[0]}" eulerseq="{theirs[1]}"/></mujoco>'
    assert _largest_difference(_child_exact(text, *mine), parent) <= 1e-15


# -- A geom fitted to a mesh refuses another ``fitaabb``; every other geom passes. -------------
#
# MuJoCo sizes a primitive geom that names a ``mesh`` from the mesh's box or
# ellipsoid as ``fitaabb`` says, so a child whose ``fitaabb`` differs from the
# parent's cannot keep such a geom's size: the conversion refuses, naming the geom,
# the mesh and what to do. A ``mesh`` or ``sdf`` geom is not fitted, and nothing is
# refused when ``fitaabb`` is the same. MuJoCo, compiling the child alone, referees.


MESH = '<asset><mesh name="wedge" vertex="0 0 0 1 0 0 0 2 0 0 0 3 1 1 1"/></asset>'


def _child_fitted_geoms(compiler: str, body: str, defaults: str = "") -> Mujoco:
    return loads(
        f"<mujoco><compiler {compiler}/>{MESH}<default>{defaults}</default>"
        f'<worldbody><body name="holder"><joint name="hinge"/>{body}</body></worldbody></mujoco>'
    )


def _same_geoms(child: Mujoco, parent: Mujoco) -> bool:
    """Whether the rewritten child compiles under the parent to the child's geoms."""
    converted = in_conventions(child, parent)
    found = compiled(with_children(converted, [*parent.children, *converted.children]))
    expected = compiled(child)
    return all(
        np.allclose(getattr(found, f), getattr(expected, f), rtol=1e-12, atol=1e-12)
        for f in ("geom_type", "geom_size", "geom_pos", "geom_quat", "body_mass")
    )


def _refusal(geom: str, mesh: str) -> str:
    return (
        "^the parent's fitaabb differs from the child's, and geom "
        + re.escape(f"{geom} is fitted to mesh {mesh!r}: ")
        + re.escape("its size would change; give the two models the same fitaabb")
        + "$"
    )


def test_a_named_fitted_geom_is_refused_by_name() -> None:
    """The refusal names the fitted geom and its mesh and says to give the same fitaabb."""
    child = _child_fitted_geoms('fitaabb="true"', '<geom name="fitted" type="box" mesh="wedge"/>')
    parent = loads("<mujoco/>")
    under_parent = _child_fitted_geoms(
        'fitaabb="false"', '<geom name="fitted" type="box" mesh="wedge"/>'
    )
    assert not np.allclose(compiled(under_parent).geom_size, compiled(child).geom_size)
    with pytest.raises(MjcfValueError, match=_refusal("fitted", "wedge")):
        in_conventions(child, parent)


def test_an_unnamed_fitted_geom_is_refused_as_unnamed() -> None:
    """An unnamed fitted geom is called (unnamed) in the refusal."""
    child = _child_fitted_geoms('fitaabb="true"', '<geom type="capsule" mesh="wedge"/>')
    with pytest.raises(MjcfValueError, match=_refusal("(unnamed)", "wedge")):
        in_conventions(child, loads("<mujoco/>"))


def test_a_mesh_from_a_childclass_makes_a_fitted_geom() -> None:
    """A box geom whose mesh comes from its body's childclass is fitted: refused."""
    child = _child_fitted_geoms(
        'fitaabb="true"',
        '<body name="inner" childclass="shaped"><geom name="boxed" type="box"/></body>',
        '<default class="shaped"><geom mesh="wedge"/></default>',
    )
    with pytest.raises(MjcfValueError, match=_refusal("boxed", "wedge")):
        in_conventions(child, loads("<mujoco/>"))


def test_a_mesh_type_from_a_childclass_is_not_fitted() -> None:
    """A geom a childclass makes type="mesh" is not fitted: it compiles as the child alone."""
    child = _child_fitted_geoms(
        'fitaabb="true"',
        '<body name="inner" childclass="shaped"><geom name="shaped" mesh="wedge"/></body>',
        '<default class="shaped"><geom type="mesh"/></default>',
    )
    assert _same_geoms(child, loads("<mujoco/>"))


def test_an_sdf_geom_with_a_mesh_is_not_fitted() -> None:
    """An sdf geom that names a mesh is not fitted: it compiles as the child alone."""
    child = _child_fitted_geoms('fitaabb="true"', '<geom name="field" type="sdf" mesh="wedge"/>')
    assert _same_geoms(child, loads("<mujoco/>"))


def test_a_fitted_geom_passes_when_fitaabb_is_the_same() -> None:
    """Only fitaabb can refuse a fitted geom: another setting differing converts it."""
    child = _child_fitted_geoms(
        'fitaabb="true" angle="radian"', '<geom name="fitted" type="box" mesh="wedge"/>'
    )
    assert _same_geoms(child, loads('<mujoco><compiler fitaabb="true"/></mujoco>'))


# -- Free joints under another ``alignfree``: align written where auto, refused where it cannot
#    be.
#
# MuJoCo's ``alignfree`` aligns a free body (one with no child bodies) with its
# inertial frame unless its free joint says ``align``. A ``<freejoint>`` that says
# ``align="auto"`` follows ``alignfree``, so the child's value is written on it; a
# ``<joint type="free">`` (its type written or given by a class) cannot say
# ``align``, so in a leaf body it is refused with what to do instead; in a body
# with child bodies ``alignfree`` does not apply and it passes. MuJoCo, compiling
# the child alone, referees.


REFUSAL = "^" + re.escape(
    "the parent's alignfree differs from the child's, and a <joint "
    'type="free"> cannot say which applies to it; write it as <freejoint>'
)


def _bodies_kept(child: Mujoco, parent: Mujoco) -> bool:
    """Whether the rewritten child compiles under the parent to the child's body frames."""
    converted = in_conventions(child, parent)
    found = compiled(with_children(converted, [*parent.children, *converted.children]))
    expected = compiled(child)
    return all(
        np.allclose(getattr(found, f), getattr(expected, f), rtol=1e-12, atol=1e-12)
        for f in ("body_pos", "body_quat", "body_ipos", "body_iquat", "geom_pos", "qpos0")
    )


def test_a_freejoint_saying_align_auto_keeps_the_child_alignment() -> None:
    """A <freejoint align="auto"> gets the child's alignfree: the body frame is kept."""
    child = loads(
        '<mujoco><compiler alignfree="true"/><worldbody><body pos="1 0 0">'
        '<freejoint align="auto"/><geom size=".1" pos=".2 0 0"/></body></worldbody></mujoco>'
    )
    parent = loads("<mujoco/>")
    unconverted = with_children(child, [c for c in child.children if not isinstance(c, Compiler)])
    assert not np.allclose(compiled(unconverted).body_pos, compiled(child).body_pos)
    assert _bodies_kept(child, parent)


def test_a_free_joint_with_child_bodies_passes() -> None:
    """A <joint type="free"> in a body with child bodies is not aligned: it compiles the same."""
    child = loads(
        '<mujoco><compiler alignfree="true"/><worldbody><body pos="1 0 0">'
        '<joint type="free"/><geom size=".1" pos=".2 0 0"/>'
        '<body pos="0 1 0"><geom size=".1"/></body></body></worldbody></mujoco>'
    )
    assert _bodies_kept(child, loads("<mujoco/>"))


def test_a_free_joint_in_a_leaf_body_is_refused_with_what_to_write() -> None:
    """A leaf body's <joint type="free"> is refused: write it as <freejoint>."""
    child = loads(
        '<mujoco><compiler alignfree="true"/><worldbody><body pos="1 0 0">'
        '<joint type="free"/><geom size=".1" pos=".2 0 0"/></body></worldbody></mujoco>'
    )
    with pytest.raises(MjcfValueError, match=REFUSAL + "$"):
        in_conventions(child, loads("<mujoco/>"))


def test_a_free_type_from_a_childclass_is_refused() -> None:
    """A joint made free by its body's childclass is refused like one that says so."""
    child = loads(
        '<mujoco><compiler alignfree="true"/><default><default class="loose">'
        '<joint type="free"/></default></default><worldbody>'
        '<body pos="1 0 0" childclass="loose"><joint/><geom size=".1" pos=".2 0 0"/></body>'
        "</worldbody></mujoco>"
    )
    with pytest.raises(MjcfValueError, match=REFUSAL + "$"):
        in_conventions(child, loads("<mujoco/>"))


# -- Limit flags under another ``autolimits``: written only where unset or auto, and as MuJoCo
#    reads.
#
# The conversion writes each limit flag the child's ``autolimits`` decides
# (``limited``, ``ctrllimited``...) on the elements that leave it unset or auto; a
# flag a class sets stays the class's. An ``<intvelocity>`` sets ``actlimited``
# itself, so nothing is written there, and MuJoCo 4.0 rejects its ``actrange``
# under ``autolimits="false"``: refused, saying what to do. MuJoCo 3.9 limits every
# ``<intvelocity>`` (it needs an ``actrange``, under any ``autolimits``): there the
# range is kept as it is. MuJoCo, compiling the child alone, referees.


BODY = (
    '<worldbody><body><joint name="j" limited="true" range="-1 1"/><geom size="1"/></body>'
    "</worldbody>"
)


def _under_limit_flags(converted: Mujoco, parent: Mujoco) -> Mujoco:
    """The rewritten child with the parent's ``<compiler>`` in front of it."""
    return with_children(converted, [*parent.children, *converted.children])


def test_an_inheritrange_of_zero_leaves_a_position_unlimited() -> None:
    """A position with inheritrange="0" and no ctrlrange stays unlimited under autolimits off."""
    child = loads(
        f'<mujoco>{BODY}<actuator><position name="p" joint="j" kp="1" inheritrange="0"/>'
        "</actuator></mujoco>"
    )
    parent = loads('<mujoco><compiler autolimits="false"/></mujoco>')
    converted = in_conventions(child, parent)
    assert model_differences(compiled(child), compiled(_under_limit_flags(converted, parent))) == []
    assert not compiled(child).actuator_ctrllimited[0]


def test_a_flag_a_class_sets_is_left_to_the_class() -> None:
    """A joint whose class sets limited gets no limited of its own; it compiles the same."""
    child = loads(
        '<mujoco><compiler autolimits="false"/><default><default class="free_range">'
        '<joint limited="false"/></default></default><worldbody><body>'
        '<joint name="j" class="free_range" range="0 1"/><geom size="1"/></body></worldbody>'
        "</mujoco>"
    )
    parent = loads("<mujoco/>")
    converted = in_conventions(child, parent)
    joint = find(converted, "joint", name="j")
    assert joint is not None and get_attribute(joint, "limited") is None
    assert model_differences(compiled(child), compiled(_under_limit_flags(converted, parent))) == []


def test_nothing_is_written_for_an_integrated_velocity_activation_limit() -> None:
    """An intvelocity gets no actlimited (MuJoCo 3.9 has no such attribute); compiles the same.

    MuJoCo 3.9 rejects an intvelocity without an ``actrange``, so there it has one.
    """
    actrange = "" if MUJOCO_VERSION >= (4, 0) else ' actrange="-1 1"'
    child = loads(
        f'<mujoco><compiler autolimits="false"/>{BODY}'
        f'<actuator><intvelocity name="v" joint="j" kp="1"{actrange}/></actuator></mujoco>'
    )
    parent = loads("<mujoco/>")
    converted = in_conventions(child, parent)
    actuator = find(converted, "intvelocity", name="v")
    assert actuator is not None and get_attribute(actuator, "actlimited") is None
    assert get_attribute(actuator, "ctrllimited") == "false"
    found = compiled(_under_limit_flags(converted, parent))
    assert model_differences(compiled(child), found) == []


REJECTED = "^" + re.escape(
    "the parent's autolimits='false' makes MuJoCo reject the child's "
    "<intvelocity actrange>; give the two models the same autolimits"
)


@pytest.mark.parametrize(
    "actuators",
    [
        '<actuator><intvelocity joint="j" kp="1" actrange="-1 1"/></actuator>',
        '<default><general actrange="-1 1"/></default>'
        '<actuator><intvelocity joint="j" kp="1"/></actuator>',
    ],
    ids=["own", "from its class"],
)
def test_an_integrated_velocity_range_refuses_autolimits_false(actuators: str) -> None:
    """An intvelocity actrange, own or from a class, is refused under autolimits="false".

    MuJoCo 3.9 reads it under autolimits="false" too: there it is kept, and compiles the same.
    """
    child = loads(f"<mujoco>{BODY}{actuators}</mujoco>")
    assert compiled(child).actuator_actlimited[0]
    rejected = loads(f'<mujoco><compiler autolimits="false"/>{BODY}{actuators}</mujoco>')
    parent = loads('<mujoco><compiler autolimits="false"/></mujoco>')
    if MUJOCO_VERSION < (4, 0):
        assert compiled(rejected).actuator_actlimited[0]
        converted = in_conventions(child, parent)
        assert (
            model_differences(compiled(child), compiled(_under_limit_flags(converted, parent)))
            == []
        )
        return
    with pytest.raises(MjcfError, match="actrange"):  # MuJoCo rejects it under the parent's
        compiled(rejected)
    with pytest.raises(MjcfValueError, match=REJECTED + "$"):
        in_conventions(child, parent)


def test_inheritrange_still_limits_the_control() -> None:
    """A position with inheritrange="1" is ctrl-limited to its joint's range, as the child alone."""
    child = loads(
        f'<mujoco>{BODY}<actuator><position joint="j" kp="1" inheritrange="1"/></actuator></mujoco>'
    )
    parent = loads('<mujoco><compiler autolimits="false"/></mujoco>')
    found = compiled(_under_limit_flags(in_conventions(child, parent), parent))
    assert found.actuator_ctrllimited[0]
    assert np.array_equal(found.actuator_ctrlrange, compiled(child).actuator_ctrlrange)


# -- Numeric compiler settings are compared as the numbers MuJoCo reads, not as their text. ----
#
# ``settotalmass="3"`` and ``settotalmass="3.0"`` (or ``boundmass="0.5"`` and
# ``"5e-1"``) are one setting to MuJoCo: a child and parent that write them so
# share their conventions, and the child is taken as it is.


def test_numbers_written_differently_are_the_same_setting() -> None:
    """Equal numbers in other text change nothing but the removed <compiler>."""
    child = loads(
        '<mujoco><compiler settotalmass="3" boundmass="0.5" inertiagrouprange="0 5"/>'
        '<worldbody><body name="b"><joint/><geom size="1"/>'
        '<body name="c" pos="0 0 1"><joint/><geom size=".2"/></body></body></worldbody></mujoco>'
    )
    parent = loads(
        '<mujoco><compiler settotalmass="3.0" boundmass="5e-1" inertiagrouprange="0  5"/></mujoco>'
    )
    converted = in_conventions(child, parent)
    assert converted.worldbody is child.worldbody
    found = compiled(with_children(converted, [*parent.children, *converted.children]))
    assert model_differences(compiled(child), found) == []


# -- A child with elements whose contents are not in the tree is refused, saying what is
#    refused.
#
# MuJoCo before 4.0 expands a ``<composite>`` into bodies, joints and geoms that are
# nowhere in the tree, and an ``<include>`` names another file: their angles and
# limits cannot be rewritten, so converting the compiler settings is refused.


def test_a_composite_is_refused_when_settings_differ() -> None:
    """A <composite> in the child is refused, naming the conversion and the element."""
    child = loads(
        '<mujoco><worldbody><body name="b"><composite type="particle" count="2 2 2" '
        'spacing="0.1"><geom size=".01"/></composite></body></worldbody></mujoco>'
    )
    with pytest.raises(
        MjcfValueError,
        match=r"^cannot convert the compiler settings of a model with <composite> elements",
    ):
        in_conventions(child, loads('<mujoco><compiler angle="radian"/></mujoco>'))


# -- A child converted to the parent's angles may use the parent's assets (it compiles
#    attached).


PARENT = (
    '<mujoco><compiler angle="radian"/><asset><material name="red" rgba="1 0 0 1"/></asset>'
    "<worldbody/></mujoco>"
)
#: In degrees, with a material only the parent declares: it does not compile alone.
CHILD = (
    '<mujoco><worldbody><body name="a" euler="0 0 90"><joint/>'
    '<geom size="0.1" material="red"/></body></worldbody></mujoco>'
)


def test_a_child_using_the_parents_material_is_converted_without_compiling_it_alone() -> None:
    """Only the angle setting differs: the body turns as MuJoCo turns it, the geom is red."""
    scene = compiled(attach(loads(PARENT), loads(CHILD)))
    by_hand = PARENT.replace(
        "<worldbody/>",
        '<worldbody><body name="a" euler="0 0 1.5707963267948966"><joint/>'
        '<geom size="0.1" material="red"/></body></worldbody>',
    )
    expected = mujoco.MjModel.from_xml_string(by_hand)
    np.testing.assert_allclose(scene.body_quat, expected.body_quat, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(scene.geom_matid, expected.geom_matid)
    assert "<keyframe" not in dumps(attach(loads(PARENT), loads(CHILD)))


# -- A ``<replicate>``'s turn in another ``eulerseq``: checked only at the multiples it uses. --
#
# A replicate turns copy ``i`` by ``i`` times its ``euler``; copies 0 and 1 turn by
# nothing and by the angles themselves, which the parent's sequence always says
# (to rounding, larger next to gimbal lock). Only copies 2 and up can refuse the
# conversion. MuJoCo, compiling the child alone, referees.


def test_two_copies_next_to_gimbal_lock_are_converted() -> None:
    """Two copies turned next to gimbal lock convert, compiling to the child's quaternions."""
    child = loads(
        '<mujoco><compiler angle="radian" eulerseq="XYZ"/><worldbody>'
        '<replicate count="2" euler="1 1.5707863267948965 1.2">'
        '<body name="b"><geom size=".1" pos="1 0 0"/></body></replicate></worldbody></mujoco>'
    )
    parent = loads('<mujoco><compiler angle="radian" eulerseq="zyx"/></mujoco>')
    converted = in_conventions(child, parent)
    found = compiled(with_children(converted, [*parent.children, *converted.children]))
    expected = compiled(child)
    assert expected.nbody == found.nbody == 3
    assert np.allclose(found.body_quat, expected.body_quat, rtol=0, atol=1e-11)
    assert np.allclose(found.body_pos, expected.body_pos, rtol=0, atol=1e-11)
