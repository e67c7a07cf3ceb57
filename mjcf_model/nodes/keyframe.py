"""The ``<keyframe>`` section: stored simulation states.

>>> Key(name="home", qpos=[0, 0.5]).qpos
(0.0, 0.5)
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.values import Floats, float_key, to_float, to_floats, to_str

__all__ = ["Key", "Keyframe"]


@attrs.frozen(kw_only=True, repr=False)
class Keyframe(TypedElement):
    """Section of keyframes."""

    tag: ClassVar[str] = "keyframe"

    @property
    def keys(self) -> tuple[Key, ...]:
        """The keyframes."""
        return self._of_type(Key)


@attrs.frozen(kw_only=True, repr=False)
class Key(TypedElement):
    """A keyframe: a stored simulation state."""

    tag: ClassVar[str] = "key"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Actuator activations.
    act: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Controls.
    ctrl: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Mocap body positions.
    mpos: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Mocap body orientations.
    mquat: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Plastic state.
    plastic: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Joint positions.
    qpos: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Joint velocities.
    qvel: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Simulation time.
    time: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
