"""Numeric compiler settings are compared as the numbers MuJoCo reads, not as their text.

``settotalmass="3"`` and ``settotalmass="3.0"`` (or ``boundmass="0.5"`` and
``"5e-1"``) are one setting to MuJoCo: a child and parent that write them so
share their conventions, and the child is taken as it is.
"""

from __future__ import annotations

from mjcf_model import compiled
from mjcf_model.bridge.compare import model_differences
from mjcf_model.transforms.composition.conventions import in_conventions
from mjcf_model.tree.traversal import with_children
from serializers import loads


def test_numbers_written_differently_are_the_same_setting() -> None:
    """Equal numbers in other text change nothing but the removed <compiler>."""
    child = loads(
        '<mujoco><compiler settotalmass="3" boundmass="0.5" inertiagrouprange="0 5"/>'
        '<worldbody><body name="b"><joint/><geom size="1"/>'
        '<body name="c" pos="0 0 1"><joint/><geom size=".2"/></body></body></worldbody></mujoco>'
    )
    parent = loads(
        '<mujoco><compiler settotalmass="3.0" boundmass="5e-1" inertiagrouprange="0  5"/></mujoco>'
    )
    converted = in_conventions(child, parent)
    assert converted.worldbody is child.worldbody
    found = compiled(with_children(converted, [*parent.children, *converted.children]))
    assert model_differences(compiled(child), found) == []
