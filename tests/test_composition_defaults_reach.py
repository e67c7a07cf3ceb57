"""The child's top-level defaults reach, after attaching, exactly the elements they reached alone.

MuJoCo compiling the child alone is the referee for the values; which elements
name the child's class is what :mod:`mjcf_model.transforms.composition.defaults`
documents: only those a setting of the class reaches.
"""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import attach, compiled, find, get_attribute
from serializers import loads


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
