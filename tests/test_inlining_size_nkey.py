"""Expanding ``<attach>`` in a model with ``<size nkey>`` and its own keys.

MuJoCo 4.0 compiles ``<size nkey="2"/>`` with one ``<key name="own">`` to the keys
``own`` and one blank key. The expansion once set the ``<keyframe>`` aside but not
``nkey``: the attach wrote two blank keys and the own key came third (and with a keyed
sub-model the expansion refused the scene, naming a wrong key order). MuJoCo 3.9
refuses the self-attach (it requires ``model``), and keeps all ``nkey`` keys before
an attached model's: ``own``, two blank keys, then the sub-model's.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import compiled, inlined_attachments
from mjcf_model.bridge.compare import compiled_names, model_differences, path_fields
from serializers import load, loads
from tests.conftest import MUJOCO_VERSION


def test_size_nkey_and_own_key_survive_a_self_attach() -> None:
    """The expansion compiles to MuJoCo's keys: ``own`` first, then one blank key."""
    text = (
        '<mujoco><size nkey="2"/><worldbody><body name="a"><joint/><geom size="1"/></body>'
        '<body name="m"><attach body="a" prefix="c_"/></body></worldbody>'
        '<keyframe><key name="own" qpos="0.5 0"/></keyframe></mujoco>'
    )
    got = compiled(inlined_attachments(loads(text)))
    if MUJOCO_VERSION < (4, 0):
        with pytest.raises(ValueError, match="required attribute missing: 'model'"):
            mujoco.MjModel.from_xml_string(text)
        text = text.replace(
            '<attach body="a" prefix="c_"/>', '<body name="c_a"><joint/><geom size="1"/></body>'
        )
    reference = mujoco.MjModel.from_xml_string(text)
    assert compiled_names(reference)["key"] == ["own", ""]
    assert model_differences(reference, got, ignore=path_fields()) == []


def test_size_nkey_and_own_key_with_a_keyed_sub_model(tmp_path: Path) -> None:
    """With a keyed sub-model, the expansion compiles to MuJoCo's keys instead of refusing."""
    (tmp_path / "keyed.xml").write_text(
        '<mujoco model="keyed"><worldbody><body name="arm"><joint/><geom size="0.1"/></body>'
        '</worldbody><keyframe><key name="raised" qpos="0.3"/></keyframe></mujoco>',
        encoding="utf-8",
    )
    path = tmp_path / "scene.xml"
    path.write_text(
        '<mujoco><size nkey="3"/><asset><model file="keyed.xml"/></asset><worldbody>'
        '<body name="p"><joint/><geom size="0.1"/></body>'
        '<attach model="keyed" body="arm" prefix="x_"/></worldbody>'
        '<keyframe><key name="own" qpos="0.1 0"/></keyframe></mujoco>',
        encoding="utf-8",
    )
    reference = mujoco.MjModel.from_xml_path(str(path))
    keys = ["own", "", "x_raised"] if MUJOCO_VERSION >= (4, 0) else ["own", "", "", "x_raised"]
    assert compiled_names(reference)["key"] == keys
    got = compiled(inlined_attachments(load(path)))
    assert model_differences(reference, got, ignore=path_fields()) == []
