"""Tests of ``mjcf_model.transforms.composition.attached_parts``."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import FramePos, Motor, inlined_attachments
from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.serializers import load
from mjcf_model.transforms.composition.attached_parts import element_references
from tests.conftest import MUJOCO_VERSION
from tests.support.attach_files import attached_body

# -- Which elements outside the tree an ``<attach>`` copies, decided by what they refer to. ----
#
# Each scene attaches the body ``b`` of a small model; MuJoCo compiles the scene with its
# own ``<attach>`` and the expansion must compile to the same arrays.


#: The attached body: one joint and one geom.
BODY = '<worldbody><body name="b"><joint name="j1"/><geom size="1"/></body></worldbody>'


def test_actuator_class_does_not_hide_its_uncopied_joint(tmp_path: Path) -> None:
    """A motor with a class is left out when its joint is not copied, as MuJoCo does."""
    child = (
        '<mujoco><default><default class="c"><motor gear="2"/></default></default><worldbody>'
        '<body name="a"><joint name="j0"/><geom size="1"/>'
        '<body name="b"><joint name="j1"/><geom size="1"/></body></body></worldbody>'
        '<actuator><motor class="c" joint="j0"/><motor class="c" joint="j1"/></actuator></mujoco>'
    )
    reference, expansion = attached_body(tmp_path, child)
    assert reference.nu == 1
    assert model_differences(reference, expansion, ignore=path_fields()) == []


def test_exclude_of_a_copied_body_and_the_world_is_copied(tmp_path: Path) -> None:
    """``<exclude body1="b" body2="world">`` is copied like ``body1="world" body2="b"``."""
    child = f'<mujoco>{BODY}<contact><exclude body1="b" body2="world"/></contact></mujoco>'
    reference, expansion = attached_body(tmp_path, child)
    assert reference.nexclude == 1
    assert model_differences(reference, expansion, ignore=path_fields()) == []


def test_sensor_on_a_replicated_site_is_copied(tmp_path: Path) -> None:
    """A sensor naming a site a ``<replicate>`` in the copied body makes is copied too."""
    child = (
        '<mujoco><worldbody><body name="b"><joint name="j1"/><geom size="1"/>'
        '<replicate count="2" offset="0.1 0 0"><site name="s"/></replicate></body></worldbody>'
        '<sensor><framepos objtype="site" objname="s1"/></sensor></mujoco>'
    )
    reference, expansion = attached_body(tmp_path, child)
    assert reference.nsensor == 1
    assert model_differences(reference, expansion, ignore=path_fields()) == []


def test_reference_to_a_name_with_a_space_is_one_name(tmp_path: Path) -> None:
    """A motor on the joint ``left j1`` is copied with it: the name is not split at the space."""
    child = (
        '<mujoco><worldbody><body name="b"><joint name="left j1"/><geom size="1"/></body>'
        '</worldbody><actuator><motor joint="left j1"/></actuator></mujoco>'
    )
    reference, expansion = attached_body(tmp_path, child)
    assert reference.nu == 1
    assert model_differences(reference, expansion, ignore=path_fields()) == []
    assert list(element_references(Motor(joint="left j1"), "actuator/motor")) == [
        ("joint", "joint", "left j1")
    ]


def test_empty_reference_names_nothing(tmp_path: Path) -> None:
    """A weld whose ``body2`` is written empty (the world, for MuJoCo) is copied with ``b``."""
    child = f'<mujoco>{BODY}<equality><weld body1="b" body2=""/></equality></mujoco>'
    mujoco.MjModel.from_xml_string(child)
    reference, expansion = attached_body(tmp_path, child)
    assert reference.neq == 1
    assert model_differences(reference, expansion, ignore=path_fields()) == []
    assert list(element_references(Motor(joint="j1", site=""), "actuator/motor")) == [
        ("joint", "joint", "j1")
    ]


def test_name_without_its_objtype_is_not_reported() -> None:
    """An ``objname`` without ``objtype`` has no namespace (MuJoCo requires the objtype)."""
    with pytest.raises(ValueError, match="objtype"):
        mujoco.MjModel.from_xml_string(
            f'<mujoco>{BODY}<sensor><framepos objname="b"/></sensor></mujoco>'
        )
    assert list(element_references(FramePos(objname="b"), "sensor/framepos")) == []
    assert list(element_references(FramePos(objtype="body", objname="b"), "sensor/framepos")) == [
        ("objname", "body", "b")
    ]


# -- What an ``<attach>`` expansion refuses, and what it tells the user. -----------------------
#
# MuJoCo is asked first: where it refuses too, the expansion names what is wrong;
# where MuJoCo compiles a scene whose copy is not known, the expansion says what to
# change instead of guessing. MuJoCo 3.9 refuses every ``<attach frame>`` (its
# schema has no ``frame``); the expansion refuses those scenes the same way there.


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


# -- What an ``<attach>`` copies of the attached model's sections and classes. -----------------
#
# MuJoCo compiles each scene with its own ``<attach>``; the expansion must compile to
# the same arrays.


def test_sections_after_a_second_worldbody_are_copied(tmp_path: Path) -> None:
    """A second ``<worldbody>`` is not copied with ``b``; the motor written after it is."""
    child = (
        '<mujoco><worldbody><body name="b"><joint name="j1"/><geom size="1"/></body></worldbody>'
        '<worldbody><body name="other"><geom size="1"/></body></worldbody>'
        '<actuator><motor joint="j1"/></actuator></mujoco>'
    )
    reference, expansion = attached_body(tmp_path, child)
    assert (reference.nbody, reference.nu) == (3, 1)
    assert model_differences(reference, expansion, ignore=path_fields()) == []


def test_own_childclass_wins_over_an_ancestors(tmp_path: Path) -> None:
    """The attached body keeps its own ``childclass``, not the one of the body around it."""
    child = (
        '<mujoco><default><default class="x"><joint damping="1"/></default>'
        '<default class="y"><joint damping="5"/></default></default><worldbody>'
        '<body name="a" childclass="x"><body name="b" childclass="y"><joint name="j1"/>'
        '<geom size="1"/></body></body></worldbody></mujoco>'
    )
    reference, expansion = attached_body(tmp_path, child)
    assert list(reference.dof_damping) == [5.0]
    assert model_differences(reference, expansion, ignore=path_fields()) == []
