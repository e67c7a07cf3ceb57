"""How the object classes pass robosuite's ``isinstance`` checks without importing robosuite.

``isinstance`` falls back on ``obj.__class__``, here a cached *face* class derived from the
object's class and its robosuite twin once robosuite's module is in ``sys.modules``.

>>> import xml.etree.ElementTree as ET
>>> class Mine(RobosuiteCompatible):
...     _robosuite_class = ("xml.etree.ElementTree", "TreeBuilder")
>>> mine = Mine()
>>> isinstance(mine, ET.TreeBuilder), type(mine) is Mine, mine.__class__ is robosuite_face(Mine)
(True, True, True)
"""

from __future__ import annotations

import sys
from typing import Any, ClassVar

__all__ = ["RobosuiteCompatible"]

_FACES: dict[tuple[type, type], type] = {}


def robosuite_face(cls: type) -> type:
    """``cls`` joined to the robosuite twin its MRO names, once imported; else ``cls`` itself."""
    for klass in cls.__mro__:
        home = vars(klass).get("_robosuite_class")
        if not home:
            continue
        module = sys.modules.get(home[0])
        theirs = getattr(module, home[1], None) if module is not None else None
        if not isinstance(theirs, type):
            continue
        key = (cls, theirs)
        face = _FACES.get(key)
        if face is None:
            namespace = {
                "__module__": cls.__module__,
                "__qualname__": cls.__qualname__,
                "__doc__": cls.__doc__,
            }
            face = _FACES[key] = type(cls.__name__, (cls, theirs), namespace)
        return face
    return cls


def _restore(cls: type[RobosuiteCompatible]) -> RobosuiteCompatible:
    """Unpickling: a bare instance of ``cls`` whose state pickle then fills in."""
    return object.__new__(cls)


class RobosuiteCompatible:
    """Base of the object classes: instances pass ``isinstance`` against robosuite's twins."""

    #: robosuite's twin of this class: (module, class name).
    _robosuite_class: ClassVar[tuple[str, str] | None] = None

    @property
    def __class__(self) -> type:
        """The class ``isinstance`` falls back on: :func:`robosuite_face`."""
        return robosuite_face(type(self))

    @__class__.setter
    def __class__(self, value: type) -> None:
        object.__dict__["__class__"].__set__(self, value)

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle by ``type(self)`` (pickle checks ``__class__`` against the type otherwise)."""
        return (_restore, (type(self),), self.__dict__)
