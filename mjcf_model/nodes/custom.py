"""The ``<custom>`` section: user data stored in the model.

>>> Numeric(name="gains", data=[1, 2]).data
(1.0, 2.0)
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.values import Floats, to_floats, to_int, to_str

__all__ = ["Custom", "Numeric", "Text", "Tuple", "TupleElement"]


@attrs.frozen(kw_only=True, repr=False)
class Custom(TypedElement):
    """Section of custom numeric, text and tuple data."""

    tag: ClassVar[str] = "custom"


@attrs.frozen(kw_only=True, repr=False)
class Numeric(TypedElement):
    """A named array of numbers."""

    tag: ClassVar[str] = "numeric"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Size parameters; their number and meaning depend on ``type``.
    size: int | None = attrs.field(default=None, converter=to_int)
    #: Data values.
    data: Floats | None = attrs.field(default=None, converter=to_floats)


@attrs.frozen(kw_only=True, repr=False)
class Text(TypedElement):
    """A named string."""

    tag: ClassVar[str] = "text"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)
    #: Data values.
    data: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Tuple(TypedElement):
    """A named list of object references."""

    tag: ClassVar[str] = "tuple"
    #: Name, unique within its namespace.
    name: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class TupleElement(TypedElement):
    """One object reference of a tuple."""

    tag: ClassVar[str] = "element"
    #: Name of the referenced object.
    objname: str | None = attrs.field(default=None, converter=to_str)
    #: Type of the referenced object.
    objtype: str | None = attrs.field(default=None, converter=to_str)
    #: Real-valued parameter of the tuple element.
    prm: Floats | None = attrs.field(default=None, converter=to_floats)
