"""Which elements outside the tree an ``<attach>`` copies, decided by what they refer to.

Each scene attaches the body ``b`` of a small model; MuJoCo compiles the scene with its
own ``<attach>`` and the expansion must compile to the same arrays.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import FramePos, Motor
from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.transforms.composition.attached_parts import element_references
from tests.support.attach_files import attached_body

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
