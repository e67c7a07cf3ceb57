"""Keys of parts attached inside a body: their entries sit where MuJoCo numbers them.

MuJoCo numbers joints (and mocap bodies) in document order, so parts appended
to a body come after everything above or inside that body and before what
comes later. The parent below has, before the ``mount`` body's end, a mocap
body, a slide and a ball joint (``qpos`` and ``qvel`` counts differ) and the
hinge of ``mount``; after it, a slide joint and a second mocap body. Every key
is checked, joint by joint, against the parts compiled alone by MuJoCo.
Parents whose tree does not show where the entries go, and parts MuJoCo
allows only at the top level, are refused with the way out.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model import GenericElement, MjcfValueError, Mujoco, attach, attach_all, compiled
from mjcf_model.tree.traversal import with_children
from serializers import loads

PARENT = """<mujoco>
  <worldbody>
    <body name="marker" mocap="true" pos="0 0 2">
      <geom size=".05" contype="0" conaffinity="0"/>
    </body>
    <body name="base">
      <joint name="rail" type="slide"/><geom size=".1"/>
      <body name="wrist" pos="0 0 .5"><joint name="knob" type="ball"/><geom size=".1"/></body>
      <body name="mount" pos="0 0 1"><joint name="elbow"/><geom size=".1"/></body>
      <body name="after" pos="1 0 0"><joint name="late" type="slide"/><geom size=".1"/></body>
    </body>
    <body name="flag" mocap="true" pos="1 1 1"><geom size=".05" contype="0" conaffinity="0"/></body>
  </worldbody>
  <keyframe>
    <key name="pose" qpos="0.1 0.7 0 0.7 0 0.3 0.2" qvel="1 2 3 4 5 6" mpos="0 0 3 1 1 2"/>
  </keyframe>
</mujoco>
"""
#: A finger whose key sets its slide's position and velocity.
FINGER = """<mujoco>
  <worldbody>
    <body name="finger"><joint name="pinch" type="slide" ref="0.05"/><geom size=".02"/></body>
  </worldbody>
  <keyframe><key name="closed" qpos="0.04" qvel="0.5"/></keyframe>
</mujoco>
"""


def _alone(text: str) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(text)


def _sizes(model: mujoco.MjModel, joint: str) -> tuple[int, int, int, int]:
    """Where ``joint``'s ``qpos`` and ``qvel`` entries start, and how many there are."""
    info = model.joint(joint)
    q, v = {0: (7, 6), 1: (4, 3), 2: (1, 1), 3: (1, 1)}[int(info.type[0])]
    return int(info.qposadr[0]), q, int(info.dofadr[0]), v


def _entries(model: mujoco.MjModel, key: str, joint: str) -> tuple[list[float], list[float]]:
    """The ``qpos`` and ``qvel`` entries of ``joint`` in the key named ``key``."""
    q, nq, v, nv = _sizes(model, joint)
    row = model.key(key)
    return row.qpos[q : q + nq].tolist(), row.qvel[v : v + nv].tolist()


def _initial(model: mujoco.MjModel, joint: str) -> tuple[list[float], list[float]]:
    """``joint``'s entries in the initial state: its ``qpos0``, no velocity."""
    q, nq, _, nv = _sizes(model, joint)
    return model.qpos0[q : q + nq].tolist(), [0.0] * nv


def _with_generic_flag(model: Mujoco) -> Mujoco:
    """``model`` with its last world body, ``flag``, as a generic element (``mocap`` as text)."""
    geom = GenericElement(
        tag="geom", attributes={"size": ".05", "contype": "0", "conaffinity": "0"}
    )
    attributes = {"name": "flag", "mocap": "true", "pos": "1 1 1"}
    flag = GenericElement(tag="body", attributes=attributes, children=[geom])
    world = model.worldbody
    children = [
        with_children(world, [*world.children[:-1], flag]) if c is world else c
        for c in model.children
    ]
    return with_children(model, children)


@pytest.mark.parametrize("generic", [False, True], ids=["typed", "generic_mocap_body"])
def test_two_fingers_at_a_body_sit_between_its_joints_and_the_later_ones(generic: bool) -> None:
    """Each finger's key sets it, every other part is at its own key or ``qpos0``, by name."""
    fingers = [(loads(FINGER), "l_"), (loads(FINGER), "r_")]
    model = _with_generic_flag(loads(PARENT)) if generic else loads(PARENT)
    scene = compiled(attach_all(model, fingers, at="mount"))
    parent, finger = _alone(PARENT), _alone(FINGER)
    assert scene.nkey == 3
    for key in ("pose", "l_closed", "r_closed"):
        for joint in ("rail", "knob", "elbow", "late"):
            own = _entries(parent, "pose", joint) if key == "pose" else _initial(parent, joint)
            assert _entries(scene, key, joint) == own, (key, joint)
        for prefix in ("l_", "r_"):
            mine = key == f"{prefix}closed"
            own = _entries(finger, "closed", "pinch") if mine else _initial(finger, "pinch")
            assert _entries(scene, key, prefix + "pinch") == own, (key, prefix)
    assert np.array_equal(scene.key("pose").mpos, parent.key("pose").mpos)


def test_a_parent_whose_replicate_hides_joints_is_refused_with_the_way_out() -> None:
    """A ``<replicate>`` in the parent: attach at the world or inline first, the error says."""
    replicated = loads(
        '<mujoco><worldbody><body name="shelf"><joint type="slide"/><geom size=".1"/></body>'
        '<replicate count="2" offset="1 0 0"><geom size=".1"/></replicate></worldbody>'
        '<keyframe><key qpos="0.2"/></keyframe></mujoco>'
    )
    with pytest.raises(
        MjcfValueError,
        match=r"whose <replicate> makes joints or bodies: attach at the world, or inline them "
        r"first \(mjcf_model\.inlined_attachments\)",
    ):
        attach(replicated, loads(FINGER), at="shelf", prefix="f_")


def test_a_mocap_part_inside_a_body_is_refused_naming_the_body() -> None:
    """A part with a mocap body attached at ``mount``: the error names the body it is inside."""
    target = loads(
        '<mujoco><worldbody><body name="t" mocap="true"><geom size=".1" contype="0" '
        'conaffinity="0"/></body></worldbody></mujoco>'
    )
    with pytest.raises(MjcfValueError, match=r"it is inside the <body> 'mount', and MuJoCo"):
        attach(loads(PARENT), target, at="mount", prefix="t_")
