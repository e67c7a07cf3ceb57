"""Models that name files (a robot with a mesh), written to folders for the file tests."""

from __future__ import annotations

import functools
from pathlib import Path

import mujoco

from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.files.provenance import file_references
from mjcf_model.serializers import load
from tests.conftest import compiling_corpus


def obj_mesh(points: int) -> str:
    """An OBJ mesh with ``points`` vertices: which file MuJoCo read shows in ``mesh_vertnum``."""
    vertices = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    vertices += [(0.2 + 0.01 * i, 0.2, 0.2) for i in range(points - 4)]
    lines = [f"v {x} {y} {z}" for x, y, z in vertices]
    return "\n".join([*lines, "f 1 2 3", "f 1 2 4", "f 1 3 4", "f 2 3 4", ""])


def write_tree(root: Path, files: dict[str, str]) -> Path:
    """Write ``files`` (relative path: text) under ``root``; return ``root``."""
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def _same(a: mujoco.MjModel, b: mujoco.MjModel) -> list[str]:
    return model_differences(a, b, ignore=path_fields())


ROBOT = """<mujoco model="robot">
  <compiler meshdir="assets" texturedir="textures" angle="radian"/>
  <asset>
    <mesh name="link" file="link.obj"/>
    <texture name="grid" type="2d" builtin="checker" width="8" height="8"/>
  </asset>
  <worldbody>
    <body name="base"><joint name="j" range="0 1"/><geom type="mesh" mesh="link"/></body>
  </worldbody>
</mujoco>
"""


@functools.cache
def with_files() -> list[Path]:
    """Corpus models that name files: the ones relocation and export can get wrong.

    Read on first use (the ``robot`` fixture imports this module and needs none of them).
    """
    return [p for p in compiling_corpus() if any(file_references(load(p, inline_includes=True)))]
