"""Tests of ``mjcf_model.transforms.composition.inertia``."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model import Mujoco, attach, compiled
from mjcf_model.errors import MjcfValueError
from mjcf_model.serializers import loads

# -- A child attached under other inertia settings keeps every body's mass and inertia. --------
#
# MuJoCo is the referee: the child compiled alone (under the parent's model-wide
# settings, as :func:`mjcf_model.attach` promises) gives each body's mass, centre
# and inertia, and the scene must hold the same; where the parent's settings would
# change them even with an explicit ``<inertial>``, the attach is refused, naming
# the body and the settings.


#: What MuJoCo computes of a body's mass distribution, compared body by body.
FIELDS = ("body_mass", "body_inertia", "body_ipos", "body_iquat", "body_pos")


def _scene(child: str, parent: str = "<mujoco/>") -> mujoco.MjModel:
    """The child attached into ``parent`` with the prefix ``c_``, compiled."""
    return compiled(attach(loads(parent), loads(child), prefix="c_"))


def _assert_same_bodies(alone: mujoco.MjModel, scene: mujoco.MjModel) -> None:
    """Every body of the child alone has its mass distribution and place in the scene."""
    assert scene.nbody == alone.nbody
    for field in FIELDS:
        assert np.allclose(getattr(scene, field), getattr(alone, field), rtol=1e-12, atol=1e-15)
    alone_data, scene_data = mujoco.MjData(alone), mujoco.MjData(scene)
    mujoco.mj_kinematics(alone, alone_data)
    mujoco.mj_kinematics(scene, scene_data)
    assert np.allclose(scene_data.xipos, alone_data.xipos, rtol=1e-12, atol=1e-15)


def _body(name: str) -> str:
    """A moving body whose tiny geom weighs less than the child's ``boundmass``."""
    named = f' name="{name}"' if name else ""
    return f'<body{named} pos="0 0 1"><joint/><geom size="0.01" mass="0.001"/></body>'


def test_unnamed_bodies_next_to_bodies_named_like_the_made_up_names() -> None:
    """Unnamed bodies keep their bounded mass though other bodies use the names made for them."""
    child = (
        '<mujoco><compiler boundmass="0.5"/><worldbody>'
        f"{_body('')}{_body('')}"
        f"{_body('mjcf_model_conventions_0')}{_body('mjcf_model_conventions_1')}"
        "</worldbody></mujoco>"
    )
    alone = mujoco.MjModel.from_xml_string(child)
    assert list(alone.body_mass[1:]) == [0.5] * 4  # boundmass lifts every body
    _assert_same_bodies(alone, _scene(child))


def test_bodies_in_nested_and_single_copy_replicates() -> None:
    """Bodies in replicates inside replicates, and in a one-copy replicate, keep their mass."""
    child = (
        '<mujoco><compiler boundmass="0.5"/><worldbody>'
        '<replicate count="2" offset="1 0 0"><replicate count="3" offset="0 1 0">'
        f"{_body('leaf')}</replicate></replicate>"
        f'<replicate count="1" offset="0 0 1">{_body("single")}</replicate>'
        "</worldbody></mujoco>"
    )
    alone = mujoco.MjModel.from_xml_string(child)
    assert list(alone.body_mass[1:]) == [0.5] * 7
    _assert_same_bodies(alone, _scene(child))


def test_a_free_body_aligned_to_its_inertia_keeps_its_centre() -> None:
    """A free joint with align="true" moves the body to its centre of mass, as alone."""
    child = (
        '<mujoco><compiler boundmass="0.5"/><worldbody><body name="free" pos="0 0 1">'
        '<freejoint align="true"/><geom size="0.1" pos="0.2 0.1 0" quat="0.9 0.3 0 0"/>'
        '<geom type="box" size="0.1 0.05 0.02" pos="-0.1 0 0.1"/></body></worldbody></mujoco>'
    )
    alone = mujoco.MjModel.from_xml_string(child)
    assert alone.body_pos[1][0] != 0  # the aligned body frame moved to the centre of mass
    _assert_same_bodies(alone, _scene(child))


def test_a_static_body_keeps_its_mass_though_the_child_asks_to_fuse_it() -> None:
    """The parent's fusestatic holds: a static body of the child keeps its own mass."""
    body = (
        '<body name="base"><geom size="0.1" group="0"/>'
        '<geom size="0.1" pos="0.3 0 0" group="3"/></body>'
        '<body name="arm" pos="0 0 1"><joint/><geom size="0.05"/></body>'
    )
    child = f'<mujoco><compiler fusestatic="true" inertiagrouprange="0 2"/><worldbody>{body}'
    alone = mujoco.MjModel.from_xml_string(
        child.replace('fusestatic="true"', 'fusestatic="false"') + "</worldbody></mujoco>"
    )
    _assert_same_bodies(alone, _scene(child + "</worldbody></mujoco>"))


LIGHT = (
    '<inertial pos="0 0 0" mass="0.001" diaginertia="0.001 0.001 0.001"/></body>'
    "</worldbody></mujoco>"
)


def test_a_named_body_the_parent_would_make_heavier_is_refused_naming_it() -> None:
    """Refused naming the body, each differing setting with the child's value, and the fix."""
    child = f'<mujoco><worldbody><body name="light"><joint/>{LIGHT}'
    parent = '<mujoco><compiler boundmass="0.5" boundinertia="0.0001"/></mujoco>'
    with pytest.raises(
        MjcfValueError,
        match=r"^body 'light' would get another mass or inertia under the parent's "
        r"boundinertia='0.0001' \(child: '0'\), boundmass='0.5' \(child: '0'\), even with "
        r"an explicit <inertial>; give the two models the same inertia settings$",
    ):
        attach(loads(parent), loads(child), prefix="c_")


def test_an_unnamed_body_the_parent_would_make_heavier_is_refused() -> None:
    """Refused calling it an unnamed body, not by the name made up for it."""
    child = f"<mujoco><worldbody><body><joint/>{LIGHT}"
    parent = '<mujoco><compiler boundmass="0.5"/></mujoco>'
    with pytest.raises(
        MjcfValueError, match=r"^an unnamed body would get another mass or inertia under"
    ):
        attach(loads(parent), loads(child), prefix="c_")


@pytest.mark.parametrize(
    ("inertial", "setting"),
    [
        ('mass="0.00999999" diaginertia="1 1 1"', 'boundmass="0.01"'),
        ('mass="1" diaginertia="1e-10 1e-10 1e-10"', 'boundinertia="1e-9"'),
    ],
    ids=["mass a millionth below", "inertia below a tiny bound"],
)
def test_the_smallest_change_the_parent_would_make_is_refused(inertial: str, setting: str) -> None:
    """A mass lifted by a millionth, or a tiny inertia lifted to a tiny bound, is refused."""
    child = (
        '<mujoco><worldbody><body name="b"><joint/>'
        f'<inertial pos="0 0 0" {inertial}/></body></worldbody></mujoco>'
    )
    compiler = f"<compiler {setting}/>"
    parent = f"<mujoco>{compiler}</mujoco>"
    alone = mujoco.MjModel.from_xml_string(child)
    under_parent = mujoco.MjModel.from_xml_string(child.replace("<mujoco>", parent[:-9]))
    assert not np.array_equal(alone.body_mass, under_parent.body_mass) or not np.array_equal(
        alone.body_inertia, under_parent.body_inertia
    )  # MuJoCo does change it under the parent's setting
    with pytest.raises(MjcfValueError, match="body 'b' would get another mass or inertia"):
        attach(loads(parent), loads(child), prefix="c_")


def test_a_child_that_does_not_compile_alone_is_refused() -> None:
    """A moving body without mass under the child's own settings: refused, saying so."""
    child = (
        '<mujoco><compiler inertiafromgeom="false"/><worldbody><body name="b"><joint/>'
        '<geom size="0.1"/></body></worldbody></mujoco>'
    )
    with pytest.raises(ValueError, match="mjMINVAL"):
        mujoco.MjModel.from_xml_string(child)
    with pytest.raises(
        MjcfValueError,
        match=r"^cannot keep the child's inertias under the parent's inertiafromgeom='auto' "
        r"\(child: 'false'\): MuJoCo does not compile the child alone: .*mjMINVAL",
    ):
        attach(Mujoco(), loads(child), prefix="c_")


# -- The child's own ``<lengthrange>`` does not block attaching under other inertia settings. --
#
# ``<lengthrange>`` is model-wide: the parent's holds, and attaching drops the
# child's. When an inertia setting differs, the child is compiled once more to read
# its inertias; that compile once kept the child's ``<lengthrange>``, so one MuJoCo
# cannot satisfy refused an attach the child's own compile allows.


BODY = (
    '<worldbody><body name="b"><joint name="j" type="slide"/><geom size="0.01" mass="0.001"/>'
    '</body></worldbody><actuator><motor joint="j"/></actuator></mujoco>'
)
#: A length range MuJoCo cannot compute for the motor on an unlimited slide joint.
LENGTHRANGE = '<lengthrange mode="all" useexisting="false"/>'


def test_a_child_lengthrange_does_not_block_keeping_its_inertias() -> None:
    """The child's unsatisfiable lengthrange (dropped anyway) does not refuse the attach."""
    child = f'<mujoco><compiler boundmass="0.5">{LENGTHRANGE}</compiler>{BODY}'
    alone = mujoco.MjModel.from_xml_string(f'<mujoco><compiler boundmass="0.5"/>{BODY}')
    scene = compiled(attach(Mujoco(), loads(child), prefix="c_"))
    assert np.array_equal(scene.body_mass, alone.body_mass)
