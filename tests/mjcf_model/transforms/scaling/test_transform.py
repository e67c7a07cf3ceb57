"""Tests of ``mjcf_model.transforms.scaling.transform``."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import mujoco
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import Body, Geom, Joint, Mujoco, Site, compiled
from mjcf_model.bridge.compare import model_differences
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.nodes.base import AnyElement, GenericElement, TypedElement, attribute_items
from mjcf_model.serializers import dumps, from_etree, load, loads, to_dict
from mjcf_model.strategies import elements, models
from mjcf_model.tools.check import check_file
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.traversal import keyed_walk, map_elements, map_tree
from mjcf_model.values import format_value
from tests.conftest import PER_CLASS, compiling_corpus, corpus_id
from tests.support.node_classes import TYPED_CLASSES
from tests.support.oracles import trees_close
from tests.support.scaling_oracle import (
    ALIGNED_SLIDES,
    IGNORED,
    SCALING_FIXTURES,
    _scaled_copy,
    scaled_model_problems,
)
from tests.support.skin_files import skin_file

# -- Scaling: every length multiplied, checked by MuJoCo on the corpus and on drawn models. ----


CORPUS = compiling_corpus()


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


# -- Scaling on constructs real models use: masses, shells, flexcomps, SDFs, includes, skin
#    files.
#
# The fixtures live in ``tests/fixtures/scaling``; MuJoCo compiles each original and
# each scaled copy, and the oracle compares the compiled arrays.


#: The fixtures the scale oracle runs on (``attach.xml`` and ``sdf_fixed_shape.xml`` are
#: refused; ``sdf_gear.xml`` has its own oracle, in ``test_plugins.py``).
SCALABLE = ("mass.xml", "flexcomp.xml", "sdf.xml", "includes.xml", "keys.xml")

#: Every top-level fixture of the folder.
ALL_FIXTURES = (*SCALABLE, "attach.xml", "sdf_fixed_shape.xml", "sdf_gear.xml")


def _problems(name: str, factor: float) -> list[str]:
    """What keeps the fixture scaled by ``factor`` from being exactly scaled, masses kept."""
    path = SCALING_FIXTURES / name
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = _scaled_copy(path, factor)
    return scaled_model_problems(original, changed, factor, ignore=IGNORED.get(name, ()))


@pytest.mark.parametrize("name", ALL_FIXTURES)
@pytest.mark.parametrize("inline_includes", [False, True], ids=["kept", "inlined"])
def test_fixture_round_trips_to_the_identical_model(name: str, inline_includes: bool) -> None:
    """Each fixture of the folder survives the round trip that ``test_fixtures`` applies."""
    result = check_file(SCALING_FIXTURES / name, inline_includes=inline_includes)
    assert (result.status, result.differences, result.message) == ("identical", (), "")


@pytest.mark.parametrize("name", SCALABLE)
def test_fixture_scaled_by_two_doubles_every_length_and_keeps_masses(name: str) -> None:
    """Every field changes as classified: lengths double, masses stay, inertias grow by four."""
    assert _problems(name, 2.0) == []


@pytest.mark.parametrize("name", SCALABLE)
def test_fixture_scaled_by_a_half_halves_every_length(name: str) -> None:
    """The same oracle for a factor below one."""
    assert _problems(name, 0.5) == []


def test_attach_fixture_compiles_but_scaling_refuses_it() -> None:
    """MuJoCo compiles ``<attach>`` from a subfolder; ``scaled`` still refuses it by name."""
    path = SCALING_FIXTURES / "attach.xml"
    assert mujoco.MjModel.from_xml_path(str(path)).body("arm_lower").id > 0
    with pytest.raises(MjcfValueError, match=r"^cannot scale an <attach>: the attached model"):
        scaled(load(path), 2)


@pytest.mark.parametrize("tag", ["geom", "site"])
def test_a_size_of_more_than_three_numbers_is_refused_as_mujoco_refuses_it(tag: str) -> None:
    """Four size values are not MJCF (MuJoCo: "too much data"): scaling says so, writes nothing."""
    text = f'<mujoco><worldbody><body><{tag} size="1 2 3 4"/></body></worldbody></mujoco>'
    with pytest.raises(ValueError, match="too much data"):
        mujoco.MjModel.from_xml_string(text)
    generic = from_etree(ET.fromstring(text), typed=False)
    with pytest.raises(MjcfValueError, match="at most 3"):
        scaled(generic, 2)


#: A model whose skin MuJoCo reads from ``sheet.skn``, bound to its three bodies.
_SKINNED = """<mujoco><asset><skin name="sheet" file="sheet.skn" inflate="0.01"/></asset>
<worldbody><body name="a"><geom size="0.05"/></body><body name="b" pos="0.1 0 0">
<geom size="0.05"/></body><body name="c" pos="0 0.1 0"><geom size="0.05"/></body></worldbody>
</mujoco>"""


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_skin_read_from_a_file_scales_its_vertices_and_bind_poses(
    tmp_path: Path, factor: float
) -> None:
    """A loaded model's ``.skn`` skin is written inline and compiles with its lengths scaled."""
    skin_file(tmp_path / "sheet.skn", ("a", "b", "c"))
    path = tmp_path / "model.xml"
    path.write_text(_SKINNED)
    original = mujoco.MjModel.from_xml_path(str(path))
    assert np.any(original.skin_vert != 0) and np.any(original.skin_bonebindpos != 0)
    changed = compiled(scaled(load(path), factor))
    assert scaled_model_problems(original, changed, factor) == []


def test_skin_read_from_a_file_without_the_folder_is_refused() -> None:
    """Without its folder the skin's file cannot be read: scaling says to write it inline."""
    with pytest.raises(MjcfValueError) as refused:
        scaled(loads(_SKINNED), 2)
    assert str(refused.value) == (
        "cannot scale a model where skin 'sheet' is read from 'sheet.skn': the file holds its "
        "vertices and bind poses; write the skin inline first with "
        "mjcf_model.serializers.skins.inline_skin_files(model, model_folder)"
    )


@pytest.mark.parametrize("cls", TYPED_CLASSES, ids=lambda c: c.__name__)
def test_a_lone_element_of_any_class_scales_or_is_refused_clearly(cls: type[TypedElement]) -> None:
    """``scaled`` takes any node: outside a model it has no ancestors and no model to read.

    The result is a node of the same class, or an ``MjcfError`` that says why.
    """

    @PER_CLASS
    @given(elements(cls))
    def check(node: TypedElement) -> None:
        try:
            result = scaled(node, 3.0)
        except MjcfError:
            return
        assert type(result) is cls

    check()


def test_per_axis_factors_scale_axis_aligned_slides_exactly() -> None:
    """Per-axis factors: each slide scales by the factor along its axis.

    Its range and its key value scale so, and the key's pose (MuJoCo's kinematics) is
    the original's pose scaled axis by axis.
    """
    factors = np.array([2.0, 3.0, 5.0])
    original = mujoco.MjModel.from_xml_string(ALIGNED_SLIDES)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(ALIGNED_SLIDES), factors)))
    along = np.abs(original.jnt_axis) @ factors
    assert along.tolist() == [2.0, 5.0, 3.0]
    np.testing.assert_allclose(changed.jnt_range, original.jnt_range * along[:, None], rtol=1e-12)
    np.testing.assert_allclose(changed.key_qpos, original.key_qpos * along, rtol=1e-12)
    poses = []
    for model in (original, changed):
        data = mujoco.MjData(model)
        mujoco.mj_resetDataKeyframe(model, data, 0)
        mujoco.mj_kinematics(model, data)
        poses.append(data.xpos.copy())
    np.testing.assert_allclose(poses[1], poses[0] * factors, rtol=1e-12, atol=1e-15)


# -- What scaling leaves unchanged is the input's own node (shared, not copied). ---------------


def test_a_hinge_at_the_origin_is_shared() -> None:
    """A hinge's zero position scales to itself: the joint node is the input's."""
    joint = Joint(name="j", type="hinge", pos=[0.0, 0.0, 0.0], range=[-1.0, 1.0])
    body = Body(name="b", pos=[0.0, 0.0, 1.0], children=[joint])
    new = scaled(body, 2.0)
    assert new.pos == (0.0, 0.0, 2.0)
    assert new.children[0] is joint


# -- Geom sizes held as text are read and scaled as typed ones. --------------------------------
#
# A geom held as a generic element keeps its attributes as text; its size of one,
# two or three values (completed or overridden by its class) scales as a typed
# geom's does, and MuJoCo compiles the result to the original scaled.


#: Geoms of each size length, with classes completing and overriding sizes.
_GEOMS = """<mujoco><default><default class="thin"><geom size=".02 .3"/></default></default>
<worldbody><body><freejoint/><geom size=".1"/><geom type="capsule" size=".05 .2"/>
  <geom type="box" size=".1 .2 .3"/><geom class="thin" type="cylinder"/>
  <geom class="thin" type="capsule" size=".03"/></body></worldbody></mujoco>"""


def _generic_geoms(element: AnyElement, key: str | None, ancestors: object) -> AnyElement:
    """A body's geom as a generic element: its attributes as text."""
    if key != "body/geom":
        return element
    attributes = {name: format_value(value) for name, value in attribute_items(element)}
    return GenericElement(tag="geom", attributes=attributes)


def test_geoms_held_as_generic_elements_scale_as_typed_ones() -> None:
    """Text sizes of one, two and three values scale as typed ones; MuJoCo agrees."""
    model = map_elements(_generic_geoms, loads(_GEOMS))
    kinds = {type(e) for e, key, _ in keyed_walk(model) if key == "body/geom"}
    assert kinds == {GenericElement}
    original = mujoco.MjModel.from_xml_string(_GEOMS)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(model, 2.0)))
    typed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(_GEOMS), 2.0)))
    assert scaled_model_problems(original, changed, 2.0) == []
    assert np.array_equal(changed.geom_size, typed.geom_size)


# -- A slide range a class gives is scaled along the class's axis, and rewritten where that is
#    wrong.
#
# Per-axis factors scale a slide's coordinate by the factor along its axis (see
# ``test_per_axis_factors_scale_axis_aligned_slides_exactly``). A class giving
# slides an axis and a range has that range scaled along its axis; a joint of the
# class keeps inheriting it when its own axis and type agree, and writes its own
# scaled value when they do not (another axis, or a hinge, whose range is an
# angle). MuJoCo compiles every joint's range to the original's times the factor
# along its axis.


_MODEL = """<mujoco><default><default class="rail">
  <joint type="slide" axis="1 0 0" range="-.1 .2" margin=".01"/></default></default>
<worldbody><body childclass="rail"><joint name="x"/><joint name="z" axis="0 0 1"/>
  <joint name="y" axis="0 1 0"/><joint name="h" type="hinge"/><geom size=".05"/>
</body></worldbody></mujoco>"""


def test_class_slide_ranges_scale_along_each_joints_axis() -> None:
    """Factors 2, 3, 5: x's range doubles (inherited), z's and y's are rewritten, h's stays."""
    factors = np.array([2.0, 3.0, 5.0])
    model = scaled(loads(_MODEL), factors)
    original = mujoco.MjModel.from_xml_string(_MODEL)
    changed = mujoco.MjModel.from_xml_string(dumps(model))
    slide = original.jnt_type == mujoco.mjtJoint.mjJNT_SLIDE
    along = np.where(slide, np.abs(original.jnt_axis) @ factors, 1.0)  # a hinge's is an angle
    assert along.tolist() == [2.0, 5.0, 3.0, 1.0]
    np.testing.assert_allclose(changed.jnt_range, original.jnt_range * along[:, None], rtol=1e-12)
    np.testing.assert_allclose(changed.jnt_margin, original.jnt_margin * along, rtol=1e-12)
    joints = {e.name: e for e, key, _ in keyed_walk(model) if key == "body/joint"}
    assert (joints["x"].range, joints["x"].margin) == (None, None)  # inherits the class's
    assert joints["z"].range is not None


_EDGE = """<mujoco><worldbody><body><joint/>
<inertial pos="0 0 0" mass="1" diaginertia="0.1 0.2 0.3"/></body></worldbody></mujoco>"""


@pytest.mark.parametrize("mass", ["keep", "volume"])
@pytest.mark.parametrize("factor", [1.2, 0.7, 1.1, 3.0])
def test_moments_on_the_triangle_edge_still_compile(factor: float, mass: str) -> None:
    """Moments MuJoCo accepts (``0.1 + 0.2 >= 0.3``) are accepted scaled, as scaled as floats allow.

    Times 1.44 they would round to ``0.144 + 0.288 < 0.432``, which MuJoCo rejects.
    """
    model = loads(_EDGE)
    moments = compiled(scaled(model, factor, mass=mass)).body_inertia[1]  # MuJoCo accepts it
    inertia = factor**2 * (factor**3 if mass == "volume" else 1.0)
    expected = mujoco.MjModel.from_xml_string(_EDGE).body_inertia[1] * inertia
    np.testing.assert_allclose(np.sort(moments), np.sort(expected), rtol=1e-15)
