"""robosuite 1.5.2's own environments with this library's objects, unpatched.

Each of robosuite's 19 manipulation environments is built twice on the same seed,
once as robosuite ships it and once with every object class (and
``CustomMaterial``) the modules that build its objects import from robosuite
replaced by this library's twin; both are reset and stepped with the same seeded
random actions (:data:`STEPS` of them). The compiled models, the model XML, every observation,
every reward, every ``done`` flag and every success check must be identical. An
environment that used an object class this library lacks fails here, since every
robosuite object class a building module imports is replaced.

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
STEPS = 100


def _record(task: str, seed: int) -> dict[str, Any]:
    """Build, reset and step ``task``: the compiled model, its XML and each step's result."""
    env = make(task, seed)
    try:
        reset = env.reset()
        actions = np.random.default_rng(seed)
        low, high = env.action_spec
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
    """Same compiled model, XML, observations, rewards and done flags over the random steps."""
    theirs = _record(task, seed=3)
    with our_objects(task) as replaced:
        mine = _record(task, seed=3)

    assert replaced and mine["objects"]
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
