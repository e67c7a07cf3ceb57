"""Tests of the contact rules: geoms that start inside each other, as MuJoCo detects them."""

from __future__ import annotations

import mujoco

from mjcf_model import loads
from mjcf_model.tools.lint import lint

SCENE = """
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="box" pos="0 0 {z}"><freejoint/>
      <geom name="box" type="box" size="0.1 0.1 0.1" {filters}/></body>
  </worldbody>
  {keys}
</mujoco>
"""


#: How the messages give a depth of 5 cm.
DEEP = "overlap by 0.05 (in the model's unit of length; 50 mm in metres)"


def _findings(z: float, filters: str = "", keys: str = "") -> list[tuple[str, str]]:
    text = SCENE.format(z=z, filters=filters, keys=keys)
    return [(f.rule, f.message.split(":")[0]) for f in lint(loads(text), select=["P"])]


def test_geoms_overlapping_at_qpos0_are_found_with_their_depth() -> None:
    """P101: 50 mm into the floor; resting on it, or 0.5 mm in, is not found."""
    assert _findings(0.05) == [
        (
            "P101",
            f"geoms 'floor' and 'box' {DEEP} at qpos0",
        )
    ]
    assert _findings(0.1) == [] and _findings(0.0995) == []


def test_geoms_that_cannot_collide_are_not_found() -> None:
    """MuJoCo's filters decide: contype and conaffinity that do not match make no contact."""
    assert _findings(0.05, filters='contype="0" conaffinity="0"') == []


def test_geoms_overlapping_at_a_key_are_found_for_that_key() -> None:
    """P102: the key sinks the box; a key that lifts it is not found."""
    sunk = '<keyframe><key name="sunk" qpos="0 0 0.05 1 0 0 0"/></keyframe>'
    lifted = '<keyframe><key name="up" qpos="0 0 1 1 0 0 0"/></keyframe>'
    assert _findings(1, keys=sunk) == [
        (
            "P102",
            f"geoms 'floor' and 'box' {DEEP} at key 'sunk'",
        )
    ]
    assert _findings(1, keys=lifted) == []


def test_a_part_welded_to_the_world_is_filtered_as_once_mounted() -> None:
    """A palm welded to the world and its finger: filtered as MuJoCo filters them once mounted.

    MuJoCo collides parent and child only while the parent is welded to the world;
    mounted on a moving arm it filters them, and the rule does so either way.
    """
    hand = """<mujoco><worldbody>{mount}<body name="palm" pos="0 0 1">{joint}
      <geom name="palm" type="box" size="0.05 0.05 0.05"/>
      <body name="finger" pos="0 0 0.06"><joint type="slide" axis="1 0 0"/>
        <geom name="finger" type="box" size="0.02 0.02 0.03"/></body>
      </body>{close}</worldbody></mujoco>"""
    alone = hand.format(mount="", joint="", close="")
    mounted = hand.format(mount='<body name="arm"><joint/>', joint="", close="</body>")
    assert lint(loads(alone), select=["P"]) == lint(loads(mounted), select=["P"]) == []

    for text, colliding in ((alone, True), (mounted, False)):  # what MuJoCo itself does
        model = mujoco.MjModel.from_xml_string(text)
        data = mujoco.MjData(model)
        mujoco.mj_forward(model, data)
        assert (data.ncon > 0) == colliding
        assert all(contact.dist < -0.01 for contact in data.contact[: data.ncon])
