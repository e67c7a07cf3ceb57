"""Tests of ``mjcf_model.transforms.scaling.rules``."""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence

import mujoco
import numpy as np
import pytest

from mjcf_model import compiled
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import (
    AnyElement,
    attribute_items,
    get_attribute,
    with_attributes,
)
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.serializers import dumps, loads
from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.pieces import NO_LENGTHS
from mjcf_model.transforms.scaling.rules import RULES, UNSCALED_BY_DECISION
from mjcf_model.transforms.scaling.transform import MassPolicy, scaled
from mjcf_model.tree.traversal import keyed_walk, map_elements
from tests.support.scale_cases import UNCHECKED, scale_cases
from tests.support.scale_elements import ScaleCase
from tests.support.scaling_oracle import (
    SCALING_FIXTURES,
    _scaled_copy,
    compiled_pair,
    scaled_model_problems,
)
from tests.support.schema_cases import known, reference_cases

# -- The complete scaling oracle: every float field classified, and the bugs it catches. -------
#
# MuJoCo compiles each model before and after scaling; :func:`scaled_model_problems`
# states the expected change of every field (:mod:`mjcf_model.bridge.scaled_fields`).


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_geom_and_pair_margins_and_gaps_scale(factor: float) -> None:
    """A geom's and a pair's margin and gap are distances: they compile multiplied."""
    text = """<mujoco><worldbody><body><freejoint/><geom name="a" size="0.1" margin="0.01"
    gap="0.005"/></body><geom name="b" type="plane" size="1 1 0.1" margin="0.02"/></worldbody>
    <contact><pair geom1="a" geom2="b" margin="0.03" gap="0.01"/></contact></mujoco>"""
    original, changed = compiled_pair(text, factor)
    assert scaled_model_problems(original, changed, factor) == []
    assert np.isclose(changed.geom("a").margin[0], factor * 0.01)


@pytest.mark.parametrize("tag", ["connect", "weld"])
def test_connect_and_weld_anchors_scale(tag: str) -> None:
    """Both anchors of a connect or weld (and a weld's relative position) compile multiplied."""
    text = f"""<mujoco><worldbody><body name="a" pos="0 0 1"><freejoint/><geom size="0.1"/>
    </body><body name="b" pos="1 0 1"><freejoint/><geom size="0.1"/></body></worldbody>
    <equality><{tag} body1="a" body2="b" anchor="0.3 0.2 0.1"/></equality></mujoco>"""
    original, changed = compiled_pair(text, 2.0)
    assert scaled_model_problems(original, changed, 2.0) == []
    assert np.allclose(changed.eq_data[0, :3], [0.6, 0.4, 0.2])


@pytest.mark.parametrize("factor", [2.0, 3.0])
def test_cylinder_with_the_built_in_area_gets_it_scaled(factor: float) -> None:
    """A cylinder actuator's area is a length squared, MuJoCo's default of 1 included.

    An area the element writes overrides its class's diameter, and is scaled.
    """
    text = """<mujoco><default><default class="bore"><cylinder diameter="0.2"/></default>
    </default><worldbody><body><joint name="s" type="slide"/><geom size="0.1"/>
    </body></worldbody><actuator><cylinder joint="s"/><cylinder joint="s" area="2"/>
    <cylinder joint="s" diameter="0.1"/><cylinder joint="s" class="bore"/>
    <cylinder joint="s" class="bore" area="3"/></actuator></mujoco>"""
    original, changed = compiled_pair(text, factor)
    assert scaled_model_problems(original, changed, factor) == []
    assert np.allclose(
        changed.actuator_gainprm[:, 0], factor**2 * original.actuator_gainprm[:, 0], rtol=1e-12
    )


def test_a_site_gear_mixing_offset_and_rotation_measures_a_scaled_length() -> None:
    """A site transmission with a refsite and a gear of both kinds: its length doubles."""
    text = """<mujoco><worldbody>
      <site name="ref"/>
      <body name="arm"><joint type="slide"/><geom size=".1"/>
        <site name="tip" pos=".3 .1 0" euler="0 0 28.6"/></body>
    </worldbody>
    <actuator><general site="tip" refsite="ref" gear="1 0 0 0 0 1"/>
      <general site="tip" refsite="ref" gear="0 0 0 0 0 1"/></actuator></mujoco>"""
    original, changed = compiled_pair(text, 2.0)
    assert original.actuator_length0[0] > 0.3  # both parts measured
    assert np.isclose(changed.actuator_length0[0], 2 * original.actuator_length0[0], rtol=1e-12)
    assert np.isclose(changed.actuator_length0[1], original.actuator_length0[1], rtol=1e-12)
    assert scaled_model_problems(original, changed, 2.0) == []


def test_position_targets_on_a_slide_joint_scale_beside_a_replicate_of_geoms() -> None:
    """A replicate copying only geoms hides no joint: slide targets and key controls scale."""
    text = """<mujoco><worldbody><body>
      <joint name="rail" type="slide"/><geom size=".1"/>
      <replicate count="2" offset=".3 0 0"><geom size=".1"/></replicate>
    </body></worldbody>
    <actuator><position joint="rail" kp="10" ctrlrange="-.5 .5"/></actuator>
    <keyframe><key ctrl=".25"/></keyframe></mujoco>"""
    original, changed = compiled_pair(text, 2.0)
    assert np.array_equal(changed.actuator_ctrlrange, 2 * original.actuator_ctrlrange)
    assert np.array_equal(changed.key_ctrl, 2 * original.key_ctrl)
    assert scaled_model_problems(original, changed, 2.0) == []


@pytest.mark.parametrize("default", ["position", "general"])
def test_a_class_given_position_target_range_scales_where_its_joint_slides(default: str) -> None:
    """A class's ctrlrange is a length on the slide servo's, an angle on the hinge servo's."""
    text = f"""<mujoco><default><default class="servo">
      <{default} ctrlrange="-.5 .5"/></default></default>
    <worldbody><body><joint name="rail" type="slide"/><joint name="pin" axis="0 1 0"/>
      <geom size=".1"/></body></worldbody>
    <actuator><position class="servo" joint="rail" kp="10"/>
      <position class="servo" joint="pin" kp="10"/></actuator></mujoco>"""
    original, changed = compiled_pair(text, 2.0)
    assert np.array_equal(changed.actuator_ctrlrange[0], 2 * original.actuator_ctrlrange[0])
    assert np.array_equal(changed.actuator_ctrlrange[1], original.actuator_ctrlrange[1])
    assert scaled_model_problems(original, changed, 2.0) == []


# -- Scaling: every length multiplied, checked by MuJoCo on the corpus and on drawn models. ----


#: Attribute names that hold a length wherever they appear.
LENGTH_ATTRIBUTES = frozenset(
    {"pos", "size", "fromto", "anchor", "margin", "gap", "vertex", "offset", "bindpos", "radius"}
)


def test_every_schema_key_and_node_type_has_a_scaling_rule() -> None:
    """Every element of the table, and so every typed class, has an explicit rule."""
    assert set(RULES) == set(SCHEMA)
    for key, cls in CLASS_BY_KEY.items():
        assert key in RULES, cls.__name__


def test_elements_with_length_attributes_do_not_use_the_no_lengths_rule() -> None:
    """An element with a position, size, margin... has a rule, unless left alone on purpose."""
    forgotten = [
        key
        for key, spec in SCHEMA.items()
        if spec.attributes & LENGTH_ATTRIBUTES
        and RULES[key] is NO_LENGTHS
        and not key.startswith("visual")
    ]
    assert sorted(forgotten) == sorted(UNSCALED_BY_DECISION)


# -- Scaling on constructs real models use: masses, shells, flexcomps, SDFs, includes, skin
#    files.
#
# The fixtures live in ``tests/fixtures/scaling``; MuJoCo compiles each original and
# each scaled copy, and the oracle compares the compiled arrays.


def test_flexcomp_points_are_placed_once_scaled() -> None:
    """Every flex vertex and generated body sits at twice its position after ``mj_forward``."""
    path = SCALING_FIXTURES / "flexcomp.xml"
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = _scaled_copy(path, 2.0)
    before, after = mujoco.MjData(original), mujoco.MjData(changed)
    mujoco.mj_forward(original, before)
    mujoco.mj_forward(changed, after)
    assert original.nflexvert > 200
    assert np.allclose(after.flexvert_xpos, 2 * before.flexvert_xpos, rtol=1e-9, atol=1e-15)
    assert np.allclose(after.xpos, 2 * before.xpos, rtol=1e-9, atol=1e-15)


_DISC = """<mujoco><worldbody><body name="b"><flexcomp name="d" type="disc" count="4 4 1"
    spacing="{spacing} {spacing} {depth}" radius="{radius}" mass="1"><edge equality="true"/>
    {contact}</flexcomp></body></worldbody></mujoco>"""


def _disc_fixes(scale: float, margin: float | None) -> str:
    """The disc scaled by hand: spacing by the root of ``scale``, radius and margin by it."""
    root = math.sqrt(scale)
    contact = "" if margin is None else f'<contact margin="{margin * scale}"/>'
    return _DISC.format(
        spacing=0.06 * root, depth=0.1 * root, radius=0.004 * scale, contact=contact
    )


@pytest.mark.parametrize("margin", [None, 0.01, 0.03])
@pytest.mark.parametrize("factor", [2, 4, 9, 16, 64])
def test_a_disc_flexcomp_is_refused_exactly_when_mujoco_would_reject_it(
    factor: float, margin: float | None
) -> None:
    """Scaling refuses a disc whose spacing falls under twice its radius plus its margin.

    MuJoCo is the referee: it compiles the disc scaled by hand, or rejects it.
    """
    mujoco.MjModel.from_xml_string(_disc_fixes(1, margin))
    try:
        mujoco.MjModel.from_xml_string(_disc_fixes(factor, margin))
        rejected = False
    except ValueError as error:
        assert "Spacing must be larger" in str(error)
        rejected = True
    if rejected:
        with pytest.raises(MjcfValueError) as refused:
            scaled(loads(_disc_fixes(1, margin)), factor)
        assert str(refused.value) == (
            f"cannot scale the disc flexcomp 'd' by {(float(factor),) * 3}: its spacing grows "
            "with the square root of the factor but must exceed twice its radius plus its "
            "margin, which grow with the factor; use a smaller factor or a larger spacing"
        )
    else:
        mujoco.MjModel.from_xml_string(dumps(scaled(loads(_disc_fixes(1, margin)), factor)))


# -- Every length attribute the scaling rules scale, set on a small model and refereed by
#    MuJoCo.
#
# Each case (``tests/support/scale_cases.py``) sets one attribute; scaling the model by 2 must
# multiply the value MuJoCo compiles from it by 2 (an area by 4). Every attribute that
# :func:`scaled` changes on these models must have a case of its own.


CASES = scale_cases()
FACTOR = 3.0  # not 2, where doubling, squaring and adding agree


def changed_attributes(xml: str) -> set[tuple[str, str]]:
    """The ``(key, attribute)`` pairs with a value that scaling the model by ``FACTOR`` writes."""

    def values(node: AnyElement) -> Counter[tuple[str, str, object]]:
        return Counter(
            (str(key), attribute, value)
            for element, key, _ in keyed_walk(node)
            for attribute, value in attribute_items(element)
        )

    written = values(scaled(loads(xml), FACTOR)) - values(loads(xml))
    return {(key, attribute) for key, attribute, _ in written}


@pytest.mark.parametrize("case", CASES, ids=[f"{c.key} {c.attribute}" for c in CASES])
def test_scaled_case_multiplies_the_compiled_value(case: ScaleCase) -> None:
    """Scaling the case by 2 multiplies what MuJoCo compiles from the attribute by 2 (or 4).

    An element the installed MuJoCo does not read (MuJoCo 3.9 has no ``pid``) must be refused.
    """
    assert (case.key, case.attribute) in changed_attributes(case.xml)
    if not known(case.key, case.attribute):
        with pytest.raises(ValueError, match="unrecognized"):
            mujoco.MjModel.from_xml_string(case.xml)
        return
    original = case.value(mujoco.MjModel.from_xml_string(case.xml))
    changed = case.value(compiled(scaled(loads(case.xml), FACTOR)))
    assert np.any(original != 0)
    np.testing.assert_allclose(changed, original * FACTOR**case.power, rtol=case.rtol, atol=0)


def test_every_attribute_scaling_writes_has_a_case() -> None:
    """What scaling changes on any case, the prefix cases too, is an attribute with a case.

    Scaling refuses ``<attach>`` (it scales the expansion), so that prefix case is left out.
    """
    covered = {(c.key, c.attribute) for c in CASES}
    models = [c.xml for c in CASES] + [
        c.xml for c in reference_cases().values() if c.key != "body/attach"
    ]
    written = set().union(*(changed_attributes(xml) for xml in models))
    assert sorted(written - covered) == []


def test_every_key_with_a_scaling_rule_has_a_case_or_a_reason() -> None:
    """A key whose rule scales something has a case, or a listed reason it has none."""
    scaling = {key for key, rule in RULES.items() if rule is not NO_LENGTHS}
    assert sorted(scaling - {c.key for c in CASES} - UNCHECKED.keys()) == []
    assert sorted(UNCHECKED.keys() & {c.key for c in CASES}) == []


@pytest.mark.parametrize("key", ["actuator", "actuator/adhesion", "actuator/orientation"])
def test_unchecked_actuator_keys_still_have_no_crank_length(key: str) -> None:
    """The actuator keys listed as unchecked still have no ``cranklength`` to scale."""
    assert "cranklength" not in SCHEMA[key].attributes


# -- The compiler's ``boundmass`` and ``boundinertia`` scale as the masses and inertias they
#    bound.
#
# ``<compiler>`` keeps both as text (its typed class does not model them); they
# scale all the same: ``boundinertia`` with the length squared (times the mass
# factor), ``boundmass`` with the mass factor. A body lighter than the bound
# compiles to the bound, so MuJoCo's compiled mass and inertia of such a body
# are the original's scaled.


#: A body whose mass and inertia MuJoCo raises to the bounds, and one above them.
_MODEL_COMPILER_BOUNDS = """<mujoco><compiler boundmass="0.5" boundinertia="0.01"/><worldbody>
  <body name="tiny"><freejoint/><geom size=".001" density="1"/></body>
  <body name="big" pos="1 0 0"><freejoint/><geom size=".2"/></body>
</worldbody></mujoco>"""


@pytest.mark.parametrize(("mass", "mass_factor"), [("keep", 1.0), ("volume", 8.0)])
def test_compiler_bounds_written_as_text_scale_with_what_they_bound(
    mass: MassPolicy, mass_factor: float
) -> None:
    """Scaled by two, the bounded body weighs the bound times the mass factor."""
    model = loads(_MODEL_COMPILER_BOUNDS)
    assert isinstance(get_attribute(model.compiler, "boundinertia"), str)
    original = mujoco.MjModel.from_xml_string(_MODEL_COMPILER_BOUNDS)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(model, 2.0, mass=mass)))
    tiny = original.body("tiny").id
    assert original.body_mass[tiny] == 0.5
    assert np.array_equal(original.body_inertia[tiny], [0.01] * 3)
    assert np.isclose(changed.body_mass[tiny], 0.5 * mass_factor, rtol=1e-12)
    np.testing.assert_allclose(changed.body_inertia[tiny], [0.04 * mass_factor] * 3, rtol=1e-12)
    assert scaled_model_problems(original, changed, 2.0, mass=mass) == []


# -- A scaled disc flexcomp is refused only where MuJoCo rejects it, at the limit and off it. --
#
# MuJoCo requires a disc's spacing to be at least twice its radius plus its contact
# margin ("Spacing must be larger than geometry size", equality accepted). Scaling
# multiplies the spacing by the square root of the factor and the radius and the
# margin by the factor; MuJoCo compiles the disc scaled by hand, and the scaled
# model must compile to the same flex.


def _disc_flexcomp_spacing(spacing: float, radius: float, contact: str) -> str:
    """A disc of ``spacing`` (depth five times it) and ``radius``, with a ``<contact>`` child."""
    return _DISC.format(spacing=spacing, depth=5 * spacing, radius=radius, contact=contact)


def _compiled_flex(text: str) -> tuple[np.ndarray, np.ndarray]:
    """MuJoCo's flex radius and vertex positions (at ``qpos0``) of ``text``."""
    model = mujoco.MjModel.from_xml_string(text)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return model.flex_radius.copy(), data.flexvert_xpos.copy()


@pytest.mark.parametrize(
    ("radius", "margin"),
    [(0.25, None), (0.125, 0.25)],
    ids=["radius", "radius-and-margin"],
)
def test_a_disc_scaled_to_exactly_the_limit_is_accepted_as_mujoco_accepts_it(
    radius: float, margin: float | None
) -> None:
    """Scaled by four, the spacing (1 to 2) equals twice the radius plus the margin.

    Every value is exact in binary, so the scaled disc sits on MuJoCo's limit.
    """
    factor = 4.0
    contact = "" if margin is None else f'<contact margin="{margin}"/>'
    by_hand_contact = "" if margin is None else f'<contact margin="{margin * factor}"/>'
    by_hand = _disc_flexcomp_spacing(2.0, radius * factor, by_hand_contact)
    assert 2 * radius * factor + (margin or 0.0) * factor == 2.0
    expected = _compiled_flex(by_hand)  # MuJoCo accepts the limit itself
    result = _compiled_flex(
        dumps(scaled(loads(_disc_flexcomp_spacing(1.0, radius, contact)), factor))
    )
    assert np.array_equal(result[0], expected[0])
    assert np.allclose(result[1], expected[1], rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("factor", [2.0, 4.0])
def test_a_contact_without_a_margin_adds_none_to_the_disc_limit(factor: float) -> None:
    """A ``<contact>`` child that writes no margin has MuJoCo's zero margin: no refusal."""
    contact = '<contact condim="3"/>'
    by_hand = _disc_flexcomp_spacing(0.06 * np.sqrt(factor), 0.01 * factor, contact)
    expected = _compiled_flex(by_hand)  # MuJoCo accepts it
    result = _compiled_flex(
        dumps(scaled(loads(_disc_flexcomp_spacing(0.06, 0.01, contact)), factor))
    )
    assert np.allclose(result[0], expected[0], rtol=1e-12)
    assert np.allclose(result[1], expected[1], rtol=1e-12, atol=1e-15)


# -- A site transmission's gear scales its rotational part only where both parts are set. ------
#
# With a ``refsite`` MuJoCo measures ``gear[:3]`` along the site's offset and
# ``gear[3:]`` along its rotation. A gear of one part only (written short, the
# rest zero, as no class gives a gear here) measures a length or an angle and
# stays as written; a gear of both parts measures a length, so its rotational
# part is a lever arm and scales. MuJoCo compiles the scaled model to the
# original scaled, and measures the actuator's length accordingly.


_MODEL_SITE_GEAR_PARTS = """<mujoco><worldbody>
  <site name="ref"/>
  <body name="arm"><joint type="slide"/><geom size=".1"/>
    <site name="tip" pos=".3 .1 0" euler="10 0 28.6"/></body>
</worldbody>
<actuator><general site="tip" refsite="ref" gear="{gear}"/></actuator></mujoco>"""


def _compiled_pair_site_gear_parts(gear: str) -> tuple[mujoco.MjModel, mujoco.MjModel]:
    """MuJoCo's compilation of the model with ``gear`` and of it scaled by two."""
    text = _MODEL_SITE_GEAR_PARTS.format(gear=gear)
    original = mujoco.MjModel.from_xml_string(text)
    return original, mujoco.MjModel.from_xml_string(dumps(scaled(loads(text), 2.0)))


@pytest.mark.parametrize(
    ("gear", "length"),
    [("1", 2.0), ("1 0", 2.0), (".5 2", 2.0), ("0 0 0 1 0 0", 1.0), ("0 0 0 0 1 1", 1.0)],
)
def test_a_gear_of_one_part_stays(gear: str, length: float) -> None:
    """A translation's length doubles, a rotation's angle stays; the gear is unchanged."""
    original, changed = _compiled_pair_site_gear_parts(gear)
    translation, rotation = original.actuator_gear[0, :3], original.actuator_gear[0, 3:]
    assert np.any(translation) != np.any(rotation)
    assert original.actuator_length0[0] != 0
    assert np.array_equal(changed.actuator_gear, original.actuator_gear)
    assert np.isclose(
        changed.actuator_length0[0], length * original.actuator_length0[0], rtol=1e-12
    )
    assert scaled_model_problems(original, changed, 2.0) == []


@pytest.mark.parametrize("gear", ["1 0 0 1 0 0", "0 2 0 0 0 1"])
def test_a_gear_of_both_parts_scales_its_rotation(gear: str) -> None:
    """The rotational part doubles with the length it now contributes to."""
    original, changed = _compiled_pair_site_gear_parts(gear)
    expected = original.actuator_gear[0] * [1, 1, 1, 2, 2, 2]
    assert np.array_equal(changed.actuator_gear[0], expected)
    assert np.isclose(changed.actuator_length0[0], 2 * original.actuator_length0[0], rtol=1e-12)
    assert scaled_model_problems(original, changed, 2.0) == []


@pytest.mark.parametrize(
    ("own", "of_class"),
    [("1", "0 0 0 0 0 1"), ("1 0", "0 0 0 0 1"), ("2", "1 0 0 0 1 0"), (None, "1 0 0 0 0 1")],
)
def test_a_short_gear_keeps_its_class_trailing_values(own: str | None, of_class: str) -> None:
    """MuJoCo reads ``gear="1"`` over a class's ``0 0 0 0 0 1``: two parts, the rotation scales.

    The scaled model compiles to the original scaled (``actuator_gear`` and the
    actuator's ``length0``, measured by MuJoCo).
    """
    written = "" if own is None else f' gear="{own}"'
    text = (
        f'<mujoco><default><general gear="{of_class}"/></default><worldbody><site name="ref"/>'
        '<body><joint type="slide"/><geom size=".1"/><site name="tip" pos=".3 .1 0" '
        'euler="0 0 28.6"/></body></worldbody><actuator>'
        f'<general site="tip" refsite="ref"{written}/></actuator></mujoco>'
    )
    original = mujoco.MjModel.from_xml_string(text)
    assert np.count_nonzero(original.actuator_gear[0, :3]) and np.count_nonzero(
        original.actuator_gear[0, 3:]
    )
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(text), 2.0)))
    assert scaled_model_problems(original, changed, 2.0) == []


# -- Scaled keyframes: each ``qpos``, ``qvel`` and ``ctrl`` entry scales as its joint or
#    actuator.
#
# MuJoCo compiles the original and the scaled model; the oracle
# (:func:`tests.support.scaling_oracle.scaled_model_problems`) and the compiled ``key_*``
# arrays say which entries are lengths: a free joint's position and linear velocity
# and a slide joint's coordinate are, wherever the joint stands in ``qpos``; the
# control of a position servo on a slide joint is, and a ``<config>`` setting of a
# plugin actuator is no actuator of its own.


#: A slide joint before a free joint in ``qpos`` (the free joint's entries start at 1).
_SLIDE_THEN_FREE = """<mujoco><worldbody>
  <body name="rail"><joint name="s" type="slide" axis="1 0 0"/><geom size=".1"/></body>
  <body name="ball" pos="0 0 1"><freejoint/><geom size=".1"/></body>
  <body name="arm" pos="1 0 0"><joint name="h" type="hinge"/><geom size=".1"/></body>
</worldbody>
<keyframe><key qpos=".3  1 2 3  1 0 0 0  .7" qvel=".5  1 2 3  .1 .2 .3  .4"/></keyframe>
</mujoco>"""

#: A plugin actuator with a ``<config>`` child, before a position servo on a slide joint.
_PLUGIN_THEN_SERVO = """<mujoco><extension><plugin plugin="mujoco.pid"/></extension>
<worldbody><body><joint name="h" type="hinge"/>
  <joint name="s" type="slide" axis="1 0 0"/><geom size=".1"/></body></worldbody>
<actuator><plugin joint="h" plugin="mujoco.pid"><config key="kp" value="4"/></plugin>
  <position joint="s" kp="10" ctrlrange="-1 1"/></actuator>
<keyframe><key ctrl=".1 .25"/></keyframe></mujoco>"""


def _compiled_pair_keyframe_layout(
    text: str, factor: float
) -> tuple[mujoco.MjModel, mujoco.MjModel]:
    """MuJoCo's compilation of ``text`` and of it scaled by ``factor``."""
    original = mujoco.MjModel.from_xml_string(text)
    return original, mujoco.MjModel.from_xml_string(dumps(scaled(loads(text), factor)))


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_a_free_joint_after_a_slide_scales_its_key_position_and_velocity(factor: float) -> None:
    """The slide's entry and the free joint's position and linear velocity scale; the rest stay."""
    original, changed = _compiled_pair_keyframe_layout(_SLIDE_THEN_FREE, factor)
    assert scaled_model_problems(original, changed, factor) == []
    qpos_factors = np.array([factor, factor, factor, factor, 1, 1, 1, 1, 1])
    qvel_factors = np.array([factor, factor, factor, factor, 1, 1, 1, 1])
    assert np.allclose(changed.key_qpos[0], original.key_qpos[0] * qpos_factors, rtol=1e-12)
    assert np.allclose(changed.key_qvel[0], original.key_qvel[0] * qvel_factors, rtol=1e-12)


def test_a_plugin_actuators_config_is_not_counted_among_the_key_controls() -> None:
    """The servo's control is the key's second entry: it scales; the plugin's stays."""
    original, changed = _compiled_pair_keyframe_layout(_PLUGIN_THEN_SERVO, 2.0)
    assert original.nu == 2
    assert np.allclose(changed.key_ctrl[0], [0.1, 0.5], rtol=1e-12)
    assert np.allclose(changed.actuator_ctrlrange[1], [-2.0, 2.0], rtol=1e-12)
    assert scaled_model_problems(original, changed, 2.0) == []


def test_a_key_scaled_without_its_model_scales_only_its_mocap_positions() -> None:
    """Without the model, the joints and actuators the entries belong to are unknown.

    The key rule then scales ``mpos`` alone, and MuJoCo reads the key so changed
    with every other entry as written.
    """
    text = """<mujoco><worldbody><body name="m" mocap="true" pos="0 0 1"><geom size=".1"
    contype="0" conaffinity="0"/></body><body><joint name="s" type="slide"/><geom size=".1"/>
    </body></worldbody><actuator><position joint="s" kp="1"/></actuator>
    <keyframe><key qpos=".3" ctrl=".2" mpos="1 2 3"/></keyframe></mujoco>"""
    model = loads(text)
    context = ScaleContext(factors=(2.0, 2.0, 2.0))  # no model

    def key_rule(
        element: AnyElement, key: str | None, ancestors: Sequence[AnyElement]
    ) -> AnyElement:
        if key != "keyframe/key":
            return element
        changes = RULES[key](element, ancestors, context)
        assert set(changes) == {"mpos"}
        return with_attributes(element, changes)

    original = mujoco.MjModel.from_xml_string(text)
    changed = mujoco.MjModel.from_xml_string(dumps(map_elements(key_rule, model)))
    assert np.array_equal(changed.key_mpos, 2 * original.key_mpos)
    assert np.array_equal(changed.key_qpos, original.key_qpos)
    assert np.array_equal(changed.key_ctrl, original.key_ctrl)
