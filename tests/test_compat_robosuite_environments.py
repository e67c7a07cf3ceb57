"""robosuite 1.5.2's own environments with this library's objects, unpatched.

Each environment is built twice on the same seed, once as robosuite ships it and
once with every object class it creates (and ``CustomMaterial``) taken from
``mjcf_model.compat``; both are reset and stepped with the same 200 seeded random
actions. The compiled models, the model XML, every observation, every reward and
every ``done`` flag must be identical.

robosuite 1.5.2 itself runs only on MuJoCo up to 3.9 (from 3.10 on its own
controllers call ``mj_fullM`` with the old arguments and read ``MjData.qM``), so
these tests run in the ``oldest`` environment of ``tests/run_installed.py``
(MuJoCo 3.9.0) and say why they do not run on a newer MuJoCo.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from types import ModuleType
from typing import Any

import mujoco
import numpy as np
import pytest

from mjcf_model.compat import mjcf_utils as our_utils
from mjcf_model.compat import objects as ours
from mjcf_model.tools.compare import model_differences
from tests.conftest import MUJOCO_VERSION
from tests.test_compat_objects_support import text_of

pytestmark = pytest.mark.skipif(
    MUJOCO_VERSION >= (3, 10),
    reason=f"robosuite 1.5.2 does not run on MuJoCo {mujoco.__version__} (only up to 3.9); "
    "tests/run_installed.py runs these in its 'oldest' environment",
)

#: Each task, the robosuite module that builds it, and the names it creates objects by.
TASKS = {
    "Lift": ("lift", ("BoxObject", "CustomMaterial")),
    "Stack": ("stack", ("BoxObject", "CustomMaterial")),
    "PickPlace": (
        "pick_place",
        (
            "BreadObject",
            "BreadVisualObject",
            "CanObject",
            "CanVisualObject",
            "CerealObject",
            "CerealVisualObject",
            "MilkObject",
            "MilkVisualObject",
        ),
    ),
    "NutAssembly": ("nut_assembly", ("RoundNutObject", "SquareNutObject")),
}
#: How many random actions each run takes.
STEPS = 200
#: The environment settings: no rendering, staged rewards (they check grasps).
SETTINGS = {
    "robots": "Panda",
    "has_renderer": False,
    "has_offscreen_renderer": False,
    "use_camera_obs": False,
    "reward_shaping": True,
}


def _ours(name: str) -> Any:
    return getattr(our_utils if name == "CustomMaterial" else ours, name)


def _record(task: str, seed: int) -> dict[str, Any]:
    """Build, reset and step ``task``: the compiled model, its XML and each step's result."""
    import robosuite

    env = robosuite.make(task, seed=seed, **SETTINGS)
    try:
        reset = env.reset()
        actions = np.random.default_rng(seed)
        low, high = env.action_spec
        steps = [env.step(actions.uniform(low, high)) for _ in range(STEPS)]
        return {
            "objects": list(env.model.mujoco_objects),
            "model": env.sim.model._model,
            "xml": env.model.get_xml(),
            "reset": reset,
            "steps": steps,
        }
    finally:
        env.close()


def _assert_same_observations(mine: dict[str, Any], theirs: dict[str, Any], label: str) -> None:
    assert mine.keys() == theirs.keys(), label
    for key in theirs:
        np.testing.assert_array_equal(mine[key], theirs[key], err_msg=f"{label}: {key}")


def _module(name: str) -> ModuleType:
    import importlib

    return importlib.import_module(f"robosuite.environments.manipulation.{name}")


@pytest.mark.parametrize("task", list(TASKS))
def test_task_runs_identically_with_this_librarys_objects(
    task: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Same compiled model, XML, observations, rewards and done flags over 200 random steps."""
    module_name, names = TASKS[task]
    module = _module(module_name)
    theirs = _record(task, seed=3)
    for name in names:
        monkeypatch.setattr(module, name, _ours(name))
    mine = _record(task, seed=3)

    created = [obj for obj in mine["objects"] if type(obj).__module__.startswith("mjcf_model")]
    assert created and len(created) == len(mine["objects"])
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
    assert len({step[1] for step in theirs["steps"]}) > 1  # the rewards really vary
