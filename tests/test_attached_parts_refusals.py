"""What an ``<attach>`` expansion refuses, and what it tells the user.

MuJoCo is asked first: where it refuses too, the expansion names what is wrong;
where MuJoCo compiles a scene whose copy is not known, the expansion says what to
change instead of guessing. MuJoCo 3.9 refuses every ``<attach frame>`` (its
schema has no ``frame``); the expansion refuses those scenes the same way there.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import inlined_attachments
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from serializers import load
from tests.conftest import MUJOCO_VERSION

#: What MuJoCo 3.9 says of any ``<attach frame>`` (its schema has no ``frame``, added in 4.0).
NO_FRAME_BEFORE_4 = "unrecognized attribute: 'frame'"


def _mujoco_refuses(scene: Path, says: str) -> None:
    """MuJoCo refuses ``scene``, saying ``says`` (MuJoCo 3.9: that it has no ``frame``)."""
    with pytest.raises(ValueError, match=says if MUJOCO_VERSION >= (4, 0) else NO_FRAME_BEFORE_4):
        mujoco.MjModel.from_xml_path(str(scene))


def _scene(tmp_path: Path, child: str, attach: str) -> Path:
    """A scene whose body ``holder`` holds ``attach`` of the model ``c`` (text ``child``)."""
    (tmp_path / "child.xml").write_text(child, encoding="utf-8")
    scene = tmp_path / "scene.xml"
    scene.write_text(
        '<mujoco><asset><model name="c" file="child.xml"/></asset><worldbody>'
        f'<body name="holder">{attach}</body></worldbody></mujoco>',
        encoding="utf-8",
    )
    return scene


def test_body_inside_a_replicate_is_refused(tmp_path: Path) -> None:
    """MuJoCo finds no body ``b`` among the replicated copies; the expansion says why."""
    child = (
        '<mujoco><worldbody><replicate count="2" offset="1 0 0">'
        '<body name="b"><geom size="1"/></body></replicate></worldbody></mujoco>'
    )
    scene = _scene(tmp_path, child, '<attach model="c" body="b" prefix="p_"/>')
    with pytest.raises(ValueError, match="could not find body 'b'"):
        mujoco.MjModel.from_xml_path(str(scene))
    with pytest.raises(
        MjcfValueError,
        match=r"cannot expand <attach body='b'>: it is inside a <replicate>, "
        "whose copies have other names",
    ):
        inlined_attachments(load(scene))


def test_frame_inside_a_replicate_is_refused(tmp_path: Path) -> None:
    """MuJoCo finds no frame ``f`` among the replicated copies; the expansion says why."""
    child = (
        '<mujoco><worldbody><replicate count="2" offset="1 0 0"><frame name="f">'
        '<body name="b"><geom size="1"/></body></frame></replicate></worldbody></mujoco>'
    )
    scene = _scene(tmp_path, child, '<attach model="c" frame="f" prefix="p_"/>')
    _mujoco_refuses(scene, "could not find frame 'f'")
    with pytest.raises(MjcfValueError, match=r"<attach frame='f'>: it is inside a <replicate>"):
        inlined_attachments(load(scene))


def test_unknown_frame_lists_the_frames(tmp_path: Path) -> None:
    """Attaching a frame the model lacks names it as a frame and lists the frames there are."""
    child = (
        '<mujoco><worldbody><frame name="f"><body name="b"><geom size="1"/></body></frame>'
        "</worldbody></mujoco>"
    )
    scene = _scene(tmp_path, child, '<attach model="c" frame="g" prefix="p_"/>')
    _mujoco_refuses(scene, "could not find frame 'g'")
    with pytest.raises(MjcfLookupError, match=r"no frame named 'g'; its frames are \['f'\]"):
        inlined_attachments(load(scene))


def test_attach_of_a_body_and_a_frame_is_refused(tmp_path: Path) -> None:
    """An ``<attach>`` naming both a body and a frame is refused, as by MuJoCo's schema."""
    child = (
        '<mujoco><worldbody><frame name="f"><body name="b"><geom size="1"/></body></frame>'
        "</worldbody></mujoco>"
    )
    scene = _scene(tmp_path, child, '<attach model="c" body="b" frame="f" prefix="p_"/>')
    _mujoco_refuses(scene, "at most one of 'body', 'frame'")
    with pytest.raises(MjcfValueError, match=r"^an <attach> names a body or a frame, not both$"):
        inlined_attachments(load(scene))


def test_skin_bone_on_the_world_is_refused_naming_the_bone(tmp_path: Path) -> None:
    """A skin bone on the world body is refused, naming ``<bone body="world">``.

    MuJoCo compiles the scene; whether it copies such a skin is not measured.
    """
    child = (
        '<mujoco><worldbody><body name="b"><geom size="1"/></body></worldbody><deformable>'
        '<skin name="s" vertex="0 0 0 1 0 0 0 1 0" face="0 1 2">'
        '<bone body="world" bindpos="0 0 0" bindquat="1 0 0 0" vertid="0 1 2" '
        'vertweight="1 1 1"/>'
        '<bone body="b" bindpos="0 0 0" bindquat="1 0 0 0" vertid="0 1 2" vertweight="1 1 1"/>'
        "</skin></deformable></mujoco>"
    )
    scene = _scene(tmp_path, child, '<attach model="c" body="b" prefix="p_"/>')
    mujoco.MjModel.from_xml_path(str(scene))
    with pytest.raises(
        MjcfValueError,
        match=r'whose model has <bone body="world">: .*refer to a body instead',
    ):
        inlined_attachments(load(scene))
