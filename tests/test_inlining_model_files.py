"""Expanding ``<attach>``: how sub-model files are read, and what is left of the scene.

A sub-model's ``<include>`` is read as MuJoCo reads it, the scene's asset section
keeps its comments and its other assets, an ``<attach>`` with an empty prefix
copies the names as they are, a self-attach needs no asset ``<model>``, and a model
without ``<attach>`` comes back as it is. MuJoCo compiling the original is the referee
(MuJoCo 3.9, which requires ``model``, compiles the self-attach's copy written out).
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import compiled, inlined_attachments
from mjcf_model.bridge.compare import compiled_names, model_differences, path_fields
from mjcf_model.nodes.base import Comment, get_attribute
from mjcf_model.nodes.body import Worldbody
from mjcf_model.nodes.keyframe import Keyframe
from mjcf_model.tree.traversal import walk
from serializers import load, loads
from tests.conftest import MUJOCO_VERSION
from tests.support.attach_files import written


def _differences(path: Path) -> list[str]:
    """The fields in which the expansion of ``path`` differs from MuJoCo's compilation of it."""
    reference = mujoco.MjModel.from_xml_path(str(path))
    expanded = inlined_attachments(load(path))
    return model_differences(reference, compiled(expanded), ignore=path_fields())


def test_sub_model_includes_are_read(tmp_path: Path) -> None:
    """A sub-model whose bodies are in an included file attaches them, as MuJoCo does."""
    path = written(
        tmp_path,
        {
            "scene.xml": '<mujoco><asset><model file="cup.xml"/></asset><worldbody>'
            '<body name="table"><attach model="cup" body="cup" prefix="a_"/></body>'
            "</worldbody></mujoco>",
            "cup.xml": '<mujoco model="cup"><include file="cup_body.xml"/></mujoco>',
            "cup_body.xml": '<mujoco><worldbody><body name="cup" pos="0 0 0.1">'
            '<joint name="tilt"/><geom size="0.1"/></body></worldbody></mujoco>',
        },
    )
    assert _differences(path) == []
    assert compiled_names(mujoco.MjModel.from_xml_path(str(path)))["body"][-1] == "a_cup"


def test_asset_comments_and_other_assets_stay(tmp_path: Path) -> None:
    """Removing the asset ``<model>`` keeps the asset section's comment and material."""
    path = written(
        tmp_path,
        {
            "scene.xml": '<mujoco><asset><!-- the parts --><model file="cup.xml"/>'
            '<material name="wood" rgba="0.5 0.3 0.1 1"/></asset><worldbody>'
            '<body name="table"><geom size="0.5" material="wood"/>'
            '<attach model="cup" body="cup" prefix="a_"/></body></worldbody></mujoco>',
            "cup.xml": '<mujoco model="cup"><worldbody><body name="cup">'
            '<geom size="0.1"/></body></worldbody></mujoco>',
        },
    )
    assert _differences(path) == []
    asset = inlined_attachments(load(path)).asset
    assert asset is not None
    assert [type(n) for n in asset.children][:1] == [Comment]
    assert [get_attribute(e, "name") for e in asset.elements] == ["wood"]


def test_empty_prefix_keeps_the_names(tmp_path: Path) -> None:
    """``prefix=""`` attaches the sub-model's names unchanged, as MuJoCo does."""
    path = written(
        tmp_path,
        {
            "scene.xml": '<mujoco><asset><model file="cup.xml"/></asset><worldbody>'
            '<body name="table"><attach model="cup" body="cup" prefix=""/></body>'
            "</worldbody></mujoco>",
            "cup.xml": '<mujoco model="cup"><worldbody><body name="cup">'
            '<joint name="tilt"/><geom name="rim" size="0.1"/></body></worldbody></mujoco>',
        },
    )
    assert _differences(path) == []
    names = compiled_names(compiled(inlined_attachments(load(path))))
    assert [names["body"], names["jnt"], names["geom"]] == [
        ["world", "table", "cup"],
        ["tilt"],
        ["rim"],
    ]


def test_self_attach_without_model_assets_is_expanded() -> None:
    """An ``<attach body>`` copying from the model itself is expanded without any asset model."""
    text = (
        '<mujoco><worldbody><body name="a" pos="1 0 0"><joint name="j"/><geom size="0.1"/></body>'
        '<body name="b" pos="0 1 0"><attach body="a" prefix="c_"/></body></worldbody></mujoco>'
    )
    expanded = inlined_attachments(loads(text))
    assert not any(e.tag == "attach" for _, e in walk(expanded))
    if MUJOCO_VERSION >= (4, 0):
        reference = mujoco.MjModel.from_xml_string(text)
    else:
        with pytest.raises(ValueError, match="required attribute missing: 'model'"):
            mujoco.MjModel.from_xml_string(text)
        reference = mujoco.MjModel.from_xml_string(
            text.replace(
                '<attach body="a" prefix="c_"/>',
                '<body name="c_a" pos="1 0 0"><joint name="c_j"/><geom size="0.1"/></body>',
            )
        )
    assert model_differences(reference, compiled(expanded), ignore=path_fields()) == []


def test_model_without_attach_comes_back_as_it_is() -> None:
    """With no ``<attach>`` or asset ``<model>``, the model is returned as it is, in its order."""
    model = loads(
        '<mujoco><keyframe><key qpos="0.5"/></keyframe><worldbody><body name="a">'
        '<joint/><geom size="0.1"/></body></worldbody></mujoco>'
    )
    assert inlined_attachments(model) == model
    assert [type(s) for s in inlined_attachments(model).children] == [Keyframe, Worldbody]
