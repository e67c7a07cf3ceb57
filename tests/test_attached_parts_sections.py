"""What an ``<attach>`` copies of the attached model's sections and classes.

MuJoCo compiles each scene with its own ``<attach>``; the expansion must compile to
the same arrays.
"""

from __future__ import annotations

from pathlib import Path

import mujoco

from mjcf_model import compiled
from mjcf_model.tools.compare import model_differences, path_fields
from serializers import load


def _attached(tmp_path: Path, child: str) -> tuple[mujoco.MjModel, mujoco.MjModel]:
    """MuJoCo's compilation of a scene attaching ``b`` of ``child``, and of its expansion."""
    (tmp_path / "child.xml").write_text(child, encoding="utf-8")
    scene = tmp_path / "scene.xml"
    scene.write_text(
        '<mujoco><asset><model name="c" file="child.xml"/></asset><worldbody>'
        '<body name="holder"><attach model="c" body="b" prefix="p_"/></body></worldbody></mujoco>',
        encoding="utf-8",
    )
    return mujoco.MjModel.from_xml_path(str(scene)), compiled(load(scene, inline_attachments=True))


def test_sections_after_a_second_worldbody_are_copied(tmp_path: Path) -> None:
    """A second ``<worldbody>`` is not copied with ``b``; the motor written after it is."""
    child = (
        '<mujoco><worldbody><body name="b"><joint name="j1"/><geom size="1"/></body></worldbody>'
        '<worldbody><body name="other"><geom size="1"/></body></worldbody>'
        '<actuator><motor joint="j1"/></actuator></mujoco>'
    )
    reference, expansion = _attached(tmp_path, child)
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
    reference, expansion = _attached(tmp_path, child)
    assert list(reference.dof_damping) == [5.0]
    assert model_differences(reference, expansion, ignore=path_fields()) == []
