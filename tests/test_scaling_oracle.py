"""The complete scaling oracle: every float field classified, and the bugs it catches.

MuJoCo compiles each model before and after scaling; :func:`scaled_model_problems`
states the expected change of every field (:mod:`tests.support.compiled_fields`).
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from tests.support.compiled_fields import FLOAT_FIELDS, float_fields
from tests.support.scaling_oracle import compiled_pair, scaled_model_problems


def test_every_float_field_of_the_installed_mujoco_is_classified() -> None:
    """A float array MuJoCo adds must be given a kind before scaling can be trusted with it."""
    model = mujoco.MjModel.from_xml_string("<mujoco/>")
    assert [f for f in float_fields(model) if f not in FLOAT_FIELDS] == []
    assert len(float_fields(model)) > 150


def test_an_unclassified_field_is_reported_not_skipped() -> None:
    """The oracle names a float field it has no kind for instead of passing over it."""

    class Extended:
        def __init__(self, model: mujoco.MjModel) -> None:
            self._model = model
            self.geom_novelty = np.ones(3)

        def __dir__(self) -> list[str]:
            return [*dir(self._model), "geom_novelty"]

        def __getattr__(self, name: str) -> object:
            return getattr(self._model, name)

    model = mujoco.MjModel.from_xml_string("<mujoco/>")
    assert "geom_novelty: not classified" in scaled_model_problems(
        Extended(model), Extended(model), 2.0
    )


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


def test_welds_between_sites_and_spatial_tendons_are_read_as_mujoco_does() -> None:
    """A weld between sites keeps its unread data; a spatial tendon over sites is a length.

    Both were found by the drawn models: the oracle expected a site weld's default
    ``relpose`` to scale, and took a spatial tendon's sites for joints.
    """
    text = """<mujoco><worldbody>
      <body name="a"><joint type="slide"/><geom size=".1"/><site name="s0"/></body>
      <body name="b" pos="0 0 1"><geom size=".1"/><site name="s1"/></body>
    </worldbody>
    <tendon><spatial name="t" springlength=".5"><site site="s0"/><site site="s1"/></spatial>
    </tendon>
    <equality><weld site1="s0" site2="s1"/></equality></mujoco>"""
    original, changed = compiled_pair(text, 2.0)
    assert np.array_equal(changed.eq_data, original.eq_data)
    assert changed.tendon_lengthspring[0, 0] == 2 * original.tendon_lengthspring[0, 0]
    assert scaled_model_problems(original, changed, 2.0) == []


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


def _offset_frames(offset: float) -> str:
    """A body whose geom and site lie ``offset`` metres from its frame along x."""
    return f"""<mujoco><worldbody><body>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
      <geom size="0.1" pos="{offset} 0 0"/><site pos="{offset} 0 0"/>
    </body></worldbody></mujoco>"""


def test_a_frame_offset_crossing_mujocos_tolerance_when_scaled_is_no_change() -> None:
    """0.7 micrometres is "at the body's frame" to MuJoCo, 1.4 is not: that flip is expected."""
    original, changed = compiled_pair(_offset_frames(7e-7), 2.0)
    assert original.geom_sameframe.tolist() == original.site_sameframe.tolist() == [1]
    assert changed.geom_sameframe.tolist() == changed.site_sameframe.tolist() == [3]
    assert scaled_model_problems(original, changed, 2.0) == []


@pytest.mark.parametrize("offset", [3e-7, 0.01])
def test_a_frame_flag_flip_the_offset_cannot_explain_is_reported(offset: float) -> None:
    """A flag that changes where scaling keeps the offset on one side of the tolerance."""
    original, changed = compiled_pair(_offset_frames(offset), 2.0)
    assert scaled_model_problems(original, changed, 2.0) == []
    changed.site_sameframe[0] = 3 if original.site_sameframe[0] == 1 else 1
    assert scaled_model_problems(original, changed, 2.0) == [
        f"site_sameframe[0]: {original.site_sameframe[0]} became {changed.site_sameframe[0]}"
    ]


@pytest.mark.parametrize("wrap", [False, True], ids=["body", "frame"])
def test_a_bodys_joints_come_before_a_child_body_written_above_them(wrap: bool) -> None:
    """MuJoCo numbers a body's own joints before those of a body inside it, wherever written.

    A child body (bare or in a frame) written before its parent's joints: the key's
    slide entry still scales (a drawn model found it unscaled).
    """
    child = '<body name="c"><joint name="c_hinge"/><joint name="c_slide" type="slide"/>'
    child += '<geom size="0.1"/></body>'
    child = f"<frame>{child}</frame>" if wrap else child
    text = f"""<mujoco><worldbody><body name="p">{child}<joint name="p_slide" type="slide"/>
    <joint name="p_hinge"/><geom size="0.1"/></body></worldbody>
    <keyframe><key qpos="0.1 0.2 0.3 0.4" qvel="1 2 3 4"/></keyframe></mujoco>"""
    original, changed = compiled_pair(text, 2.0)
    names = [original.joint(i).name for i in range(original.njnt)]
    assert names == ["p_slide", "p_hinge", "c_hinge", "c_slide"]
    assert scaled_model_problems(original, changed, 2.0) == []
    assert changed.key_qvel[0].tolist() == [2.0, 2.0, 3.0, 8.0]
