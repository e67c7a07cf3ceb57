"""The scene check (tests/support/scenes.py) on robosuite's and dm_control's robots and on fixtures.

Each case is one robot attached twice beside a placed free box; each stage of the check is
its own test, so a failure names the case, the stage, the part and the body.
"""

from __future__ import annotations

import functools
import importlib.util
import tempfile
from pathlib import Path
from typing import Any

import attrs
import mujoco
import pytest

from mjcf_model import Mujoco, attach, get_attribute, with_attributes
from mjcf_model.tree.traversal import map_elements
from tests.support.scenes import SCENES, STAGES, Part, home_key, main, scene_layout, scene_problems


def _installed(package: str, relative: str) -> Path:
    """A file of an installed wheel, found without importing the package."""
    spec = importlib.util.find_spec(package)
    assert spec is not None and spec.origin is not None, f"{package} is a test dependency"
    return Path(spec.origin).parent / relative


@attrs.frozen
class Case:
    """A robot file, where its second copy goes, and whether the test adds it a ``home`` key."""

    name: str
    path: Path
    point: str

    def part(self) -> Part:
        """The robot; one without keys gets a ``home`` key drawn within its ranges."""
        alone = mujoco.MjModel.from_xml_path(str(self.path))
        return Part(self.path, () if alone.nkey else (("home", home_key(alone, seed=7)),))


#: Robots without keys of their own, from the wheels (each compiles alone).
WHEELS = [
    ("robosuite/panda", "robosuite", "models/assets/robots/panda/robot.xml", "site"),
    ("robosuite/sawyer", "robosuite", "models/assets/robots/sawyer/robot.xml", "frame"),
    ("robosuite/iiwa", "robosuite", "models/assets/robots/iiwa/robot.xml", "site"),
    ("robosuite/ur5e", "robosuite", "models/assets/robots/ur5e/robot.xml", "frame"),
    ("robosuite/kinova3", "robosuite", "models/assets/robots/kinova3/robot.xml", "site"),
    ("robosuite/jaco", "robosuite", "models/assets/robots/jaco/robot.xml", "frame"),
    ("robosuite/panda_gripper", "robosuite", "models/assets/grippers/panda_gripper.xml", "site"),
    (
        "robosuite/robotiq_140",
        "robosuite",
        "models/assets/grippers/robotiq_gripper_140.xml",
        "frame",
    ),
    ("dm_control/humanoid", "dm_control", "suite/humanoid.xml", "site"),
    ("dm_control/quadruped", "dm_control", "suite/quadruped.xml", "frame"),
    ("dm_control/cheetah", "dm_control", "suite/cheetah.xml", "site"),
]
#: Fixtures with keys of their own, for what the wheels lack; each at a site and at a frame.
FIXTURES = ["floating_arm", "mocap_rig", "nested_free", "filter_arm"]
CASES = [Case(name, _installed(package, file), point) for name, package, file, point in WHEELS] + [
    Case(f"fixture/{name}", SCENES / f"{name}.xml", point)
    for name in FIXTURES
    for point in ("site", "frame")
]
BY_NAME = {f"{case.name}@{case.point}": case for case in CASES}


@functools.cache
def _outcome(name: str) -> dict[str, list[str]]:
    """The scene check of one case, run once for all its stages."""
    case = BY_NAME[name]
    with tempfile.TemporaryDirectory() as workdir:
        return scene_problems(case.part(), case.point, Path(workdir))


@pytest.mark.parametrize("stage", STAGES)
@pytest.mark.parametrize("name", list(BY_NAME))
def test_the_scene_check(name: str, stage: str) -> None:
    """The stage passes for the case: counts, initial poses, keys, files, merged keys."""
    problems = _outcome(name)[stage]
    assert not problems, f"{name}, stage {stage}:\n" + "\n".join(problems)


def test_the_cases_cover_the_brief() -> None:
    """The cases hold free joints, mocap bodies, activations, short and unnamed keys, all points."""
    alone = {name: mujoco.MjModel.from_xml_path(str(c.path)) for name, c in BY_NAME.items()}
    free = [n for n, m in alone.items() if (m.jnt_type == mujoco.mjtJoint.mjJNT_FREE).any()]
    assert len(free) >= 4
    assert any(m.nmocap for m in alone.values())
    assert any(m.na and m.nkey for m in alone.values())
    assert any((m.key_act != 0).any() and (m.key_ctrl != 0).any() for m in alone.values())
    unnamed = [m for m in alone.values() if any(not m.key(k).name for k in range(m.nkey))]
    assert unnamed
    points = {scene_layout(alone[n], BY_NAME[n].point)[1].at for n in alone}
    assert points == {"spot", "dock_inner", "table_site", "table_frame"}


GRIPPER = Case("gripper", _installed("robosuite", WHEELS[6][2]), "site")


def test_fixed_robots_compose_without_a_free_object(tmp_path: Path) -> None:
    """A fixed-base robot, twice, without the free box: all but merged keys pass."""
    problems = scene_problems(GRIPPER.part(), "site", tmp_path, thing=None)
    assert {stage: found for stage, found in problems.items() if stage != "merged"} == {
        "compiled": [],
        "initial": [],
        "keys": [],
        "files": [],
    }


def _misplacing(parent: Mujoco, child: Mujoco, **options: Any) -> Mujoco:
    """``attach``, with the ``b_`` copy placed 1 mm off."""
    if options.get("prefix") == "b_":
        x, y, z = options["pos"]
        options["pos"] = (x + 1e-3, y, z)
    return attach(parent, child, **options)


def test_the_check_names_a_misplaced_copy_and_its_bodies(tmp_path: Path) -> None:
    """A copy placed 1 mm off fails the initial poses, naming that copy and each of its bodies."""
    problems = scene_problems(GRIPPER.part(), "site", tmp_path, attach=_misplacing, thing=None)
    initial = problems["initial"]
    assert initial and all(line.startswith("copy b_: body 'b_") for line in initial)
    assert "copy b_: body 'b_right_gripper' at" in "\n".join(initial)
    assert problems["compiled"] == []


def _wrong_key(parent: Mujoco, child: Mujoco, **options: Any) -> Mujoco:
    """``attach``, then the ``b_home`` key's controls all 0.5."""
    scene = attach(parent, child, **options)

    def changed(element: Any, key: str | None, _ancestors: Any) -> Any:
        if key == "keyframe/key" and get_attribute(element, "name") == "b_home":
            ctrl = get_attribute(element, "ctrl")
            return with_attributes(element, {"ctrl": tuple(0.5 for _ in ctrl)})
        return element

    result = map_elements(changed, scene)
    assert isinstance(result, Mujoco)
    return result


def test_the_check_names_a_key_with_wrong_controls(tmp_path: Path) -> None:
    """A key whose controls differ fails the keys stage, naming the key and the control."""
    problems = scene_problems(GRIPPER.part(), "frame", tmp_path, attach=_wrong_key, thing=None)
    keys = problems["keys"]
    assert keys and all(line.startswith("key 'b_home': ctrl[") for line in keys)
    assert problems["initial"] == []


def test_the_command_line_prints_each_stage(capsys: pytest.CaptureFixture[str]) -> None:
    """``python -m tests.support.scenes`` prints a line per stage and the passes per stage."""
    main([str(SCENES / "filter_arm.xml")])
    lines = capsys.readouterr().out.splitlines()
    assert [line.split()[3] for line in lines[:-1]] == [f"{stage}:" for stage in STAGES]
    assert lines[-1].startswith("models 1; passed per stage: {'compiled': ")
