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
from collections.abc import Callable
from types import ModuleType
from typing import Any, NamedTuple

import mujoco
import numpy as np
import pytest

from mjcf_model.bridge.compare import model_differences
from mjcf_model.compat import mjcf_utils as our_utils
from mjcf_model.compat import objects as ours
from tests.conftest import MUJOCO_VERSION
from tests.support.compat_objects import text_of

pytestmark = pytest.mark.skipif(
    MUJOCO_VERSION >= (3, 10),
    reason=f"robosuite 1.5.2 does not run on MuJoCo {mujoco.__version__} (only up to 3.9); "
    "tests/run_installed.py runs these in its 'oldest' environment",
)

#: robosuite's package of manipulation environments.
_MANIPULATION = "robosuite.environments.manipulation"


class Task(NamedTuple):
    """How a robosuite environment is built, and where its objects are."""

    #: The modules whose imported object classes make the environment's objects.
    modules: tuple[str, ...]
    #: The objects the environment made, read off the environment.
    objects: Callable[[Any], list[Any]] = lambda env: list(env.model.mujoco_objects)
    #: The robots (two-arm tasks get two Pandas).
    robots: str | list[str] = "Panda"


def _two_arm(module: str, objects: Callable[[Any], list[Any]] | None = None) -> Task:
    modules = (f"{_MANIPULATION}.{module}",)
    if objects is None:
        return Task(modules, robots=["Panda", "Panda"])
    return Task(modules, objects, robots=["Panda", "Panda"])


def _one_arm(module: str) -> Task:
    return Task((f"{_MANIPULATION}.{module}",))


#: Every manipulation environment of robosuite 1.5.2.
TASKS: dict[str, Task] = {
    "Door": _one_arm("door"),
    "Lift": _one_arm("lift"),
    "Stack": _one_arm("stack"),
    **{
        task: _one_arm("nut_assembly")
        for task in ("NutAssembly", "NutAssemblyRound", "NutAssemblySingle", "NutAssemblySquare")
    },
    **{
        task: _one_arm("pick_place")
        for task in (
            "PickPlace",
            "PickPlaceBread",
            "PickPlaceCan",
            "PickPlaceCereal",
            "PickPlaceMilk",
            "PickPlaceSingle",
        )
    },
    "ToolHang": _one_arm("tool_hang"),
    "Wipe": Task(
        (f"{_MANIPULATION}.wipe", "robosuite.models.arenas.wipe_arena"),
        lambda env: list(env.model.mujoco_arena.markers),
    ),
    "TwoArmLift": _two_arm("two_arm_lift"),
    "TwoArmHandover": _two_arm("two_arm_handover"),
    "TwoArmPegInHole": _two_arm("two_arm_peg_in_hole", lambda env: [env.hole, env.peg]),
    "TwoArmTransport": Task(
        (f"{_MANIPULATION}.two_arm_transport", "robosuite.models.objects.group.transport"),
        robots=["Panda", "Panda"],
    ),
}
#: How many random actions each run takes.
STEPS = 100
#: The environment settings: no rendering, staged rewards (they check grasps).
SETTINGS = {
    "has_renderer": False,
    "has_offscreen_renderer": False,
    "use_camera_obs": False,
    "reward_shaping": True,
}


def _robosuite_classes(module: ModuleType) -> list[str]:
    """The names ``module`` binds to robosuite's object classes and ``CustomMaterial``."""
    from robosuite.models.objects import MujocoObject
    from robosuite.utils.mjcf_utils import CustomMaterial

    return sorted(
        name
        for name, value in vars(module).items()
        if isinstance(value, type)
        and value.__module__.startswith("robosuite.")
        and (issubclass(value, MujocoObject) or value is CustomMaterial)
    )


def _ours(name: str) -> Any:
    """The twin of robosuite's class ``name`` here (a missing one fails the test)."""
    twin = getattr(our_utils if name == "CustomMaterial" else ours, name, None)
    assert twin is not None, f"mjcf_model.compat has no {name}"
    return twin


def _record(task: str, seed: int) -> dict[str, Any]:
    """Build, reset and step ``task``: the compiled model, its XML and each step's result."""
    import robosuite

    env = robosuite.make(task, seed=seed, robots=TASKS[task].robots, **SETTINGS)
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
def test_task_runs_identically_with_this_librarys_objects(
    task: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Same compiled model, XML, observations, rewards and done flags over the random steps."""
    import importlib

    theirs = _record(task, seed=3)
    replaced = []
    for module_name in TASKS[task].modules:
        module = importlib.import_module(module_name)
        for name in _robosuite_classes(module):
            monkeypatch.setattr(module, name, _ours(name))
            replaced.append(name)
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
