"""Scaling on constructs real models use: masses, shells, flexcomps, SDFs, includes, skin files.

The fixtures live in ``tests/fixtures/scaling``; MuJoCo compiles each original and
each scaled copy, and the oracle compares the compiled arrays.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import mujoco
import numpy as np
import pytest
from hypothesis import given

from mjcf_model import compiled
from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.nodes.base import TypedElement
from mjcf_model.strategies import elements
from mjcf_model.tools.check import check_file
from mjcf_model.transforms.scaling.plugins import SDF_LENGTHS
from mjcf_model.transforms.scaling.transform import scaled
from serializers import dumps, from_etree, load, loads
from tests.conftest import PER_CLASS
from tests.support.node_classes import TYPED_CLASSES
from tests.support.oracles import friction_problems, scaled_problems
from tests.support.scaling_oracle import (
    ALIGNED_SLIDES,
    IGNORED,
    SCALING_FIXTURES,
    _scaled_copy,
    scaled_model_problems,
)
from tests.support.skin_files import skin_file

#: The fixtures the scale oracle runs on (``attach.xml`` and ``sdf_fixed_shape.xml`` are
#: refused; ``sdf_gear.xml`` has its own oracle, below).
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


def test_keep_policy_keeps_the_centre_of_mass_of_mixed_bodies() -> None:
    """A body mixing written masses and densities keeps its mass; its centre of mass doubles."""
    path = SCALING_FIXTURES / "mass.xml"
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = _scaled_copy(path, 2.0)
    for name in ("mixed", "mixed_shells"):
        before, after = original.body(name), changed.body(name)
        assert np.isclose(after.mass[0], before.mass[0], rtol=1e-12, atol=0)
        assert np.allclose(after.ipos, 2 * before.ipos, rtol=1e-9, atol=0)


def test_volume_policy_scales_shells_with_area_and_solids_with_volume() -> None:
    """Density masses grow by s**2 on shells and s**3 on solids; written masses by s**3."""
    path = SCALING_FIXTURES / "mass.xml"
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = _scaled_copy(path, 2.0, mass="volume")
    expected = {"shells_only": 4.0, "solids_only": 8.0, "weighed_only": 8.0, "with_inertial": 8.0}
    for name, factor in expected.items():
        before, after = original.body(name), changed.body(name)
        assert np.isclose(after.mass[0], factor * before.mass[0], rtol=1e-9, atol=0), name
        trace = np.sum(after.inertia), 4 * factor * np.sum(before.inertia)
        assert np.isclose(*trace, rtol=1e-9, atol=0), name


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


def _disc(scale: float, margin: float | None) -> str:
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
    mujoco.MjModel.from_xml_string(_disc(1, margin))
    try:
        mujoco.MjModel.from_xml_string(_disc(factor, margin))
        rejected = False
    except ValueError as error:
        assert "Spacing must be larger" in str(error)
        rejected = True
    if rejected:
        with pytest.raises(MjcfValueError) as refused:
            scaled(loads(_disc(1, margin)), factor)
        assert str(refused.value) == (
            f"cannot scale the disc flexcomp 'd' by {(float(factor),) * 3}: its spacing grows "
            "with the square root of the factor but must exceed twice its radius plus its "
            "margin, which grow with the factor; use a smaller factor or a larger spacing"
        )
    else:
        mujoco.MjModel.from_xml_string(dumps(scaled(loads(_disc(1, margin)), factor)))


def test_sdf_settings_are_scaled_instead_of_the_mesh_scale() -> None:
    """No ``scale`` on SDF meshes; the torus's unwritten ``radius2`` is written, scaled."""
    model = scaled(load(SCALING_FIXTURES / "sdf.xml"), 2)
    text = dumps(model)
    assert 'key="radius1" value="0.4"' in text
    assert 'key="radius2" value="0.3"' in text
    mujoco.MjModel.from_xml_string(text)  # MuJoCo refuses a scale on an SDF mesh


@pytest.mark.parametrize("plugin", ["nut", "bolt"])
def test_sdf_plugin_with_fixed_dimensions_is_refused(plugin: str) -> None:
    """MuJoCo's nut and bolt SDFs compile but have no length settings: scaling names them."""
    text = (
        (SCALING_FIXTURES / "sdf_fixed_shape.xml").read_text().replace("sdf.nut", f"sdf.{plugin}")
    )
    assert mujoco.MjModel.from_xml_string(text).nmesh == 1
    with pytest.raises(MjcfValueError) as refused:
        scaled(loads(text), 2)
    assert str(refused.value) == _refusal(
        "mesh", f"mujoco.sdf.{plugin}", "its dimensions are fixed in the plugin's code"
    )


def _refusal(owner: str, plugin: str, why: str) -> str:
    """What scaling says of a shape plugin it cannot scale: why, and what to do."""
    return (
        f"cannot scale the {owner} made by plugin {plugin!r}: {why}; only "
        f"{', '.join(SDF_LENGTHS)} scale. Replace that shape (or scale its settings "
        "yourself and take it out of the model) before scaling"
    )


#: The gear SDF's settings in the order MuJoCo keeps them, with its defaults
#: (``innerdiameter`` below zero: derived from the diameter), and whether each is a length.
_GEAR_SETTINGS = (
    ("alpha", 0.0, False),
    ("diameter", 2.8, True),
    ("teeth", 25.0, False),
    ("thickness", 0.2, True),
    ("innerdiameter", -1.0, True),
)


def _gear_settings(model: mujoco.MjModel) -> np.ndarray:
    """Each gear instance's settings as the plugin reads them, defaults filled in."""
    values = []
    for start in model.plugin_attradr:
        fields = model.plugin_attr[start:].tobytes().decode().split("\0")[: len(_GEAR_SETTINGS)]
        values.append(
            [float(f) if f else d for f, (_, d, _) in zip(fields, _GEAR_SETTINGS, strict=True)]
        )
    return np.array(values)


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_gear_sdf_scales_through_its_length_settings(factor: float) -> None:
    """The gear's diameter, thickness and bore scale, and with them the shape MuJoCo builds.

    Its bounding boxes (the plugin's, and the mesh MuJoCo makes of it) and bounding
    spheres scale exactly. The mesh itself is rebuilt: MuJoCo meshes the gear with a
    numerical gradient, so vertex counts and volumes differ slightly (measured on
    MuJoCo 4.0.0 and 3.9.0: volume within 0.4% of ``factor**3``).
    """
    path = SCALING_FIXTURES / "sdf_gear.xml"
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = _scaled_copy(path, factor)
    lengths = np.array([length for _, _, length in _GEAR_SETTINGS])
    before, after = _gear_settings(original), _gear_settings(changed)
    factors = np.where(lengths & (before >= 0), factor, 1.0)  # a negative bore stays derived
    assert np.allclose(after, factors * before, rtol=1e-12, atol=0)
    assert scaled_problems(original, changed, factor, ["geom_aabb", "geom_rbound"]) == []
    assert np.allclose(_mesh_boxes(changed), factor * _mesh_boxes(original), rtol=1e-6, atol=0)
    assert np.allclose(changed.body_mass, original.body_mass, rtol=5e-3, atol=0)
    assert friction_problems(original, changed, factor) == []


def _mesh_boxes(model: mujoco.MjModel) -> np.ndarray:
    """Each mesh's lowest and highest vertex coordinates."""
    boxes = []
    for start, count in zip(model.mesh_vertadr, model.mesh_vertnum, strict=True):
        vertices = model.mesh_vert[start : start + count]
        boxes.append(np.concatenate([vertices.min(axis=0), vertices.max(axis=0)]))
    return np.array(boxes)


@pytest.mark.parametrize("owner", ["mesh", "geom"])
def test_unknown_shape_plugin_is_refused(owner: str) -> None:
    """A mesh or geom made by a plugin mjcf-model does not know raises an error naming it."""
    use = '<plugin plugin="acme.sdf.blob"><config key="size" value="1"/></plugin>'
    mesh = f'<mesh name="m">{use if owner == "mesh" else ""}</mesh>'
    geom = f'<geom type="sdf" mesh="m">{use if owner == "geom" else ""}</geom>'
    model = loads(
        f"<mujoco><asset>{mesh}</asset><worldbody><body>{geom}</body></worldbody></mujoco>"
    )
    with pytest.raises(MjcfValueError) as refused:
        scaled(model, 2)
    why = "mjcf-model does not know which of its settings are lengths"
    assert str(refused.value) == _refusal(owner, "acme.sdf.blob", why)


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
        "serializers.skins.inline_skin_files(model, model_folder)"
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
