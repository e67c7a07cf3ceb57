"""A child's file paths are rewritten to name its files from the parent's folder, relatively.

The scene keeps the parent's folder and ``<compiler>``, so a mesh the child
reads from its own ``meshdir`` is written as the path from the parent's
folder to that file: relative, so the scene's folder tree can be moved as a
whole (:func:`mjcf_model.files.provenance.relocated`). MuJoCo compiling the
child from its own file is the referee for what the mesh holds.
"""

from __future__ import annotations

import os

import mujoco

from mjcf_model import attach, compiled
from mjcf_model.nodes.base import get_attribute
from mjcf_model.tree.queries import find_all
from serializers import load, loads
from tests.conftest import FIXTURES

SCENE_DIR = FIXTURES / "attachments" / "nested"
GRIPPER = SCENE_DIR / "arm" / "gripper" / "gripper.xml"


def test_a_childs_mesh_is_named_relative_to_the_parents_folder() -> None:
    """The child's mesh file is written as the relative path from the parent's folder."""
    parent = loads("<mujoco/>", base_dir=SCENE_DIR)
    scene = attach(parent, load(GRIPPER), prefix="g_")
    (mesh,) = find_all(scene, "mesh")
    mesh_file = GRIPPER.parent / "meshes" / "pad.obj"
    assert get_attribute(mesh, "file") == os.path.relpath(mesh_file, SCENE_DIR)
    alone = mujoco.MjModel.from_xml_path(str(GRIPPER))
    assert compiled(scene).nmeshvert == alone.nmeshvert
