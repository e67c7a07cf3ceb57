"""The compat objects inside robosuite's own pipeline: worlds, tasks, grippers and arenas.

robosuite's environments with these objects: test_compat_robosuite_environments.py.
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np
import pytest
import robosuite.models.objects as rs
from robosuite.models.arenas import TableArena
from robosuite.models.grippers import PandaGripper
from robosuite.models.robots import Panda
from robosuite.models.tasks import ManipulationTask
from robosuite.models.world import MujocoWorldBase
from robosuite.utils.mjcf_utils import GRIPPER_COLLISION_COLOR, CustomMaterial, xml_path_completion

from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_tree,
    assert_same_value,
    assert_view_matches_model,
    text_of,
)


class OurPandaGripper(ours.MujocoXMLModel):
    """robosuite's ``PandaGripper`` naming and colours, on this library's MujocoXMLModel."""

    def __init__(self, idn: Any = 0) -> None:
        super().__init__(xml_path_completion("grippers/panda_gripper.xml"), idn=idn)

    naming_prefix = property(lambda self: f"gripper{self.idn}_")
    contact_geom_rgba = property(lambda self: GRIPPER_COLLISION_COLOR)
    # robosuite's raw names for the Panda gripper (plain data in its properties)
    _important_sites = PandaGripper._important_sites
    _important_geoms = PandaGripper._important_geoms
    _important_sensors = PandaGripper._important_sensors


OurPandaGripper.__name__ = "PandaGripper"


@pytest.mark.parametrize("idn", [0, 1, "right"])
def test_xml_model_matches_panda_gripper(idn: Any) -> None:
    """MujocoXMLModel reads, names, prefixes and recolours PandaGripper as robosuite (golden 13)."""
    theirs, mine = PandaGripper(idn=idn), OurPandaGripper(idn=idn)
    assert_same_tree(mine.root, theirs.root)
    assert [c.tag for c in mine.root] == [
        *["asset", "actuator", "worldbody", "sensor", "tendon", "equality", "contact"]
    ]
    names = ["name", "naming_prefix", "root_body", "bodies", "joints", "actuators", "sites"]
    names += ["sensors", "contact_geoms", "visual_geoms", "bottom_offset", "base_offset"]
    names += ["important_sites", "important_geoms", "important_sensors"]
    for name in names:
        assert_same_value(getattr(mine, name), getattr(theirs, name), name)
    assert_view_matches_model(mine)


def test_world_merges_assets_by_name() -> None:
    """Robosuite's world merges this library's assets by tag and name (golden check 12)."""
    worlds = []
    for make in (rs.CanObject, ours.CanObject):
        world = MujocoWorldBase()
        for name in ("c1", "c2", "c1"):
            world.merge_assets(make(name))
        worlds.append(world)
    assert len(worlds[1].asset) == 6
    assert_same_tree(worlds[1].asset, worlds[0].asset)
    for make_can, make_box in ((rs.CanObject, rs.BoxObject), (ours.CanObject, ours.BoxObject)):
        world = MujocoWorldBase()
        for obj in (make_can("can"), make_box("cube", size=[0.02, 0.02, 0.02])):
            world.merge_assets(obj)
            world.worldbody.append(obj.get_obj())
        model = world.get_model(mode="mujoco")
        names = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_GEOM, i) for i in range(model.ngeom)]
        assert names == ["can_g0", "can_g0_visual", "cube_g0", "cube_g0_vis"]


def test_object_merge_assets_matches() -> None:
    """An object's own merge_assets keeps the first of each tag and name, as robosuite's."""
    theirs, mine = rs.CanObject("a"), ours.CanObject("a")
    for other in (rs.CanObject("b"), ours.CanObject("b"), rs.CanObject("a")):
        theirs.merge_assets(other)
        mine.merge_assets(other)
    assert_same_tree(mine.asset, theirs.asset)
    assert_view_matches_model(mine)


def _scene(module: Any) -> list[Any]:
    wood = CustomMaterial(
        "WoodRed",
        "redwood",
        "redwood_mat",
        {"type": "cube"},
        {"texrepeat": "1 1", "specular": "0.4"},
    )
    objects = [
        module.CanObject("can"),
        module.MilkObject("milk"),
        module.BoxObject("cube", size=[0.02, 0.02, 0.02], material=wood),
        module.CylinderObject("cyl", size=[0.02, 0.04]),
        module.SquareNutObject("nut"),
    ]
    for index, obj in enumerate(objects):  # placed as robosuite's environments place them
        obj.get_obj().set("pos", f"{-0.2 + 0.1 * index} 0.05 0.9")
    return objects


def test_manipulation_task_scene_compiles_and_steps() -> None:
    """Table, Panda and five objects in robosuite's ManipulationTask: robosuite's XML, 100 steps."""
    runs = []
    for module in (rs, ours):
        robot = Panda()
        robot.add_gripper(PandaGripper())
        task = ManipulationTask(
            mujoco_arena=TableArena(), mujoco_robots=[robot], mujoco_objects=_scene(module)
        )
        model = task.get_model(mode="mujoco")
        data = mujoco.MjData(model)
        for _ in range(100):
            mujoco.mj_step(model, data)
        runs.append((task, model, data))
    (their_task, _, their_data), (my_task, my_model, my_data) = runs
    assert text_of(my_task.root) == text_of(their_task.root)
    assert my_model.nbody > 5 and np.all(np.isfinite(my_data.qpos))
    np.testing.assert_array_equal(my_data.qpos, their_data.qpos)
    can_body = mujoco.mj_name2id(my_model, mujoco.mjtObj.mjOBJ_BODY, "can_main")
    assert my_data.xpos[can_body][2] < 0.9  # it fell towards the table
