"""Expanding ``<attach>`` across angle units: a degree parent meets a radian sub-model.

MuJoCo reads each model under its own ``<compiler angle>``. Some radians, such as 0.73
and 1.21, are read from no double written in degrees (MuJoCo multiplies degrees by
``pi / 180``), so the expansion must rewrite the degree parent in radians, not the radian child in
degrees; MuJoCo compiling the original scene is the referee. A parent whose sub-models
are all in degrees is left in degrees, as written.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import compiled, inlined_attachments
from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.nodes.compiler import Compiler
from mjcf_model.tree.queries import find
from serializers import load

#: A sub-model in radians whose joint range no double in degrees gives.
RADIAN_CHILD = (
    '<mujoco model="finger"><compiler angle="radian"/><worldbody>'
    '<body name="finger" euler="0 1.2 0.3"><joint name="bend" range="0.73 1.21"/>'
    '<geom size="0.01"/></body></worldbody></mujoco>'
)
#: The same sub-model in degrees.
DEGREE_CHILD = RADIAN_CHILD.replace('<compiler angle="radian"/>', "")

#: A degree parent (``{compiler}`` is its own ``<compiler>``, if any) attaching ``finger``.
PARENT = (
    '<mujoco model="hand">{compiler}<asset><material name="skin"/>'
    '<model name="finger" file="finger.xml"/></asset>'
    '<worldbody><body name="palm" euler="10 20 30"><joint name="wrist" range="-30 45"/>'
    '<geom size="0.05" material="skin"/>'
    '<attach model="finger" body="finger" prefix="f_"/></body>'
    "</worldbody></mujoco>"
)


def _scene(folder: Path, parent_compiler: str, child: str) -> Path:
    (folder / "finger.xml").write_text(child, encoding="utf-8")
    path = folder / "scene.xml"
    path.write_text(PARENT.format(compiler=parent_compiler), encoding="utf-8")
    return path


@pytest.mark.parametrize(
    "parent_compiler",
    ["", '<compiler autolimits="true"/>'],
    ids=["parent_without_compiler", "parent_with_compiler"],
)
def test_radian_child_in_degree_parent_compiles_as_mujocos_attach(
    tmp_path: Path, parent_compiler: str
) -> None:
    """Every compiled array of the expansion equals MuJoCo's, the child's radians exact."""
    path = _scene(tmp_path, parent_compiler, RADIAN_CHILD)
    reference = mujoco.MjModel.from_xml_path(str(path))
    expanded = inlined_attachments(load(path))
    assert model_differences(reference, compiled(expanded), ignore=path_fields()) == []
    assert compiled(expanded).jnt_range[reference.joint("f_bend").id].tolist() == [0.73, 1.21]


def test_compiler_added_to_a_parent_without_one_comes_first(tmp_path: Path) -> None:
    """The parent rewritten in radians gets ``<compiler angle="radian">`` as its first section."""
    expanded = inlined_attachments(load(_scene(tmp_path, "", RADIAN_CHILD)))
    first = expanded.children[0]
    assert isinstance(first, Compiler)
    assert first.angle == "radian"


def test_degree_children_leave_the_parent_in_degrees_as_written(tmp_path: Path) -> None:
    """With no sub-model in radians, the parent keeps its degrees and its numbers as written."""
    path = _scene(tmp_path, "", DEGREE_CHILD)
    expanded = inlined_attachments(load(path))
    assert find(expanded, "compiler") is None
    assert find(expanded, "body", name="palm", euler=(10, 20, 30)) is not None
    assert find(expanded, "joint", name="wrist", range=(-30, 45)) is not None
    reference = mujoco.MjModel.from_xml_path(str(path))
    assert model_differences(reference, compiled(expanded), ignore=path_fields()) == []
