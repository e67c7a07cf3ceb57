"""The model a lint run looks at: its tree, MuJoCo's compile of it, and where each row is.

The rules ask MuJoCo, not the text: the compiled arrays say what the model is after
its default classes, ``autolimits`` and angle units; :mod:`mjcf_model.bridge.numbering`
says which element each compiled row came from, so that a finding names the user's
file, line and element path.
"""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING

from mjcf_model.bridge.compiling import compiled
from mjcf_model.bridge.numbering import Numbering, numbering
from mjcf_model.nodes.base import AnyElement
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers.locations import element_at, read_from
from mjcf_model.tools.lint.findings import RULES, Finding

if TYPE_CHECKING:
    import mujoco

__all__ = ["Subject"]

#: A place in the model: an index path, or a compiled object as its kind and row.
Place = tuple[int, ...] | tuple[str, int]


class Subject:
    """One model being linted."""

    def __init__(self, model: Mujoco, physics: mujoco.MjModel | None = None) -> None:
        #: The model as loaded.
        self.model = model
        #: MuJoCo's compile of it.
        self.physics = compiled(model) if physics is None else physics

    @functools.cached_property
    def rows(self) -> Numbering:
        """Which compiled row each element is."""
        return numbering(self.model)

    def element(self, place: Place) -> tuple[AnyElement, tuple[int, ...]] | None:
        """The element at ``place`` and its index path; ``None`` where there is none.

        A compiled row made by ``<replicate>`` or ``<attach>`` has no element of its own.
        """
        if place and isinstance(place[0], str):
            kind, row = place
            path = self.rows.path_of(str(kind), int(row))
        else:
            path = tuple(int(index) for index in place)
        if path is None:
            return None
        found = element_at(self.model, path)
        return (found[0], path) if found is not None else None

    def name(self, kind: str, row: int) -> str:
        """How a message names compiled object ``row`` of ``kind``: its name or its row.

        Examples:
            >>> from mjcf_model import loads
            >>> subject = Subject(loads("<mujoco><worldbody><geom name='g' size='1'/>"
            ...     "<geom size='1'/></worldbody></mujoco>"))
            >>> subject.name("geom", 0), subject.name("geom", 1)
            ("'g'", 'geom 1')

        """
        import mujoco

        kind_id = getattr(mujoco.mjtObj, f"mjOBJ_{kind.upper()}")
        name = mujoco.mj_id2name(self.physics, kind_id, row)
        return repr(name) if name else f"{kind} {row}"

    def finding(self, code: str, place: Place | None, message: str) -> Finding:
        """The finding of rule ``code`` at ``place`` (``None``: the model as a whole)."""
        found = self.element(place) if place is not None else None
        element = found[0] if found is not None else self.model
        located = element_at(self.model, found[1]) if found is not None else None
        file, line = read_from(element)
        return Finding(
            file=file,
            line=line,
            path=located[1] if located is not None else "/mujoco",
            rule=code,
            severity=RULES[code].severity,
            message=message,
        )
