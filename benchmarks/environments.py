"""robosuite 1.5.2's 19 manipulation environments, and how to build them with our objects.

One table serves the differential test (``tests/mjcf_model/test_compat.py``: the same
seeded run both ways must give identical models and observations) and the hard-reset
benchmark (``benchmarks/cases_resets.py``: the same resets both ways must cost the same).
An environment is built "with our objects" by binding, in the modules that build its
objects, every name of a robosuite object class (and ``CustomMaterial``) to this
library's twin, or those names and robosuite's ``mjcf_utils`` in every robosuite module
(the global swap by assignment); :func:`our_objects` does that and undoes it.

robosuite 1.5.2 runs only on MuJoCo up to 3.9 (from 3.10 on its own controllers call
``mj_fullM`` with the old arguments): :data:`ROBOSUITE_RUNS` says whether it runs here.
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from types import ModuleType
from typing import Any, NamedTuple

import mujoco

__all__ = [
    "ROBOSUITE_RUNS",
    "SETTINGS",
    "TASKS",
    "Task",
    "make",
    "our_objects",
    "our_twin",
    "robosuite_classes",
]

#: Whether robosuite 1.5.2's environments run on this MuJoCo (3.9 and older).
ROBOSUITE_RUNS = tuple(int(part) for part in mujoco.__version__.split(".")[:2]) < (3, 10)

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

#: The environment settings: no rendering, staged rewards (they check grasps).
SETTINGS = {
    "has_renderer": False,
    "has_offscreen_renderer": False,
    "use_camera_obs": False,
    "reward_shaping": True,
}


def make(task: str, seed: int, robots: str | list[str] | None = None, **settings: Any) -> Any:
    """robosuite's environment ``task`` on ``seed``, with :data:`SETTINGS` and ``settings``.

    ``robots`` replaces the task's own (:attr:`Task.robots`).
    """
    import robosuite

    robots = TASKS[task].robots if robots is None else robots
    return robosuite.make(task, seed=seed, robots=robots, **SETTINGS, **settings)


def robosuite_classes(module: ModuleType) -> list[str]:
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


def our_twin(name: str) -> Any:
    """This library's twin of robosuite's class ``name`` (``None`` if it has none)."""
    from mjcf_model.compat import mjcf_utils as our_utils
    from mjcf_model.compat import objects as ours

    return getattr(our_utils if name == "CustomMaterial" else ours, name, None)


@contextmanager
def our_objects(task: str, *, everywhere: bool = False) -> Iterator[list[str]]:
    """Within the block, ``task``'s modules build this library's objects.

    Yields the names replaced; each module's own bindings come back afterwards.

    Args:
        task: The environment.
        everywhere: Replace the names in every robosuite module imported (after
            ``task``'s), ``robosuite.models.objects`` and the modules defining the
            classes included, and robosuite's ``mjcf_utils`` functions and classes by this
            library's: the global swap a program does by assignment.

    Raises:
        LookupError: This library has no twin of a class the modules use.

    """
    for module_name in TASKS[task].modules:
        importlib.import_module(module_name)
    replacements = _everywhere() if everywhere else _in_modules(TASKS[task].modules)
    saved: list[tuple[ModuleType, str, Any]] = []
    try:
        for module, name, twin in replacements:
            saved.append((module, name, getattr(module, name)))
            setattr(module, name, twin)
        yield [name for _, name, _ in saved]
    finally:
        for module, name, value in reversed(saved):
            setattr(module, name, value)


def _in_modules(names: tuple[str, ...]) -> list[tuple[ModuleType, str, Any]]:
    """Each object class (and ``CustomMaterial``) the modules ``names`` bind, with our twin."""
    found = []
    for module_name in names:
        module = importlib.import_module(module_name)
        for name in robosuite_classes(module):
            twin = our_twin(name)
            if twin is None:
                raise LookupError(f"mjcf_model.compat has no {name}")
            found.append((module, name, twin))
    return found


def _everywhere() -> list[tuple[ModuleType, str, Any]]:
    """:func:`_in_modules` for every robosuite module, and its ``mjcf_utils`` names too."""
    import robosuite.utils.mjcf_utils as their_utils

    from mjcf_model.compat import mjcf_utils as our_utils

    theirs = {
        id(value): name
        for name, value in vars(their_utils).items()
        if callable(value) and getattr(value, "__module__", "") == their_utils.__name__
    }
    found = []
    for module_name, module in sorted(sys.modules.items()):
        if module_name.partition(".")[0] != "robosuite" or module is None:
            continue
        found.extend(_in_modules((module_name,)))
        for name, value in vars(module).items():
            if theirs.get(id(value)) == name and name != "CustomMaterial":
                twin = getattr(our_utils, name, None)
                if twin is None:
                    raise LookupError(f"mjcf_model.compat.mjcf_utils has no {name}")
                found.append((module, name, twin))
    return found
