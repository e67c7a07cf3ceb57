"""How the object classes pass robosuite's ``isinstance`` checks without importing robosuite.

robosuite's pipeline checks ``isinstance(obj, robosuite.models.objects.MujocoObject)``
(``ManipulationTask.merge_objects``, the placement samplers) and
``isinstance(obj, robosuite.models.base.MujocoModel)`` (contact checks in the
environments). robosuite's classes are plain classes, not ABCs: they have no
``register`` and their metaclass is ``type``, so no ``__instancecheck__`` can
be added to them without changing robosuite.

``isinstance(obj, C)`` for a plain class ``C`` first tests ``type(obj)``, then
falls back to ``obj.__class__``, an attribute a class may define (this is how
``unittest.mock`` objects pass checks). :class:`RobosuiteCompatible` defines
``__class__`` as a property returning a *face*: a class derived from the
object's own class and from its robosuite counterpart (``CanObject`` and
robosuite's ``CanObject``), made once and cached. The face is looked up at
the moment of the check, only among modules already imported
(``sys.modules``): the library never imports robosuite, and an object made
before robosuite was imported passes the check all the same. When robosuite is
not imported, ``obj.__class__`` is ``type(obj)``.

No robosuite code ever runs on these objects: the face is never instantiated
and ``type(obj)`` is the library's class, whose methods answer every call.
Pickling uses ``type(obj)`` through :meth:`RobosuiteCompatible.__reduce__`,
because pickle refuses an object whose ``__class__`` differs from its type.

>>> class Plain(RobosuiteCompatible):
...     pass
>>> Plain().__class__ is Plain
True
"""

from __future__ import annotations

import sys
from typing import Any, ClassVar

__all__ = ["RobosuiteCompatible", "robosuite_face"]

_FACES: dict[tuple[type, type], type] = {}


def robosuite_face(cls: type) -> type:
    """The class ``isinstance`` sees for instances of ``cls``: ``cls`` joined to robosuite's twin.

    The twin is the nearest class in ``cls.__mro__`` that names one in
    ``_robosuite_class`` and whose robosuite module is already imported; with
    none, ``cls`` itself.

    Example:
        >>> class Mine(RobosuiteCompatible):
        ...     _robosuite_class = ("xml.etree.ElementTree", "TreeBuilder")
        >>> face = robosuite_face(Mine)
        >>> import xml.etree.ElementTree as ET
        >>> issubclass(face, Mine), issubclass(face, ET.TreeBuilder), robosuite_face(Mine) is face
        (True, True, True)

    """
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
    """Base of the object classes: instances pass ``isinstance`` against robosuite's twins.

    A subclass names its twin as ``_robosuite_class = (module, class name)``.
    """

    #: robosuite's twin of this class: (module, class name).
    _robosuite_class: ClassVar[tuple[str, str] | None] = None

    @property
    def __class__(self) -> type:
        """The class ``isinstance`` falls back on (see the module docstring)."""
        return robosuite_face(type(self))

    @__class__.setter
    def __class__(self, value: type) -> None:
        object.__dict__["__class__"].__set__(self, value)

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle by ``type(self)`` (pickle checks ``__class__`` against the type otherwise)."""
        return (_restore, (type(self),), self.__dict__)
