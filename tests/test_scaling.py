"""Scaling: every length multiplied, checked by MuJoCo on the corpus and on drawn models."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import Body, Geom, Mujoco, Site, compiled
from mjcf_model.bridge.compare import model_differences
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.strategies import models
from mjcf_model.transforms.scaling.pieces import NO_LENGTHS
from mjcf_model.transforms.scaling.rules import RULES, UNSCALED_BY_DECISION
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.traversal import map_tree
from serializers import dumps, load, loads, to_dict
from tests.conftest import compiling_corpus, corpus_id
from tests.support.oracles import trees_close
from tests.support.scaling_oracle import scaled_model_problems

CORPUS = compiling_corpus()

#: Attribute names that hold a length wherever they appear.
LENGTH_ATTRIBUTES = frozenset(
    {"pos", "size", "fromto", "anchor", "margin", "gap", "vertex", "offset", "bindpos", "radius"}
)


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_corpus_model_scaled_by_two_changes_every_field_as_classified(path: Path) -> None:
    """A corpus model scaled by 2 compiles with every field its classified multiple.

    Every body keeps its mass (``mass="keep"``, the default), density-derived ones
    too; lengths double and inertias grow by four.
    """
    model = load(path, inline_includes=True)
    changed = compiled(scaled(model, 2))
    original = mujoco.MjModel.from_xml_path(str(path))
    assert scaled_model_problems(original, changed, 2.0) == []


@given(models())
def test_drawn_model_scaled_by_two_changes_every_field_as_classified(model: Mujoco) -> None:
    """The same oracle on drawn models, whose input stays untouched."""
    snapshot = to_dict(model)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(model, 2)))
    original = mujoco.MjModel.from_xml_string(dumps(model))
    assert scaled_model_problems(original, changed, 2.0) == []
    assert to_dict(model) == snapshot


@given(models())
def test_scaling_by_one_and_identity_map_return_the_input(model: Mujoco) -> None:
    """``scaled(m, 1) is m`` and ``map_tree(identity, m) is m``."""
    assert scaled(model, 1) is model
    assert scaled(model, [1, 1, 1]) is model
    assert map_tree(lambda node: node, model) is model


_FACTORS = st.floats(0.25, 4.0, allow_nan=False)


@given(models(), _FACTORS, _FACTORS, st.sampled_from(["keep", "volume"]))
def test_scaling_composes(model: Mujoco, a: float, b: float, mass: str) -> None:
    """``scaled(scaled(m, a), b)`` equals ``scaled(m, a * b)`` within float tolerance.

    When ``a * b`` is exactly 1 the right side is ``m`` itself, while the left has
    MuJoCo's built-in lengths written out; that case compiles identically instead.
    """
    if a * b == 1.0:
        twice = scaled(scaled(model, a, mass=mass), b, mass=mass)
        compiled = mujoco.MjModel.from_xml_string(dumps(twice))
        original = mujoco.MjModel.from_xml_string(dumps(model))
        assert scaled_model_problems(original, compiled, 1.0) == []
        return
    twice = scaled(scaled(model, a, mass=mass), b, mass=mass)
    assert trees_close(twice, scaled(model, a * b, mass=mass))


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


def test_joint_type_from_a_default_class_decides_whether_range_scales() -> None:
    """A slide joint by class scales its range; a hinge sharing the class's range does not."""
    model = loads(
        """<mujoco><default><default class="rail"><joint type="slide" range="0 0.5"/></default>
        </default><worldbody><body childclass="rail"><geom size="0.1"/><joint name="s"/>
        <joint name="h" type="hinge"/></body></worldbody></mujoco>"""
    )
    original = mujoco.MjModel.from_xml_string(dumps(model))
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(model, 3)))
    assert np.allclose(changed.jnt_range[0], 3 * original.jnt_range[0])
    assert np.allclose(changed.jnt_range[1], original.jnt_range[1])


def test_mass_policies_as_compiled_by_mujoco() -> None:
    """``keep`` keeps explicit masses; ``volume`` scales them by s**3 and inertia by s**5."""
    model = loads(
        """<mujoco><worldbody><body><freejoint/><inertial pos="0 0 0" mass="2"
        diaginertia="0.1 0.2 0.3"/><geom size="0.1" mass="1"/></body></worldbody></mujoco>"""
    )
    original = mujoco.MjModel.from_xml_string(dumps(model))
    kept = mujoco.MjModel.from_xml_string(dumps(scaled(model, 2)))
    volume = mujoco.MjModel.from_xml_string(dumps(scaled(model, 2, mass="volume")))
    assert kept.body_mass[1] == original.body_mass[1]
    assert np.allclose(kept.body_inertia[1], 4 * original.body_inertia[1])
    assert np.isclose(volume.body_mass[1], 8 * original.body_mass[1])
    assert np.allclose(volume.body_inertia[1], 32 * original.body_inertia[1])


def test_per_axis_sizes_follow_robosuites_conventions() -> None:
    """Sizes as robosuite's contract measured for ``scale=[1, 2, 3]`` (e8)."""
    body = Body(
        children=[
            Geom(type="box", size=[0.1, 0.2, 0.3]),
            Geom(type="cylinder", size=[0.1, 0.2]),
            Geom(type="sphere", size=[0.05]),
            Site(size=[0.01, 0.02]),
        ]
    )
    new = scaled(body, [1, 2, 3])
    assert [g.size for g in new.geoms] == [
        (0.1, 0.4, 0.8999999999999999),
        (0.15000000000000002, 0.6000000000000001),
        (0.1,),
    ]
    assert new.sites[0].size[:2] == (0.015, 0.06)


def test_site_without_size_gets_mujocos_default_scaled() -> None:
    """An unsized site compiles to twice MuJoCo's default size."""
    model = loads('<mujoco><worldbody><site name="s"/></worldbody></mujoco>')
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(model, 2)))
    assert np.allclose(changed.site_size[0], [0.01, 0.01, 0.01])


_UNIFORM = """<mujoco><worldbody><body pos="0 0 {pos}">
<geom type="sphere" size="{radius}" friction="1 {torsion} {rolling}"/>
<camera name="c" ipd="{ipd}"/><site name="s" size="{site} {site} {site}"/>
</body></worldbody></mujoco>"""


@pytest.mark.parametrize("factor", [0.8, 0.7, 1.17, 0.1])
def test_a_uniform_factor_scales_lengths_without_a_direction_by_exactly_itself(
    factor: float,
) -> None:
    """A radius, an ipd, a torsional friction: times the factor, not times the mean of three.

    ``(0.8 + 0.8 + 0.8) / 3`` is ``0.8000000000000002``; MuJoCo compiles the products
    a user writes by hand.
    """
    values = {"pos": 1.0, "radius": 0.05, "torsion": 0.005, "rolling": 0.0001, "ipd": 0.068}
    values["site"] = 0.005
    model = loads(_UNIFORM.format(**values))
    by_hand = _UNIFORM.format(**{name: repr(value * factor) for name, value in values.items()})
    expected = mujoco.MjModel.from_xml_string(by_hand)
    assert model_differences(compiled(scaled(model, factor, mass="volume")), expected) == []


def test_keyframe_qpos_scales_only_its_lengths() -> None:
    """Slide and free-joint positions in a key scale; angles and quaternions do not."""
    model = loads(
        """<mujoco><worldbody><body><freejoint/><geom size="0.1"/><body pos="0 0 1">
        <joint type="slide" axis="1 0 0"/><joint type="hinge"/><geom size="0.1"/></body></body>
        </worldbody><keyframe><key qpos="1 2 3 1 0 0 0 0.5 0.7"/></keyframe></mujoco>"""
    )
    key = scaled(model, 2).keyframe.keys[0]
    assert key.qpos == (2.0, 4.0, 6.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.7)


@pytest.mark.parametrize("factor", [0, -1, [1, 2], float("nan")])
def test_bad_factors_are_refused(factor: object) -> None:
    """A factor that is not one or three positive numbers is an error."""
    with pytest.raises(MjcfValueError, match=r"scale factor|positive"):
        scaled(Body(pos=[0, 0, 1]), factor)


def test_attach_cannot_be_scaled() -> None:
    """The attached model lives in another file, so scaling says so instead of guessing."""
    model = loads(
        '<mujoco><asset><model name="m" file="m.xml"/></asset><worldbody><body>'
        '<attach model="m" body="b" prefix="x"/></body></worldbody></mujoco>'
    )
    with pytest.raises(MjcfValueError) as refused:
        scaled(model, 2)
    assert str(refused.value) == (
        "cannot scale an <attach>: the attached model is a separate file; "
        "scale that model and attach the result"
    )


def test_an_unknown_mass_policy_is_refused_naming_the_two_policies() -> None:
    """A typo in ``mass`` is an error that lists what it can be, before anything is scaled."""
    with pytest.raises(MjcfValueError) as refused:
        scaled(Body(pos=[0, 0, 1]), 2, mass="density")  # type: ignore[arg-type]
    assert str(refused.value) == "mass policy is 'keep' or 'volume', found 'density'"


def test_a_kept_include_is_refused_saying_to_inline_includes(tmp_path: Path) -> None:
    """An ``<include>``'s file is not in the tree: scaling says to load with includes inlined."""
    (tmp_path / "part.xml").write_text('<mujoco><body name="b"><geom size="0.1"/></body></mujoco>')
    path = tmp_path / "model.xml"
    path.write_text('<mujoco><worldbody><include file="part.xml"/></worldbody></mujoco>')
    assert mujoco.MjModel.from_xml_path(str(path)).body("b").id == 1
    with pytest.raises(MjcfValueError) as refused:
        scaled(load(path), 2)
    assert str(refused.value) == (
        "cannot scale a model with <include> elements: their files are not part of the tree; "
        "load it with inline_includes=True"
    )
    inlined = compiled(scaled(load(path, inline_includes=True), 2))
    assert inlined.geom_size[0][0] == pytest.approx(0.2)


def test_tendon_lengths_from_default_classes_scale_on_spatial_tendons_only() -> None:
    """A spatial tendon's range from a class doubles; a fixed tendon of hinges keeps it."""
    model = loads(
        """<mujoco><default><tendon range="0 1" width="0.01"/></default><worldbody>
        <body><joint name="h" type="hinge"/><geom size="0.1"/><site name="a"/>
        <body pos="0 0 1"><joint type="hinge"/><geom size="0.1"/><site name="b"/></body></body>
        </worldbody><tendon><spatial limited="true"><site site="a"/><site site="b"/></spatial>
        <fixed limited="true"><joint joint="h" coef="1"/></fixed></tendon></mujoco>"""
    )
    original = mujoco.MjModel.from_xml_string(dumps(model))
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(model, 2)))
    assert np.allclose(changed.tendon_range[0], 2 * original.tendon_range[0])
    assert np.allclose(changed.tendon_width[0], 2 * original.tendon_width[0])
    assert np.allclose(changed.tendon_range[1], original.tendon_range[1])


def test_slide_joint_targets_scale_where_joints_slide() -> None:
    """Position targets and fixed tendon ranges on slide joints double; on hinges they stay."""
    model = loads(
        """<mujoco><worldbody><body><joint name="s" type="slide" axis="1 0 0"/>
        <joint name="h" type="hinge"/><geom size="0.1"/></body></worldbody>
        <tendon><fixed name="ts" range="0 0.2" limited="true"><joint joint="s" coef="1"/></fixed>
        <fixed name="th" range="0 1" limited="true"><joint joint="h" coef="1"/></fixed></tendon>
        <actuator><position joint="s" ctrlrange="0 0.04"/><position joint="h" ctrlrange="0 1"/>
        </actuator></mujoco>"""
    )
    original = mujoco.MjModel.from_xml_string(dumps(model))
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(model, 2)))
    assert np.allclose(changed.actuator_ctrlrange[0], 2 * original.actuator_ctrlrange[0])
    assert np.allclose(changed.actuator_ctrlrange[1], original.actuator_ctrlrange[1])
    assert np.allclose(changed.tendon_range[0], 2 * original.tendon_range[0])
    assert np.allclose(changed.tendon_range[1], original.tendon_range[1])
