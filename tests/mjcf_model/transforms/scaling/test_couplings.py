"""Tests of ``mjcf_model.transforms.scaling.couplings``."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model.serializers import dumps, loads
from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.rules import RULES
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.traversal import with_children
from tests.support.scaling_oracle import ALIGNED_SLIDES, compiled_pair, scaled_model_problems

# -- The complete scaling oracle: every float field classified, and the bugs it catches. -------
#
# MuJoCo compiles each model before and after scaling; :func:`scaled_model_problems`
# states the expected change of every field (:mod:`mjcf_model.bridge.scaled_fields`).


@pytest.mark.parametrize(
    ("types", "polycoef"),
    [(("hinge", "slide"), None), (("slide", "hinge"), "0.1 2 0 0 0"), (("slide", "slide"), None)],
)
def test_joint_coupling_coefficients_follow_the_joint_units(
    types: tuple[str, str], polycoef: str | None
) -> None:
    """``joint1 = a0 + a1 joint2 + ...`` keeps meaning when one of the joints slides."""
    coefficients = "" if polycoef is None else f' polycoef="{polycoef}"'
    text = f"""<mujoco><worldbody><body><joint name="j1" type="{types[0]}"/>
    <joint name="j2" type="{types[1]}" axis="1 0 0"/><geom size="0.1"/></body></worldbody>
    <equality><joint joint1="j1" joint2="j2"{coefficients}/></equality></mujoco>"""
    original, changed = compiled_pair(text, 2.0)
    assert scaled_model_problems(original, changed, 2.0) == []


# -- Scaled tendons and tendon couplings behave as the original scaled, MuJoCo measuring. ------
#
# A spatial tendon's length is a length; a fixed one's is a length when a slide
# joint is in it and an angle over hinges alone. MuJoCo computes every tendon's
# length and every equality's violation at the same configurations of the
# original and the scaled model (slide coordinates scaled).


#: Slide joints on two axes and a hinge; a spatial tendon whose spring length MuJoCo
#: measures (``-1 -1``); fixed tendons over hinges only, slides only and both; tendon
#: couplings between every kind, and one alone.
_MODEL_COUPLINGS = """<mujoco><worldbody><body><joint name="x" type="slide" axis="1 0 0" ref="0.1"/>
<joint name="h" type="hinge" axis="0 1 0" ref="0.3"/><geom size="0.1"/><site name="a"/>
<body pos="0 0 1"><joint name="z" type="slide"/><geom size="0.1"/><site name="b" pos="0.2 0 0"/>
</body></body></worldbody><tendon>
<spatial name="rope" springlength="-1 -1" stiffness="1"><site site="a"/><site site="b"/></spatial>
<fixed name="hinges"><joint joint="h" coef="1.5"/></fixed>
<fixed name="slides" range="-1 1" limited="true"><joint joint="x" coef="2"/>
<joint joint="z" coef="-1"/></fixed>
<fixed name="mixed" range="-0.5 0.5" limited="true" springlength="0.2">
<joint joint="x" coef="2"/><joint joint="h" coef="0.25"/></fixed></tendon>
<equality><tendon tendon1="rope" tendon2="hinges" polycoef="0.1 0.2 0.3 0.4 0.5"/>
<tendon tendon1="hinges" tendon2="mixed" polycoef="0.1 0.2 0.3"/>
<tendon tendon1="mixed" tendon2="slides" polycoef="0.05 -1 0.5"/>
<tendon tendon1="slides" tendon2="rope"/><tendon tendon1="mixed" polycoef="0.3"/>
</equality></mujoco>"""

#: Each tendon's length is a length (True) or an angle (False).
_LENGTHS = {"rope": True, "hinges": False, "slides": True, "mixed": True}


def _measured(model: mujoco.MjModel, qpos: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Tendon lengths and equality violations MuJoCo computes at ``qpos``."""
    data = mujoco.MjData(model)
    data.qpos[:] = qpos
    mujoco.mj_forward(model, data)
    rows = data.efc_type[: data.nefc] == mujoco.mjtConstraint.mjCNSTR_EQUALITY
    violations = np.zeros(model.neq)
    violations[data.efc_id[: data.nefc][rows]] = data.efc_pos[: data.nefc][rows]
    return data.ten_length.copy(), violations


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_tendons_and_their_couplings_measure_the_scaled_lengths(factor: float) -> None:
    """At every configuration each tendon measures ``factor`` times (an angle: the same) its length.

    Each tendon coupling's violation is in its first tendon's unit, so it scales with it.
    """
    original = mujoco.MjModel.from_xml_string(_MODEL_COUPLINGS)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(_MODEL_COUPLINGS), factor)))
    assert scaled_model_problems(original, changed, factor) == []
    tendons = np.array([factor if _LENGTHS[original.tendon(i).name] else 1.0 for i in range(4)])
    slides = np.where(original.jnt_type == mujoco.mjtJoint.mjJNT_SLIDE, factor, 1.0)
    for qpos in np.random.default_rng(7).uniform(-1, 1, (5, original.nq)):
        lengths, violations = _measured(original, qpos)
        lengths_after, violations_after = _measured(changed, slides * qpos)
        assert np.allclose(lengths_after, tendons * lengths, rtol=1e-9, atol=1e-12)
        first = tendons[original.eq_obj1id]
        assert np.allclose(violations_after, first * violations, rtol=1e-9, atol=1e-12)


# -- Couplings scaled apart from the joints and tendons they couple are kept as written. -------
#
# An ``<equality>`` section scaled alone cannot see the joints and tendons its
# couplings name, and a rule called without a model cannot either: a coupling's
# ``polycoef`` is then left as written instead of guessed. For couplings of angles
# (a hinge, a fixed tendon over hinges) that is also what scaling the whole model
# does, and MuJoCo compiles the whole scaled model to the original scaled.


#: Couplings of one object (held at ``a0``) and of two, of angles, and a connect anchor.
_MODEL_COUPLING_PARTS = """<mujoco><worldbody>
  <body name="a"><joint name="h1" type="hinge"/><joint name="h2" type="hinge" axis="1 0 0"/>
    <geom size=".1"/></body>
  <body name="b" pos="0 0 1"><joint type="slide"/><geom size=".1"/></body>
</worldbody>
<tendon><fixed name="t1"><joint joint="h1" coef="2"/></fixed>
  <fixed name="t2"><joint joint="h2" coef="1"/></fixed></tendon>
<equality><joint joint1="h1" polycoef=".3 1 0 0 0"/><joint joint1="h1" joint2="h2"
  polycoef=".1 2 0 0 0"/><tendon tendon1="t1" polycoef=".2 1 0 0 0"/>
  <tendon tendon1="t1" tendon2="t2" polycoef=".1 .5 0 0 0"/>
  <connect body1="a" body2="b" anchor=".1 .2 .3"/></equality></mujoco>"""


def test_an_equality_section_scaled_alone_is_the_section_of_the_model_scaled() -> None:
    """Its couplings, out of sight of their joints and tendons, stay; its anchor scales.

    Scaling the whole model changes exactly the same, and MuJoCo compiles that
    model to the original scaled; the section scaled alone, put in its place,
    compiles to the same equality data.
    """
    model = loads(_MODEL_COUPLING_PARTS)
    whole = scaled(model, 2.0)
    alone = scaled(model.equality, 2.0)
    assert alone == whole.equality
    assert [e.polycoef for e in alone.elements[:4]] == [
        e.polycoef for e in model.equality.elements[:4]
    ]
    original = mujoco.MjModel.from_xml_string(_MODEL_COUPLING_PARTS)
    changed = mujoco.MjModel.from_xml_string(dumps(whole))
    assert scaled_model_problems(original, changed, 2.0) == []
    spliced = with_children(whole, [alone if c is whole.equality else c for c in whole.children])
    compiled = mujoco.MjModel.from_xml_string(dumps(spliced))
    assert np.array_equal(compiled.eq_data, changed.eq_data)


def test_a_tendon_coupling_ruled_without_a_model_is_kept() -> None:
    """Without a model the tendons are unknown: the rule changes nothing."""
    model = loads(_MODEL_COUPLING_PARTS)
    section = model.equality
    context = ScaleContext(factors=(2.0, 2.0, 2.0))  # no model
    for coupling in section.elements[2:4]:
        assert RULES["equality/tendon"](coupling, (model, section), context) == {}


# -- Per-axis factors: a joint coupling's coefficients follow each slide's own axis. -----------
#
# A slide's coordinate scales by the factor along its axis (MuJoCo's kinematics
# show it: ``test_per_axis_factors_scale_axis_aligned_slides_exactly``), so in
# ``y1 = a0 + a1 y2 + ... + a4 y2**4`` each ``a_k`` scales by ``f1 / f2**k``, where
# ``f1`` and ``f2`` are the factors along the two joints' axes (MuJoCo's default
# axis is ``z``, a class may give another). MuJoCo compiles the coefficients into
# ``eq_data``.


#: Couplings between the x, y (axis from its class) and z slides, and of x alone.
_COUPLINGS = """<equality><joint joint1="x" joint2="z" polycoef=".1 .5 .2 0 0"/>
  <joint joint1="z" joint2="y" polycoef=".2 2 0 .3 0"/><joint joint1="x" polycoef=".3"/>
</equality>"""


def test_joint_couplings_scale_by_the_factors_along_each_slide() -> None:
    """The slide x scales by 2, y by 3, z by 5: each coefficient by ``f1 / f2**k``."""
    text = ALIGNED_SLIDES.replace("<keyframe>", f"{_COUPLINGS}<keyframe>")
    factors = np.array([2.0, 3.0, 5.0])
    original = mujoco.MjModel.from_xml_string(text)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(text), factors)))
    along = dict(zip(("x", "z", "y"), np.abs(original.jnt_axis) @ factors, strict=True))
    assert along == {"x": 2.0, "z": 5.0, "y": 3.0}
    powers = np.arange(5)
    expected = [
        along["x"] / along["z"] ** powers,
        along["z"] / along["y"] ** powers,
        [along["x"], 1, 1, 1, 1],  # alone: only a0, the position it holds x at, is read
    ]
    np.testing.assert_allclose(
        changed.eq_data[:, :5], original.eq_data[:, :5] * np.array(expected), rtol=1e-12
    )


# -- A fixed tendon's ``coef`` changes only where the tendon's unit and its joint's differ. ----
#
# Over slides alone (or hinges alone) a fixed tendon's length is in its joints'
# units, so under a uniform factor no coefficient changes and the tendon section
# is shared by the scaled model, unchanged; MuJoCo compiles that model to the
# original scaled. A ``coef`` read without its tendon cannot be placed and is kept.


#: Fixed tendons over two slides and over two hinges, no length written.
_MODEL_TENDON_COEFFICIENTS = """<mujoco><worldbody><body>
  <joint name="x" type="slide" axis="1 0 0"/><joint name="z" type="slide"/>
  <joint name="h" type="hinge" axis="0 1 0"/><joint name="k" type="hinge"/><geom size=".1"/>
</body></worldbody>
<tendon><fixed name="slides"><joint joint="x" coef="2"/><joint joint="z" coef="-1"/></fixed>
  <fixed name="hinges"><joint joint="h" coef="1.5"/><joint joint="k" coef="1"/></fixed>
</tendon></mujoco>"""


def test_fixed_tendons_in_their_joints_units_are_shared_unchanged() -> None:
    """Uniform scaling: the tendon section is the original's, and MuJoCo agrees."""
    model = loads(_MODEL_TENDON_COEFFICIENTS)
    result = scaled(model, 2.0)
    assert result.tendon is model.tendon
    original = mujoco.MjModel.from_xml_string(_MODEL_TENDON_COEFFICIENTS)
    changed = mujoco.MjModel.from_xml_string(dumps(result))
    assert scaled_model_problems(original, changed, 2.0) == []


def test_a_coefficient_ruled_without_its_tendon_is_kept() -> None:
    """Without the tendon around it, the coefficient's unit is unknown: nothing changes."""
    model = loads(_MODEL_TENDON_COEFFICIENTS)
    context = ScaleContext(factors=(2.0, 3.0, 5.0), classes=DefaultClasses.of(model), model=model)
    for coefficient in model.tendon.elements[0].elements:
        assert RULES["tendon/fixed/joint"](coefficient, (), context) == {}


# -- Tendon lengths given by default classes are written, scaled, on the tendons they measure. -
#
# The default ``<tendon>`` is shared by spatial and fixed tendons, and a fixed
# tendon's length is a length only with a slide joint in it, so a class's
# ``range``, ``springlength`` and ``margin`` stay in the class; each tendon whose
# length is a length writes them scaled. MuJoCo compiles the scaled model to the
# original scaled: the fixed tendon over a slide and the spatial tendon measure
# twice their ranges, the fixed tendon over a hinge keeps its class's.


_MODEL_CLASS_LENGTHS = """<mujoco><default><tendon range="-.5 .5" limited="true" margin=".01"/>
  <default class="sprung"><tendon springlength=".2" stiffness="10"/></default></default>
<worldbody><body><joint name="s" type="slide" axis="1 0 0"/><joint name="h" type="hinge"/>
  <geom size=".1"/><site name="a"/><body pos="0 0 1"><joint type="slide"/><geom size=".1"/>
  <site name="b"/></body></body></worldbody>
<tendon><fixed name="slide" class="sprung"><joint joint="s" coef="1"/></fixed>
  <fixed name="hinge" class="sprung"><joint joint="h" coef="1"/></fixed>
  <spatial name="rope"><site site="a"/><site site="b"/></spatial></tendon></mujoco>"""


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_class_tendon_lengths_scale_on_the_tendons_measuring_lengths(factor: float) -> None:
    """The slide and spatial tendons' ranges, margins and spring lengths scale; the hinge's stay."""
    original = mujoco.MjModel.from_xml_string(_MODEL_CLASS_LENGTHS)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(_MODEL_CLASS_LENGTHS), factor)))
    assert scaled_model_problems(original, changed, factor) == []
    lengths = np.array([factor, 1.0, factor])  # slide, hinge, rope
    np.testing.assert_allclose(changed.tendon_range, original.tendon_range * lengths[:, None])
    np.testing.assert_allclose(changed.tendon_margin, original.tendon_margin * lengths)
    np.testing.assert_allclose(
        changed.tendon_lengthspring[:2], original.tendon_lengthspring[:2] * lengths[:2, None]
    )
