"""Which node class stands for each schema key of the namespace table.

>>> CLASS_BY_KEY["body/geom"].__name__, CLASS_BY_KEY["tendon/spatial/geom"].__name__
('Geom', 'TendonGeom')
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from mjcf_model import nodes  # noqa: F401  (its section modules declare every node class)
from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import declared_classes

__all__ = ["CLASS_BY_KEY"]


def _class_by_key() -> dict[str, type[TypedElement]]:
    """Each schema key a declared class names in its ``schema_keys``, mapped to that class."""
    found: dict[str, type[TypedElement]] = {}
    for cls in declared_classes():
        for key in cls.__node_info__.keys:  # type: ignore[attr-defined]
            if key in found:
                raise TypeError(f"{key!r} is claimed by {found[key].__name__} and {cls.__name__}")
            found[key] = cls
    return found


#: The typed class of each schema key; keys not listed become generic elements.
#: Derived from the ``schema_keys`` each class declares.
CLASS_BY_KEY: Mapping[str, type[TypedElement]] = MappingProxyType(_class_by_key())
