"""The composition oracle (tests/support/composition_oracle.py): complete; finds what is wrong."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from mjcf_model import Mujoco, attach, compiled
from mjcf_model.bridge.compare import model_fields
from mjcf_model.serializers import load, loads
from tests.conftest import FIXTURES
from tests.support.composition_oracle import (
    DATA,
    KINDS,
    NOT_COMPARED,
    REFERENCES,
    PlacedPart,
    composition_problems,
    field_roles,
)

ARM = FIXTURES / "compose" / "arm_radian" / "arm.xml"
WALKER = FIXTURES / "compose" / "walker_limits" / "walker.xml"
EMPTY = "<mujoco/>"
#: A parent with a slide joint and a key, and a free box whose key leaves qpos to MuJoCo.
TRACK = """<mujoco><worldbody><body name="cart"><joint name="rail" type="slide"/>
<geom size=".1" mass="1"/></body></worldbody>
<keyframe><key name="k" qpos="0.4"/></keyframe></mujoco>"""
BOX = """<mujoco><worldbody><body name="box" pos="0.1 0.2 0.3" euler="0 0 30">
<freejoint name="free"/><geom type="box" size=".05 .05 .05" mass=".2"/></body></worldbody>
<keyframe><key name="still" time="2"/><key name="thrown" qpos="1 2 3 0 1 0 0" qvel="1 0 0 0 0 1"/>
</keyframe></mujoco>"""
PLACE = {"pos": (0.3, -0.4, 0.5), "quat": (0.9238795325112867, 0.0, 0.0, 0.3826834323650898)}


def _two_arms() -> tuple[list[PlacedPart], mujoco.MjModel]:
    scene = attach(attach(Mujoco(), load(ARM), prefix="a_"), load(WALKER), prefix="b_")
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string(EMPTY)),
        PlacedPart(mujoco.MjModel.from_xml_path(str(ARM)), "a_"),
        PlacedPart(mujoco.MjModel.from_xml_path(str(WALKER)), "b_"),
    ]
    return parts, compiled(scene)


#: Listed fields MuJoCo 4.0 added (CI's oldest environment runs MuJoCo 3.9).
NEWER_FIELDS = frozenset({"site_dataid", "tex_contenttypeadr"})


def test_every_field_of_an_object_kind_is_compared_or_listed_with_a_reason() -> None:
    """Each MjModel field with a kind's prefix has a role; the listed ones are real and reasoned."""
    roles = field_roles()
    prefixed = {f for f in model_fields() if f.split("_")[0] in KINDS}
    assert prefixed <= roles.keys()
    assert {"body_pos", "geom_size", "key_qpos", "qpos0", "mesh_vert"} <= roles.keys()
    listed = REFERENCES.keys() | DATA.keys() | NOT_COMPARED.keys()
    assert listed <= set(model_fields()) | NEWER_FIELDS  # no typo: each is MuJoCo's
    assert all(len(reason) > 20 for reason in NOT_COMPARED.values())
    assert len(NOT_COMPARED) <= 20
    assert "unclassified id" not in roles.values(), "an id field needs its kind in REFERENCES"
    assert roles["geom_fluid"] == "value" and roles["geom_bodyid"] == "reference"


def test_a_correct_scene_has_no_problems() -> None:
    """Two fixture robots attached into an empty world are exactly their parts."""
    parts, scene = _two_arms()
    assert composition_problems(parts, scene) == []


@pytest.mark.parametrize(
    ("field", "kind"),
    [("geom_size", "geom"), ("jnt_range", "jnt"), ("body_ipos", "body"), ("dof_damping", "dof")],
)
def test_a_changed_value_of_any_kind_is_found(field: str, kind: str) -> None:
    """Changing one row of a per-object array of the scene is reported for that kind."""
    parts, scene = _two_arms()
    values = getattr(scene, field)
    values[-1] = values[-1] + 0.125
    problems = composition_problems(parts, scene)
    assert problems and all(p.startswith(kind) for p in problems), problems


def test_a_reference_to_the_wrong_object_is_found() -> None:
    """An actuator driving another joint of the scene is reported by the joint it points to."""
    parts, scene = _two_arms()
    scene.actuator_trnid[-1][0] = 0
    problems = composition_problems(parts, scene)
    assert problems and all("actuator_trnid" in p for p in problems), problems


def test_a_missing_or_extra_object_is_found(tmp_path: Path) -> None:
    """A part's object the scene lacks, or one it adds, breaks the counts and the names."""
    parts, _ = _two_arms()
    spec = mujoco.MjSpec.from_string(compiled_text := _scene_text())
    spec.worldbody.add_site(name="stray")
    assert "nsite is" in " ".join(composition_problems(parts, spec.compile()))
    assert compiled_text


def _scene_text() -> str:
    from mjcf_model.serializers import dumps

    scene = attach(attach(Mujoco(), load(ARM), prefix="a_"), load(WALKER), prefix="b_")
    return dumps(scene)


def _box_scene(**keywords: object) -> tuple[list[PlacedPart], mujoco.MjModel]:
    scene = attach(loads(TRACK), loads(BOX), prefix="obj_", **keywords)  # type: ignore[arg-type]
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string(TRACK)),
        PlacedPart(mujoco.MjModel.from_xml_string(BOX), "obj_", **keywords),  # type: ignore[arg-type]
    ]
    return parts, compiled(scene)


def test_keys_of_a_placed_free_body_follow_its_pos_and_quat() -> None:
    """Keys completed from a free body's initial pose, and set ones, move with pos and quat."""
    parts, scene = _box_scene(**PLACE)
    assert scene.nkey == 3
    assert composition_problems(parts, scene) == []


def test_the_parents_key_holds_the_placed_free_body_where_it_was_placed() -> None:
    """The parent's key puts the box at its placed initial pose: body pos moved by the placement."""
    parts, scene = _box_scene(pos=PLACE["pos"])
    key = mujoco.mj_name2id(scene, mujoco.mjtObj.mjOBJ_KEY, "k")
    expected = np.array([0.1, 0.2, 0.3]) + PLACE["pos"]
    assert np.allclose(scene.key_qpos[key][1:4], expected, rtol=0, atol=1e-12)
    assert composition_problems(parts, scene) == []


def test_a_key_placed_wrong_is_found() -> None:
    """A free joint's key position off by a placement is reported with the joint's name."""
    parts, scene = _box_scene(**PLACE)
    scene.key_qpos[0][1] += 0.3
    assert any("'obj_free': key_qpos" in p for p in composition_problems(parts, scene))


MOCAP = """<mujoco><worldbody><body name="target" mocap="true" pos="0.1 0 0.2">
<geom size=".02" contype="0" conaffinity="0"/></body></worldbody>
<keyframe><key name="there" mpos="0.5 0.5 0.5" mquat="0 1 0 0"/></keyframe></mujoco>"""


def test_mocap_bodies_in_keys_follow_the_placement() -> None:
    """A mocap body's key pose and its placed initial pose in the parent's key are checked."""
    scene = attach(loads(TRACK), loads(MOCAP), prefix="m_", **PLACE)  # type: ignore[arg-type]
    parts = [
        PlacedPart(mujoco.MjModel.from_xml_string(TRACK)),
        PlacedPart(mujoco.MjModel.from_xml_string(MOCAP), "m_", **PLACE),  # type: ignore[arg-type]
    ]
    together = compiled(scene)
    assert composition_problems(parts, together) == []
    together.key_mpos[0][0] += 0.25
    assert any("mocap body 'm_target'" in p for p in composition_problems(parts, together))
