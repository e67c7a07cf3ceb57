"""robosuite 1.5.2's own environments with this library's objects, unpatched.

Each of robosuite's 19 manipulation environments is built three times on the same seed:
as robosuite ships it; with every object class (and ``CustomMaterial``) the modules
that build its objects import from robosuite replaced by this library's twin; and with
the global swap a program does by assignment: those names and every function and class
of robosuite's ``mjcf_utils`` replaced in every robosuite module imported,
``robosuite.models.objects`` and the modules defining the classes included (robosuite's
robots, grippers and arenas then build through this library's ``mjcf_utils`` too). Each
is reset and stepped with the same seeded random actions (:data:`STEPS` of them). The
compiled models, the model XML, every observation, every reward, every ``done`` flag and
every success check must be identical. An environment that used an object class this
library lacks fails here, since every robosuite object class a building module imports
is replaced. robosuite's composite robots (a Panda on an Omron base, Spot with its arm,
Panda with a dexterous hand, GR1) run the same way with the global swap.

robosuite 1.5.2 itself runs only on MuJoCo up to 3.9 (from 3.10 on its own
controllers call ``mj_fullM`` with the old arguments and read ``MjData.qM``), so
these tests run in the ``oldest`` environment of ``tests/run_installed.py``
(MuJoCo 3.9.0) and say why they do not run on a newer MuJoCo.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any

import mujoco
import numpy as np
import pytest

from benchmarks.environments import TASKS, make, our_objects
from mjcf_model.bridge.compare import model_differences
from tests.conftest import MUJOCO_VERSION
from tests.support.compat_objects import text_of

pytestmark = pytest.mark.skipif(
    MUJOCO_VERSION >= (3, 10),
    reason=f"robosuite 1.5.2 does not run on MuJoCo {mujoco.__version__} (only up to 3.9); "
    "tests/run_installed.py runs these in its 'oldest' environment",
)

#: How many random actions each run takes.
STEPS = 25


def _record(task: str, seed: int, robots: str | None = None) -> dict[str, Any]:
    """Build, reset and step ``task``: the compiled model, its XML and each step's result."""
    env = make(task, seed, robots)
    try:
        reset = env.reset()
        actions = np.random.default_rng(seed)
        low, high = env.action_spec
        low, high = np.maximum(low, -1.0), np.minimum(high, 1.0)  # GR1's are unbounded
        steps, successes = [], []
        for _ in range(STEPS):
            steps.append(env.step(actions.uniform(low, high)))
            successes.append(env._check_success())
        return {
            "objects": TASKS[task].objects(env),
            "model": env.sim.model._model,
            "xml": env.model.get_xml(),
            "reset": reset,
            "steps": steps,
            "successes": successes,
        }
    finally:
        env.close()


def _assert_same_observations(mine: dict[str, Any], theirs: dict[str, Any], label: str) -> None:
    assert mine.keys() == theirs.keys(), label
    for key in theirs:
        np.testing.assert_array_equal(mine[key], theirs[key], err_msg=f"{label}: {key}")


def test_every_robosuite_environment_is_run() -> None:
    """The table holds exactly robosuite's manipulation environments."""
    import robosuite

    assert set(TASKS) == set(robosuite.ALL_ENVIRONMENTS)


@pytest.mark.parametrize("task", list(TASKS))
def test_task_runs_identically_with_this_librarys_objects(task: str) -> None:
    """Same compiled model, XML, observations, rewards and done flags over the random steps.

    Both ways of switching: the building modules' names, and every robosuite name.
    """
    theirs = _record(task, seed=3)
    with our_objects(task) as replaced:
        mine = _record(task, seed=3)
    assert replaced
    _assert_same_run(mine, theirs)
    with our_objects(task, everywhere=True) as everywhere:
        swapped = _record(task, seed=3)
    assert set(replaced) < set(everywhere) and "new_body" in everywhere
    _assert_same_run(swapped, theirs)


@pytest.mark.parametrize("robot", ["PandaOmron", "SpotWithArm", "PandaDexRH", "GR1"])
def test_composite_robots_run_identically_with_every_robosuite_name_replaced(robot: str) -> None:
    """Composite robots build the model robosuite builds, and step the same.

    Through this library's ``mjcf_utils`` and objects, every robosuite name replaced.
    """
    theirs = _record("Lift", seed=5, robots=robot)
    with our_objects("Lift", everywhere=True):
        mine = _record("Lift", seed=5, robots=robot)
    _assert_same_run(mine, theirs)


def test_the_global_swap_keeps_isinstance_against_robosuites_own_classes() -> None:
    """``isinstance`` holds against robosuite's own class after the global swap.

    Assigning this library's class to robosuite's names (in the package and in the
    defining module) leaves robosuite's own class findable; ``isinstance`` against it,
    and against the name now bound to ours, holds.
    """
    import robosuite.models.objects as their_objects
    import robosuite.models.objects.primitive.box as box_module

    from mjcf_model.compat.objects import BoxObject

    original = their_objects.BoxObject
    with our_objects("Lift", everywhere=True):
        assert their_objects.BoxObject is BoxObject and box_module.BoxObject is BoxObject
        cube = BoxObject("cube", size=[0.02, 0.02, 0.02])
        assert isinstance(cube, original) and isinstance(cube, their_objects.BoxObject)
        assert isinstance(cube, their_objects.MujocoObject)
    assert their_objects.BoxObject is original


def _assert_same_run(mine: dict[str, Any], theirs: dict[str, Any]) -> None:
    assert mine["objects"]
    assert all(type(obj).__module__.startswith("mjcf_model") for obj in mine["objects"])
    assert [type(obj).__name__ for obj in mine["objects"]] == [
        type(obj).__name__ for obj in theirs["objects"]
    ]
    assert model_differences(mine["model"], theirs["model"]) == []
    assert text_of(ET.fromstring(mine["xml"])) == text_of(ET.fromstring(theirs["xml"]))
    _assert_same_observations(mine["reset"], theirs["reset"], "reset")
    assert len(mine["steps"]) == len(theirs["steps"]) == STEPS
    for index, (my_step, their_step) in enumerate(zip(mine["steps"], theirs["steps"], strict=True)):
        (my_obs, my_reward, my_done, _), (their_obs, their_reward, their_done, _) = (
            my_step,
            their_step,
        )
        _assert_same_observations(my_obs, their_obs, f"step {index}")
        assert (my_reward, my_done) == (their_reward, their_done), f"step {index}"
    assert mine["successes"] == theirs["successes"]
    # The run really moves what the environment watches.
    observed = [step[0] for step in theirs["steps"]]
    assert any(not np.array_equal(observed[0][key], observed[-1][key]) for key in observed[0])
