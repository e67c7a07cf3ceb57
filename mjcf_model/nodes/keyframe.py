"""The ``<keyframe>`` section: stored simulation states.

>>> Key(name="home", qpos=[0, 0.5]).qpos
(0.0, 0.5)
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import number, numbers, text
from mjcf_model.values import Floats

__all__ = ["Key", "Keyframe"]


@node
class Keyframe(TypedElement):
    """Section of keyframes."""

    schema_keys: ClassVar[tuple[str, ...]] = ("keyframe",)

    @property
    def keys(self) -> tuple[Key, ...]:
        """The keyframes."""
        return self._of_type(Key)


@node
class Key(TypedElement):
    """A keyframe: a stored simulation state."""

    schema_keys: ClassVar[tuple[str, ...]] = ("keyframe/key",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Actuator activations.
    act: Floats | None = numbers()
    #: Controls.
    ctrl: Floats | None = numbers()
    #: Mocap body positions.
    mpos: Floats | None = numbers()
    #: Mocap body orientations.
    mquat: Floats | None = numbers()
    #: Plastic state.
    plastic: Floats | None = numbers()
    #: Joint positions.
    qpos: Floats | None = numbers()
    #: Joint velocities.
    qvel: Floats | None = numbers()
    #: Simulation time.
    time: float | None = number()
