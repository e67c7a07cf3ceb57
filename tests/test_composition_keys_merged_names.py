"""``keyframes="merged"``: keys of one name become one key; the others keep their own names.

A child's key whose name (before prefixing) a scene key has joins that key,
whatever its place among the child's keys; a child key no scene key names is
added under its own unprefixed name, so a second child attached in the same
call joins it; keys without a name, even written ``name=""``, are never merged
(mjcf_model/transforms/composition/keyframes.py). Expected values are the
parts compiled alone by MuJoCo: the owner's key, every other part at its
``qpos0`` with no control.
"""

from __future__ import annotations

import mujoco

from mjcf_model import attach_all, compiled
from serializers import loads

PARENT = """<mujoco>
  <worldbody><body name="base"><joint name="yaw"/><geom size=".1"/></body></worldbody>
  <actuator><motor name="turn" joint="yaw"/></actuator>
  <keyframe><key name="home" qpos="0.5" ctrl="1"/><key name="" qpos="0.25"/></keyframe>
</mujoco>
"""
#: An arm whose ``home`` is neither its first nor its last key.
ARM = """<mujoco>
  <worldbody>
    <body name="link"><joint name="shoulder" type="slide" ref="0.05"/><geom size=".1"/></body>
  </worldbody>
  <actuator><motor name="lift" joint="shoulder"/></actuator>
  <keyframe>
    <key name="solo" qpos="0.1" ctrl="0.2"/>
    <key name="home" qpos="0.3" ctrl="0.4"/>
    <key name="extra" qpos="0.6" ctrl="0.7"/>
    <key name="" qpos="0.9"/>
  </keyframe>
</mujoco>
"""


def _check(
    scene: mujoco.MjModel, row: int, owners: dict[str, tuple[mujoco.MjModel, str, int | None]]
) -> None:
    """Key ``row`` sets each part (prefix -> model alone, joint, its key or None) as expected."""
    for prefix, (alone, joint, key) in owners.items():
        at, own = scene.joint(prefix + joint).qposadr[0], alone.joint(joint).qposadr[0]
        qpos = alone.qpos0 if key is None else alone.key_qpos[key]
        ctrl = [0.0] * alone.nu if key is None else alone.key_ctrl[key].tolist()
        assert scene.key_qpos[row][at] == qpos[own], (row, prefix)
        actuator = scene.actuator(prefix + alone.actuator(0).name).id
        assert scene.key_ctrl[row][actuator] == ctrl[0], (row, prefix)


def test_merged_keys_match_by_name_and_new_names_stay_unprefixed() -> None:
    """Two arms in one call: ``home`` joins the parent's, ``solo``/``extra`` join each other."""
    arm = loads(ARM)
    scene = compiled(attach_all(loads(PARENT), [(arm, "a_"), (arm, "b_")], keyframes="merged"))
    parent, alone = mujoco.MjModel.from_xml_string(PARENT), mujoco.MjModel.from_xml_string(ARM)
    names = [scene.key(k).name for k in range(scene.nkey)]
    assert sorted(names) == ["", "", "", "extra", "home", "solo"]
    for name in ("home", "solo", "extra"):
        own = alone.key(name).id
        theirs = parent.key(name).id if name == "home" else None
        _check(
            scene,
            scene.key(name).id,
            {
                "": (parent, "yaw", theirs),
                "a_": (alone, "shoulder", own),
                "b_": (alone, "shoulder", own),
            },
        )


def test_keys_named_empty_are_never_merged() -> None:
    """``name=""`` keys of parent and arms stay three keys, each setting only its own part."""
    arm = loads(ARM)
    scene = compiled(attach_all(loads(PARENT), [(arm, "a_"), (arm, "b_")], keyframes="merged"))
    parent, alone = mujoco.MjModel.from_xml_string(PARENT), mujoco.MjModel.from_xml_string(ARM)
    unnamed = [k for k in range(scene.nkey) if scene.key(k).name == ""]
    assert len(unnamed) == 3
    parts = {"": (parent, "yaw"), "a_": (alone, "shoulder"), "b_": (alone, "shoulder")}
    for row, owner in zip(unnamed, parts, strict=True):
        _check(
            scene,
            row,
            {
                prefix: (model, joint, _unnamed(model) if prefix == owner else None)
                for prefix, (model, joint) in parts.items()
            },
        )


def _unnamed(model: mujoco.MjModel) -> int:
    """The id of ``model``'s one unnamed key."""
    (key,) = (k for k in range(model.nkey) if model.key(k).name == "")
    return key
