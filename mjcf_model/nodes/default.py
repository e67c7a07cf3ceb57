"""Default classes (``<default>``).

Inside a default class, elements use the same classes as in the model
(``Geom``, ``Joint``, ``General``...), except ``<tendon>`` and ``<equality>``,
which are :class:`~mjcf_model.nodes.tendon.DefaultTendon` and
:class:`~mjcf_model.nodes.equality.DefaultEquality`.

>>> from mjcf_model.nodes.geom import Geom
>>> Default(dclass="arm", children=[Geom(rgba=(1, 0, 0, 1))]).dclass
'arm'
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import text

__all__ = ["Default"]


@node
class Default(TypedElement):
    """A default class: attribute values its members take unless they set their own."""

    schema_keys: ClassVar[tuple[str, ...]] = ("default",)
    #: Default class whose values this element takes (XML ``class``).
    dclass: str | None = text(xml="class")

    @property
    def defaults(self) -> tuple[Default, ...]:
        """The nested default classes."""
        return self._of_type(Default)
