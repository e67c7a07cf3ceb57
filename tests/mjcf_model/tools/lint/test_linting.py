# ruff: noqa: E501  (the table of reviewed findings keeps one finding group a line)
"""Tests of ``mjcf_model.tools.lint.linting``: choosing rules, and every finding on the corpus.

Every finding on the shipped corpus was reviewed; :data:`REVIEWED` holds how many each
file gets from each rule, and why each is a real mistake in that file (or a
declaration the file's own Python code uses, said so). A finding not in it fails the
test: a rule that finds something new on a file is either right (review it, add it)
or wrong (fix the rule).
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import mujoco
import pytest

from mjcf_model import load
from mjcf_model.errors import MjcfValueError
from mjcf_model.tools.lint import RULES, lint, selected_rules
from tests.conftest import MUJOCO_VERSION, compiling_corpus, corpus_id

_UNUSED = "declared and used by nothing in the file (nor by the package's Python)"
_SAME_FILE = "collision and visual meshes of one file with the same settings: read twice"
_ZERO_POSE = "its qpos0 folds links into each other; the package's Python starts it elsewhere"

#: Each corpus file's findings, by rule: how many, and why each is a real mistake there.
REVIEWED: dict[tuple[str, str], tuple[int, str]] = {
    ("dm_control/locomotion/walkers/assets/build_fruitfly/assets/drosophila_fused.xml", "A401"): (1, "material 'base': " + _UNUSED),
    ("dm_control/locomotion/walkers/assets/dog_v2/dog.xml", "A401"): (1, "mesh 'Xiphoid_cartilage': " + _UNUSED),
    ("dm_control/mjcf/test_assets/model_with_assetdir.xml", "A401"): (1, "named 'unused_asset_should_not_cause_problems'"),
    ("dm_control/mjcf/test_assets/model_with_assets.xml", "A401"): (1, "named 'unused_asset_should_not_cause_problems'"),
    ("dm_control/mjcf/test_assets/model_with_separators.xml", "A401"): (1, "named 'unused_asset_should_not_cause_problems'"),
    ("robosuite/models/assets/arenas/multi_table_arena.xml", "A401"): (6, "table_ceramic is for the tables multi_table_arena.py adds; the other five: " + _UNUSED),
    ("robosuite/models/assets/arenas/pegs_arena.xml", "A401"): (2, "table_mat and textable: " + _UNUSED),
    ("robosuite/models/assets/arenas/table_arena.xml", "A401"): (2, "table_mat and textable: " + _UNUSED),
    ("robosuite/models/assets/bases/omron_mobile_base.xml", "A401"): (2, "two Opaque(...) materials left by a URDF conversion: " + _UNUSED),
    ("robosuite/models/assets/grippers/fourier_left_hand.xml", "A401"): (1, "l_thumb_distal_material: " + _UNUSED),
    ("robosuite/models/assets/grippers/fourier_right_hand.xml", "A401"): (1, "r_thumb_distal_material: " + _UNUSED),
    ("robosuite/models/assets/grippers/panda_gripper.xml", "A401"): (1, "mesh finger_vis2: " + _UNUSED),
    ("robosuite/models/assets/objects/door.xml", "A401"): (2, "light-wood texture and MatLightWood: " + _UNUSED),
    ("robosuite/models/assets/objects/door_lock.xml", "A401"): (2, "light-wood texture and MatLightWood: " + _UNUSED),
    ("robosuite/models/assets/robots/gr1/robot.xml", "A401"): (4, "hand pitch meshes, body texture and material: " + _UNUSED),
    ("robosuite/models/assets/robots/spot/robot.xml", "A401"): (1, "mesh rear_right_lower_leg: " + _UNUSED),
    ("robosuite/models/assets/robots/spot_arm/robot.xml", "A401"): (1, "mesh arm_link_hr0: " + _UNUSED),
    ("robosuite/models/assets/robots/tiago/robot.xml", "A401"): (9, "gripper and hand meshes of a hand the file does not build: " + _UNUSED),
    ("robosuite/models/assets/robots/xarm7/robot.xml", "A401"): (4, "meshes link7 and end_tool, materials gray and black: " + _UNUSED),
    ("dm_control/locomotion/walkers/assets/dog_v2/dog.xml", "A402"): (2, "connector and muscle: for tendons dm_control's dog builder adds in Python"),
    ("dm_control/locomotion/walkers/assets/dog_v2/dog_base.xml", "A402"): (40, "for the bodies dm_control's build_dog.py adds to this base"),
    ("dm_control/locomotion/walkers/assets/humanoid_CMU_V2019.xml", "A402"): (1, "stiff_medium_higher: " + _UNUSED),
    ("dm_control/locomotion/walkers/assets/rodent.xml", "A402"): (1, "bone: " + _UNUSED),
    ("dm_control/suite/dog.xml", "A402"): (2, "connector and muscle: for tendons the suite's dog code adds in Python"),
    ("dm_control/suite/manipulator.xml", "A402"): (1, "task: for the props the task's Python adds"),
    ("dm_control/suite/stacker.xml", "A402"): (2, "task and obstacle: for the props the task's Python adds"),
    ("robosuite/models/assets/robots/gr1/robot.xml", "A402"): (1, "class body: " + _UNUSED),
    ("dm_control/mjcf/test_assets/model_with_assetdir.xml", "A403"): (1, "the unused mesh loads cube.stl again"),
    ("dm_control/mjcf/test_assets/model_with_assets.xml", "A403"): (1, "the unused mesh loads cube.stl again"),
    ("dm_control/mjcf/test_assets/model_with_separators.xml", "A403"): (1, "the unused mesh loads cube.stl again"),
    ("robosuite/models/assets/grippers/fourier_left_hand.xml", "A403"): (12, _SAME_FILE),
    ("robosuite/models/assets/grippers/fourier_right_hand.xml", "A403"): (12, _SAME_FILE),
    ("robosuite/models/assets/grippers/inspire_left_hand.xml", "A403"): (13, _SAME_FILE),
    ("robosuite/models/assets/grippers/inspire_right_hand.xml", "A403"): (13, _SAME_FILE),
    ("robosuite/models/assets/robots/tiago/robot.xml", "A403"): (14, _SAME_FILE),
    ("robosuite/models/assets/bases/floating_legged_base.xml", "I101"): (1, "yaw velocity servo kv 1000 on the bare base's 0.013 kg m2 under Euler: kv/I*h 156; robosuite mounts a robot on it, whose inertia steadies it"),
    ("dm_control/locomotion/walkers/assets/build_fruitfly/assets/drosophila_fused.xml", "P101"): (9, "mouth parts and legs overlap their neighbours at rest"),
    ("dm_control/mjcf/test_assets/robot_arm.xml", "P101"): (11, "a test arm whose qpos0 puts links into its base"),
    ("dm_control/mujoco/testing/assets/arm.xml", "P101"): (7, "a test arm whose qpos0 puts links into the ground"),
    ("dm_control/third_party/kinova/jaco_arm.xml", "P101"): (18, _ZERO_POSE),
    ("robosuite/models/assets/grippers/panda_gripper.xml", "P101"): (1, "the closed fingers' pads overlap"),
    ("robosuite/models/assets/grippers/robotiq_gripper_140.xml", "P101"): (4, "inner finger and knuckle meshes overlap at rest"),
    ("robosuite/models/assets/grippers/robotiq_gripper_s.xml", "P101"): (2, "the palm and the first phalanges overlap at rest"),
    ("robosuite/models/assets/robots/jaco/robot.xml", "P101"): (10, _ZERO_POSE),
    ("robosuite/models/assets/robots/panda/robot.xml", "P101"): (1, "link5 and link7 overlap at qpos0 (robosuite starts from init_qpos)"),
}  # fmt: skip


def test_rules_are_chosen_by_code_or_prefix_as_ruff_chooses_them() -> None:
    """``select`` keeps, ``ignore`` drops; an entry that matches nothing is refused."""
    assert [r.code for r in selected_rules()] == sorted(RULES)
    assert {r.code[0] for r in selected_rules(select=["K"])} == {"K"}
    assert "A401" not in {r.code for r in selected_rules(ignore=["A40"])}
    with pytest.raises(MjcfValueError, match="no lint rule is 'Z9'"):
        selected_rules(select=["Z9"])


@pytest.mark.skipif(
    MUJOCO_VERSION < (4, 0),
    reason=f"the findings were reviewed with MuJoCo 4.0 (this is {mujoco.__version__}); the "
    "rules' own tests run here",
)
@pytest.mark.parametrize("path", compiling_corpus(), ids=corpus_id)
def test_every_finding_on_the_corpus_is_a_reviewed_one(path: Path) -> None:
    """Each rule finds on each corpus file exactly what was reviewed; each finding is placed."""
    findings = lint(load(path, inline_includes=True))
    found = Counter(finding.rule for finding in findings)
    expected = {
        rule: count for (name, rule), (count, _) in REVIEWED.items() if name == corpus_id(path)
    }
    assert dict(found) == expected
    for finding in findings:
        assert finding.file and finding.line and finding.path, finding
