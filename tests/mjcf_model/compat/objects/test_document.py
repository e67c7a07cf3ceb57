"""Tests of ``mjcf_model.compat.objects.document``."""

from __future__ import annotations

import copy
import pickle
import subprocess
import sys
import types
import xml.etree.ElementTree as ET
from typing import Any

import mujoco
import pytest
import robosuite.models.base as rs_base
import robosuite.models.objects as rs
from robosuite.models.world import MujocoWorldBase

from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_tree,
    assert_view_matches_model,
)

# -- XML objects of ``mjcf_model.compat.objects`` against robosuite 1.5.2's, case by case. -----


# -- the live ElementTree -------------------------------------------------------------


def test_handed_out_elements_stay_live() -> None:
    """get_obj() is one element for the object's life; changes reach it; foreign edits stay."""
    milk = ours.MilkObject("milk")
    body = milk.get_obj()
    world = ET.Element("worldbody")
    world.append(body)
    body.set("quat", "0 0 0.707 0.707")  # as robosuite's environments do
    milk.set_pos([1, 2, 3])
    milk.set_scale(2)
    assert milk.get_obj() is body and world[0] is body
    assert body.get("pos") == "1 2 3" and body.get("quat") == "0 0 0.707 0.707"
    assert body[0].get("pos") == "0.0 0.0 0.0"
    assert body in list(milk.root.iter("body"))


def test_objects_pickle_and_copy() -> None:
    """Objects pickle and deep-copy to equal, independent objects."""
    can = ours.CanObject("can")
    for clone in (pickle.loads(pickle.dumps(can)), copy.deepcopy(can)):
        assert type(clone) is ours.CanObject
        assert clone.get_xml() == can.get_xml()
        clone.set_pos([1, 1, 1])
        assert can.get_obj().get("pos") is None
        assert_view_matches_model(clone)


def test_isinstance_does_not_depend_on_which_was_imported_first() -> None:
    """Objects made before robosuite is imported pass ``isinstance`` against it once it is.

    This module imports robosuite first; a fresh process makes the objects first.
    """
    code = (
        "from mjcf_model.compat import objects as ours\n"
        "import sys\n"
        "assert not any(m.startswith('robosuite') for m in sys.modules)\n"
        "made = [ours.CanObject('c'), ours.BoxObject('b'), ours.Bin('n')]\n"
        "import robosuite.models.base as rs_base, robosuite.models.objects as rs\n"
        "twins = [rs.CanObject, rs.BoxObject, rs.CompositeObject]\n"
        "print([isinstance(o, t) and isinstance(o, rs_base.MujocoModel) "
        "for o, t in zip(made, twins)])\n"
    )
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert found.stdout.strip() == "[True, True, True]"


def test_isinstance_of_robosuite_twins() -> None:
    """Every class passes isinstance against its robosuite twin and robosuite's bases."""
    cases: list[tuple[Any, type]] = [
        (ours.CanObject("c"), rs.CanObject),
        (ours.CanObject("c"), rs.MujocoXMLObject),
        (ours.CanObject("c"), rs_base.MujocoXML),
        (ours.DoorObject("d"), rs.DoorObject),
        (ours.BoxObject("b"), rs.BoxObject),
        (ours.BoxObject("b"), rs.PrimitiveObject),
        (ours.BallObject("b"), rs.MujocoGeneratedObject),
        (ours.CylinderObject("b"), rs.CylinderObject),
        (ours.CapsuleObject("b"), rs.CapsuleObject),
        *[(getattr(ours, name)("r"), getattr(rs, name)) for name in RECIPES],
        (ours.Bin("b"), rs.CompositeObject),
        (ours.RatchetingWrenchObject("w"), rs.CompositeBodyObject),
    ]
    for obj, twin in cases:
        assert isinstance(obj, twin) and isinstance(obj, rs.MujocoObject)
        assert isinstance(obj, rs_base.MujocoModel) and isinstance(obj, ours.MujocoObject)
    assert not isinstance(ours.BoxObject("b"), rs.CanObject)


def test_robosuite_is_never_imported_and_may_come_later() -> None:
    """The library does not import robosuite; objects made before it is imported pass its checks."""
    script = (
        "import sys\n"
        "from mjcf_model.compat.objects import CanObject, BoxObject\n"
        "can, box = CanObject('can'), BoxObject('box')\n"
        "assert 'robosuite' not in sys.modules, 'imported robosuite'\n"
        "assert can.__class__ is CanObject\n"
        "import robosuite.models.objects as rs\n"
        "assert isinstance(can, rs.MujocoObject) and isinstance(box, rs.BoxObject)\n"
        "print('ok')\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, check=False
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "ok"


#: robosuite's composite recipes (made of geoms, or of objects' bodies).
RECIPES = (
    "Bin", "Lid", "ConeObject", "HollowCylinderObject", "HammerObject", "HookFrame",
    "StandWithMount", "PotWithHandlesObject", "RatchetingWrenchObject",
)  # fmt: skip


@pytest.mark.parametrize(
    "cls", ["CanObject", "BoxObject", "CompositeObject", "MujocoXMLModel", *RECIPES]
)
def test_no_robosuite_method_is_inherited(cls: str) -> None:
    """Every public attribute of robosuite's twin is defined by this library's class."""
    mine = getattr(ours, cls)
    twin = getattr(rs, cls, None) or getattr(rs_base, cls)
    defined = {name for klass in mine.__mro__ for name in vars(klass)}
    public = {n for n in dir(twin) if not n.startswith("__") and not n.startswith("_get_")}
    # robosuite's in-place helpers: ours read their input and leave it as it was.
    in_place = {"_replace_defaults_inline", "_get_default_classes", "_remove_joints"}
    assert public - defined <= in_place


# -- The compat objects inside robosuite's own pipeline: worlds, tasks, grippers and arenas. ---
#
# robosuite's environments with these objects: tests/mjcf_model/test_compat.py.


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


def test_robosuites_own_class_is_found_after_a_swap_and_looked_for_once_in_vain(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A module name bound to another class: the original is found where it is defined.

    A class the package lacks is looked for once per set of imported modules.
    """
    from mjcf_model.compat.objects import document

    swapped = types.ModuleType("xml.swapped_home")
    swapped.TreeBuilder = type("TreeBuilder", (document.RobosuiteCompatible,), {})
    swapped.Missing = type("Missing", (document.RobosuiteCompatible,), {})
    monkeypatch.setitem(sys.modules, "xml.swapped_home", swapped)
    assert document.robosuite_original(("xml.swapped_home", "TreeBuilder")) is ET.TreeBuilder
    searches: list[tuple[str, str]] = []
    real = document._defined_original
    monkeypatch.setattr(
        document, "_defined_original", lambda home: searches.append(home) or real(home)
    )
    for _ in range(3):
        assert document.robosuite_original(("xml.swapped_home", "Missing")) is None
    assert searches == [("xml.swapped_home", "Missing")]
    assert document.robosuite_original(("xml.swapped_home", "Absent")) is None
    assert searches == [("xml.swapped_home", "Missing")]  # no such name: nothing to look for
