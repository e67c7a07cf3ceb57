"""What an ``<attach>`` copies of the attached model's sections and classes.

MuJoCo compiles each scene with its own ``<attach>``; the expansion must compile to
the same arrays.
"""

from __future__ import annotations

from pathlib import Path

from mjcf_model.bridge.compare import model_differences, path_fields
from tests.support.attach_files import attached_body


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
