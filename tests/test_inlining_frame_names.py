"""Expanding ``<attach>`` in a model whose frames have names like ``attach_0``.

The user's frames, whatever their names, keep their place, their pose and their
children: MuJoCo compiling the original scene is the referee.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import compiled, inlined_attachments
from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.nodes.base import get_attribute
from mjcf_model.tree.traversal import walk
from serializers import load

#: A sub-model with one body.
CUP = (
    '<mujoco model="cup"><worldbody><body name="cup"><geom size="0.1"/></body></worldbody></mujoco>'
)


def _scene(frame_names: list[str]) -> str:
    """A scene with posed frames of these names, each holding a body, then an ``<attach>``."""
    frames = "".join(
        f'<frame name="{name}" pos="{i + 1} 0 0"><body name="in_{i}"><geom size="0.1"/></body>'
        "</frame>"
        for i, name in enumerate(frame_names)
    )
    return (
        '<mujoco><asset><model file="cup.xml"/></asset><worldbody>'
        f'{frames}<body name="table" pos="0 0 1"><attach model="cup" body="cup" prefix="a_"/>'
        "</body></worldbody></mujoco>"
    )


@pytest.mark.parametrize(
    "frame_names",
    [["attach_0"], ["attach_0", "attach_1"], ["attach_None"]],
    ids=["attach_0", "attach_0_and_1", "attach_None"],
)
def test_frames_named_like_attach_markers_are_kept(tmp_path: Path, frame_names: list[str]) -> None:
    """The expansion compiles as MuJoCo's and keeps every frame of the user, in order."""
    (tmp_path / "cup.xml").write_text(CUP, encoding="utf-8")
    path = tmp_path / "scene.xml"
    path.write_text(_scene(frame_names), encoding="utf-8")
    reference = mujoco.MjModel.from_xml_path(str(path))
    expanded = inlined_attachments(load(path))
    assert model_differences(reference, compiled(expanded), ignore=path_fields()) == []
    frames = [get_attribute(e, "name") for _, e in walk(expanded) if e.tag == "frame"]
    assert frames == frame_names
