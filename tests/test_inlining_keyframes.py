"""Expanding ``<attach>``: the keys MuJoCo adds for attached models that have keys.

MuJoCo adds one key per key of each attached model, after the parent's own keys,
with the attached key's ``time``. The expansion writes them as plain ``<key>``
elements; MuJoCo compiling the original scene is the referee. Where no attached model
has keys, nothing is added and the scene need not compile.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import compiled, inlined_attachments
from mjcf_model.bridge.compare import compiled_names, model_differences, path_fields
from mjcf_model.errors import MjcfCompileError
from mjcf_model.nodes.base import get_attribute
from mjcf_model.nodes.keyframe import Keyframe
from mjcf_model.tree.queries import find_all
from mjcf_model.tree.traversal import walk
from serializers import load
from tests.support.attach_files import written

#: A sub-model with one joint and one key, at time 0.5.
KEYED = (
    '<mujoco model="keyed"><worldbody><body name="arm"><joint name="swing"/>'
    '<geom size="0.1"/></body></worldbody>'
    '<keyframe><key name="raised" qpos="0.3" time="0.5"/></keyframe></mujoco>'
)
#: A sub-model with one joint and no keys.
PLAIN = (
    '<mujoco model="plain"><worldbody><body name="leg"><joint name="kick"/>'
    '<geom size="0.1"/></body></worldbody></mujoco>'
)
#: A scene attaching the keyed model, then the plain one; it has an unnamed and a named key.
SCENE = (
    '<mujoco model="scene"><asset><model file="keyed.xml"/><model file="plain.xml"/></asset>'
    '<worldbody><body name="base"><joint name="turn"/><geom size="0.2"/></body>'
    '<attach model="keyed" body="arm" prefix="k_"/>'
    '<attach model="plain" body="leg" prefix="p_"/></worldbody>'
    '<keyframe><key qpos="0.1 0 0"/><key name="home" qpos="0.2 0 0"/></keyframe></mujoco>'
)


@pytest.fixture
def scene(tmp_path: Path) -> Path:
    """The scene and its two sub-models, written to a folder."""
    return written(tmp_path, {"scene.xml": SCENE, "keyed.xml": KEYED, "plain.xml": PLAIN})


def test_attached_keys_compile_as_mujocos(scene: Path) -> None:
    """Every key array (and every other array) of the expansion equals MuJoCo's."""
    reference = mujoco.MjModel.from_xml_path(str(scene))
    got = compiled(inlined_attachments(load(scene)))
    assert model_differences(reference, got, ignore=path_fields()) == []
    assert compiled_names(got)["key"] == ["", "home", "k_raised"]
    assert got.key_time.tolist() == reference.key_time.tolist() == [0.0, 0.0, 0.5]


def test_attached_keys_join_the_one_keyframe_section(scene: Path) -> None:
    """The added key goes after the parent's own keys, in its only ``<keyframe>``."""
    expanded = inlined_attachments(load(scene))
    sections = [s for s in expanded.children if isinstance(s, Keyframe)]
    assert len(sections) == 1
    names = [get_attribute(k, "name") for k in sections[0].elements]
    assert names == [None, "home", "k_raised"]


def test_added_key_writes_only_the_arrays_the_model_has(scene: Path) -> None:
    """Without actuators or mocap bodies, the added key has no ``ctrl``, ``act``, ``mpos``..."""
    expanded = inlined_attachments(load(scene))
    added = [e for _, e in walk(expanded) if get_attribute(e, "name") == "k_raised"]
    assert len(added) == 1
    empty = ("ctrl", "act", "mpos", "mquat", "plastic")
    assert [name for name in empty if get_attribute(added[0], name) is not None] == []
    assert get_attribute(added[0], "time") == 0.5


def test_keyless_attachments_expand_in_a_model_mujoco_refuses(tmp_path: Path) -> None:
    """No attached model has keys: the scene is expanded without being compiled.

    MuJoCo refuses the scene (its own key is too long) and, in the same words, the expansion.
    """
    scene = (
        '<mujoco><asset><model file="plain.xml"/></asset><worldbody>'
        '<attach model="plain" body="leg" prefix="p_"/></worldbody>'
        '<keyframe><key qpos="1 2 3"/></keyframe></mujoco>'
    )
    path = written(tmp_path, {"scene.xml": scene, "plain.xml": PLAIN})
    with pytest.raises(ValueError, match="invalid qpos size"):
        mujoco.MjModel.from_xml_path(str(path))
    expanded = inlined_attachments(load(path))
    assert [get_attribute(b, "name") for b in find_all(expanded, "body")] == ["p_leg"]
    with pytest.raises(MjcfCompileError, match="invalid qpos size"):
        compiled(expanded)
