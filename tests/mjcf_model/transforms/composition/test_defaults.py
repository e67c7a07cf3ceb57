"""Tests of ``mjcf_model.transforms.composition.defaults``."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model import attach, compiled, find, get_attribute
from mjcf_model.errors import MjcfValueError
from mjcf_model.serializers import loads

# -- The child's top-level defaults reach, after attaching, exactly the elements they reached
#    alone.
#
# MuJoCo compiling the child alone is the referee for the values; which elements
# name the child's class is what :mod:`mjcf_model.transforms.composition.defaults`
# documents: only those a setting of the class reaches.


def test_several_top_level_defaults_merge_with_later_settings_winning() -> None:
    """Two top-level <default> sections setting geoms act as MuJoCo merges them."""
    child = (
        '<mujoco><default><geom rgba="1 0 0 1" size="0.2" friction="0.7 0.01 0.01"/></default>'
        '<default><geom size="0.3" rgba="0 1 0 1"/></default>'
        '<worldbody><geom name="g"/></worldbody></mujoco>'
    )
    alone = mujoco.MjModel.from_xml_string(child)
    assert list(alone.geom("g").rgba) == [0, 1, 0, 1]  # the later section wins
    assert alone.geom("g").friction[0] == 0.7  # and what it leaves is the earlier's
    parent = loads('<mujoco><default><geom rgba="0 0 1 1" size="0.5"/></default></mujoco>')
    scene = compiled(attach(parent, loads(child), prefix="c_"))
    for field in ("rgba", "size", "friction"):
        assert np.array_equal(getattr(scene.geom("c_g"), field), getattr(alone.geom("g"), field))


def test_tendon_defaults_reach_spatial_and_fixed_tendons() -> None:
    """A child's <default><tendon> sets its spatial and fixed tendons, not the parent's."""
    child = (
        '<mujoco><default><tendon width="0.05" rgba="0 1 0 1"/></default><worldbody>'
        '<site name="a"/><body name="b" pos="0 0 1"><joint name="j"/><geom size="0.1"/>'
        '<site name="s"/></body></worldbody><tendon><spatial name="t"><site site="a"/>'
        '<site site="s"/></spatial><fixed name="f"><joint joint="j" coef="1"/></fixed>'
        "</tendon></mujoco>"
    )
    alone = mujoco.MjModel.from_xml_string(child)
    parent = loads('<mujoco><default><tendon width="0.01" rgba="1 0 0 1"/></default></mujoco>')
    composed = attach(parent, loads(child), prefix="c_")
    spatial = find(composed, "spatial", name="c_t")
    assert spatial is not None
    assert get_attribute(spatial, "class") == "c_main"
    scene = compiled(composed)
    for name in ("t", "f"):
        mine, theirs = scene.tendon(f"c_{name}").id, alone.tendon(name).id
        assert scene.tendon_width[mine] == alone.tendon_width[theirs] == 0.05
        assert np.array_equal(scene.tendon_rgba[mine], alone.tendon_rgba[theirs])


def test_actuators_take_no_class_the_child_sets_no_actuator_default_for() -> None:
    """An actuator no setting of the child's defaults reaches names no class."""
    child = (
        '<mujoco><default><geom rgba="1 0 0 1"/></default><worldbody><body name="b">'
        '<joint name="j"/><geom size="0.1"/></body></worldbody>'
        '<actuator><motor name="m" joint="j"/></actuator></mujoco>'
    )
    composed = attach(loads("<mujoco/>"), loads(child), prefix="c_")
    motor, body = find(composed, "motor", name="c_m"), find(composed, "body", name="c_b")
    assert motor is not None
    assert body is not None
    assert get_attribute(motor, "class") is None
    assert get_attribute(body, "childclass") == "c_main"


# -- A later top-level ``<default>`` setting what earlier classes miss is refused by ``attach``.
#
# MuJoCo gives a class its parent's settings as it reads the class: a class declared
# in a first top-level ``<default>`` does not get what a second one sets afterwards
# (within one section, order does not matter). ``attach`` merges a model's top-level
# sections into one class, where the earlier classes would inherit the later values,
# so it refuses such a model, parent or child, saying what to move.


BODY = '<worldbody><body childclass="a"><joint name="j"/><geom size=".1"/></body></worldbody>'
#: Class ``a`` is declared before the second section sets the joints' damping.
LATER = (
    '<mujoco><default><default class="a"/></default><default><joint damping="3"/></default>'
    f"{BODY}</mujoco>"
)
#: The same settings in one section: order within it does not matter to MuJoCo.
ONE = f'<mujoco><default><default class="a"/><joint damping="3"/></default>{BODY}</mujoco>'
SAID = r"top-level <default> number 2 sets values after an earlier one declared classes"


def test_mujoco_gives_the_later_setting_to_the_class_only_within_one_section() -> None:
    """The referee: damping 0 when set in a later section, 3 when set in the same one."""
    assert mujoco.MjModel.from_xml_string(LATER).joint("j").damping[0] == 0.0
    assert mujoco.MjModel.from_xml_string(ONE).joint("j").damping[0] == 3.0


@pytest.mark.parametrize("role", ["parent", "child"])
def test_sections_merged_otherwise_than_mujoco_reads_them_are_refused(role: str) -> None:
    """Attaching such a model, as parent or as child, raises the error naming the section."""
    parent, child = (LATER, "<mujoco/>") if role == "parent" else ("<mujoco/>", LATER)
    with pytest.raises(MjcfValueError, match=SAID):
        attach(loads(parent), loads(child), prefix="c_")


def test_one_section_in_any_order_is_attached_as_mujoco_reads_it() -> None:
    """Class before setting in one section: the attached joint keeps MuJoCo's damping."""
    scene = compiled(attach(loads("<mujoco/>"), loads(ONE), prefix="c_"))
    assert (
        scene.joint("c_j").damping[0] == mujoco.MjModel.from_xml_string(ONE).joint("j").damping[0]
    )
