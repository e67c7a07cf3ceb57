"""What a node needs of the record of how it was written in its file.

An element read from a file carries a layout: where it stands in the file's text and
what it was read with, so that writing it back changes nothing. The serializers make
and read layouts (:class:`mjcf_model.serializers.layout.Layout`); a node only keeps
one, and asks it three things through this protocol: to let go of the children the
element no longer holds, how to pickle the element, and where the element stands (for
its ``repr``).

>>> from mjcf_model import loads
>>> geom = loads('<mujoco><worldbody><geom size="1"/></worldbody></mujoco>').worldbody.geoms[0]
>>> isinstance(geom.layout, FileLayout), geom.layout.where()
(True, ('<string>', 1))
"""

from __future__ import annotations

from typing import Any, Protocol, runtime_checkable

__all__ = ["FileLayout"]


@runtime_checkable
class FileLayout(Protocol):
    """How an element was written in its file (never part of the node's value)."""

    def without_old_children(self, children: tuple[Any, ...]) -> FileLayout:
        """The layout for an element that now holds ``children``: it keeps none it replaced."""
        ...

    def reduced(self, element: Any) -> tuple[Any, ...] | None:
        """How to pickle ``element`` (read with this layout) small, or ``None``: field by field."""
        ...

    def where(self) -> tuple[str | None, int]:
        """The file the element was read from (``None`` when unknown) and its line."""
        ...
