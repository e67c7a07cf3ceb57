"""The ``<custom>`` section: user data stored in the model.

>>> Numeric(name="gains", data=[1, 2]).data
(1.0, 2.0)
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import integer, numbers, text
from mjcf_model.values import Floats

__all__ = ["Custom", "Numeric", "Text", "Tuple", "TupleElement"]


@node
class Custom(TypedElement):
    """Section of custom numeric, text and tuple data."""

    schema_keys: ClassVar[tuple[str, ...]] = ("custom",)


@node
class Numeric(TypedElement):
    """A named array of numbers."""

    schema_keys: ClassVar[tuple[str, ...]] = ("custom/numeric",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Size parameters; their number and meaning depend on ``type``.
    size: int | None = integer()
    #: Data values.
    data: Floats | None = numbers()


@node
class Text(TypedElement):
    """A named string."""

    schema_keys: ClassVar[tuple[str, ...]] = ("custom/text",)
    #: Name, unique within its namespace.
    name: str | None = text()
    #: Data values.
    data: str | None = text()


@node
class Tuple(TypedElement):
    """A named list of object references."""

    schema_keys: ClassVar[tuple[str, ...]] = ("custom/tuple",)
    #: Name, unique within its namespace.
    name: str | None = text()


@node
class TupleElement(TypedElement):
    """One object reference of a tuple."""

    schema_keys: ClassVar[tuple[str, ...]] = ("custom/tuple/element",)
    #: Name of the referenced object.
    objname: str | None = text()
    #: Type of the referenced object.
    objtype: str | None = text()
    #: Real-valued parameter of the tuple element.
    prm: Floats | None = numbers()
