"""The state of every compat object: an immutable document, its live ElementTree, robosuite's face.

* :class:`RobosuiteCompatible`: ``isinstance`` falls back on ``obj.__class__``, here a cached
  *face* class joining the object's class to its robosuite twin once robosuite's module is in
  ``sys.modules`` (robosuite is never imported).
* :class:`ModelBacked`: an immutable document, named places (paths) in it, and its live
  ElementTree (:class:`mjcf_model.serializers.etree_view.EtreeView`: elements handed out
  stay live, and others' edits stay unless the model changes them).

>>> import xml.etree.ElementTree as ET
>>> from mjcf_model import GenericElement
>>> class Mine(ModelBacked, RobosuiteCompatible):
...     _robosuite_class = ("xml.etree.ElementTree", "TreeBuilder")
>>> doc = Mine()
>>> isinstance(doc, ET.TreeBuilder), type(doc) is Mine
(True, True)
>>> doc._init_document(GenericElement(tag="mujoco", children=[GenericElement(tag="asset")]),
...                    {"asset": (0,)})
>>> live = doc.asset
>>> doc._change("asset", lambda a: with_children(a, [GenericElement(tag="mesh")]))
>>> doc.asset is live, [child.tag for child in live]
(True, ['mesh'])
"""

from __future__ import annotations

import sys
import xml.etree.ElementTree as ET
from collections.abc import Callable
from typing import Any, ClassVar, TypeGuard

from mjcf_model.caching import BoundedCache
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, Element, attribute_text
from mjcf_model.serializers.etree import from_etree
from mjcf_model.serializers.etree_view import EtreeView
from mjcf_model.tree.paths import appended_at, replaced_at, subtree_at
from mjcf_model.tree.queries import find
from mjcf_model.tree.traversal import Path, walk, with_children

__all__ = [
    "ModelBacked",
    "RobosuiteCompatible",
    "as_node",
    "find_path",
    "is_element",
    "section_children",
]


# -- robosuite's isinstance ---------------------------------------------------------

#: The class joining each of ours to its robosuite twin, made once per pair.
_FACES: BoundedCache[tuple[type, type], type] = BoundedCache(256)


def robosuite_face(cls: type) -> type:
    """``cls`` joined to the robosuite twin its MRO names, once imported; else ``cls`` itself.

    The twin is robosuite's own class, also where a program replaced robosuite's names by
    this library's classes (``robosuite.models.objects.BoxObject = BoxObject``):
    :func:`robosuite_original` finds it.
    """
    for klass in cls.__mro__:
        home = vars(klass).get("_robosuite_class")
        if not home:
            continue
        theirs = robosuite_original(home)
        if theirs is None or issubclass(cls, theirs):
            continue
        face = _FACES.get((cls, theirs))
        if face is None:
            namespace = {
                "__module__": cls.__module__,
                "__qualname__": cls.__qualname__,
                "__doc__": cls.__doc__,
            }
            face = _FACES.remember((cls, theirs), type(cls.__name__, (cls, theirs), namespace))
        return face
    return cls


#: robosuite's own class by (module, class name), once found.
_ORIGINALS: dict[tuple[str, str], type] = {}
#: How many modules were imported when robosuite's own class was last looked for in vain.
_SEARCHED: dict[tuple[str, str], int] = {}


def robosuite_original(home: tuple[str, str]) -> type | None:
    """The class of robosuite's own that ``home`` (module, class name) names; ``None``: none yet.

    The module's attribute, unless a program put another class there (this library's twin,
    to swap robosuite's classes everywhere): then the class of that name defined in one of
    robosuite's modules, found among the imported ones, or among the classes alive.

    Examples:
        >>> import xml.etree.ElementTree as ET
        >>> robosuite_original(("xml.etree.ElementTree", "TreeBuilder")) is ET.TreeBuilder
        True
        >>> robosuite_original(("no_such_package.module", "Thing")) is None
        True

    """
    module = sys.modules.get(home[0])
    if module is None:
        return None
    named = getattr(module, home[1], None)
    if _original(named, home):
        _ORIGINALS.setdefault(home, named)
        return named
    found = _ORIGINALS.get(home)
    # Another class under that name (a swap): look for robosuite's own, once per set of
    # imported modules (a class robosuite lacks is not looked for at every isinstance).
    if found is None and named is not None and _SEARCHED.get(home) != len(sys.modules):
        _SEARCHED[home] = len(sys.modules)
        found = _defined_original(home)
        if found is not None:
            _ORIGINALS[home] = found
    return found


def _original(candidate: object, home: tuple[str, str]) -> TypeGuard[type]:
    """Whether ``candidate`` is a class of ``home``'s package, not one of this library's."""
    package = home[0].partition(".")[0]
    return (
        isinstance(candidate, type)
        and candidate.__name__ == home[1]
        and candidate.__module__.partition(".")[0] == package
        and not issubclass(candidate, RobosuiteCompatible)
    )


def _defined_original(home: tuple[str, str]) -> type | None:
    """The class ``home`` names where its package's modules define it, or among all classes."""
    package = home[0].partition(".")[0]
    for name, module in list(sys.modules.items()):
        if name.partition(".")[0] == package:
            candidate = getattr(module, home[1], None)
            if _original(candidate, home) and candidate.__module__ == name:
                return candidate
    pending: list[type] = [object]
    seen: set[type] = set()
    while pending:  # every module binding replaced: the class is still alive, below object
        klass = pending.pop()
        subclasses: list[type] = type.__subclasses__(klass)  # metaclasses' too
        for subclass in subclasses:
            if subclass not in seen:
                seen.add(subclass)
                if _original(subclass, home):
                    return subclass
                pending.append(subclass)
    return None


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


# -- nodes and paths ----------------------------------------------------------------


def is_element(node: object, tag: str | None = None) -> TypeGuard[AnyElement]:
    """Whether ``node`` is an element (not a comment), with the tag ``tag`` if given."""
    return isinstance(node, Element) and tag in (None, node.tag)


def as_node(value: object) -> AnyElement:
    """A node from a node or an ElementTree element (as robosuite subclasses hand them over)."""
    if is_element(value):
        return value
    if isinstance(value, ET.Element):
        node = from_etree(value, typed=False)
        assert is_element(node)
        return node
    raise MjcfValueError(f"expected a node or an ElementTree element, found {value!r}")


def find_path(
    node: AnyElement, tag: str, inside: str | None = None, **attributes: str | None
) -> Path | None:
    """The path of the first ``tag`` element with these attribute texts, parents first.

    With ``inside``, only the children of ``node``'s ``inside`` children are candidates.
    """

    def matches(element: AnyElement) -> bool:
        return element.tag == tag and all(
            attribute_text(element, k) == v for k, v in attributes.items()
        )

    if inside is None:
        return next((path for path, element in walk(node) if matches(element)), None)
    for i, outer in enumerate(node.children):
        if is_element(outer, inside):
            for j, element in enumerate(outer.children):
                if is_element(element) and matches(element):
                    return (i, j)
    return None


def section_children(model: Any, section: str) -> list[AnyElement]:
    """The elements of the section of ``model`` (ours or robosuite's), as nodes."""
    if isinstance(model, ModelBacked) and section in model._paths:
        return list(model._node(section).elements)
    return [as_node(child) for child in getattr(model, section)]


# -- the document -------------------------------------------------------------------


class ModelBacked:
    """An immutable document node, named places in it, and its ElementTree view."""

    _view: EtreeView
    _paths: dict[str, Path]
    #: (place, node) appended by :meth:`_append`, not yet written into the document.
    _appended: tuple[str, AnyElement] | None = None

    def _init_document(self, document: AnyElement, paths: dict[str, Path]) -> None:
        self._view = EtreeView(document)
        self._paths = dict(paths)

    @property
    def mjcf(self) -> AnyElement:
        """The whole state: an immutable ``<mujoco>`` node (the library's own model)."""
        if self._appended is not None:
            self._write_appended()
        return self._view.node

    def _set_mjcf(self, document: AnyElement) -> None:
        if self._appended is not None:
            self._write_appended()
        self._view.update(document)

    def _append(self, parent: str, place: str, node: AnyElement) -> None:
        """Add ``node`` after the children of the element at ``parent``, as the place ``place``."""
        self._paths[place] = (*self._paths[parent], len(self._node(parent).children))
        self._appended = (place, node)

    def _write_appended(self) -> None:
        assert self._appended is not None
        place, node = self._appended
        self._appended = None
        self._view.update(appended_at(self._view.node, self._paths[place][:-1], [node]))

    def _node(self, place: str) -> AnyElement:
        if self._appended is not None and self._appended[0] == place:
            return self._appended[1]
        return subtree_at(self.mjcf, self._paths[place])

    def _replace(self, place: str, new: AnyElement) -> None:
        if self._appended is not None and self._appended[0] == place:
            self._appended = (place, new)
            return
        self._set_mjcf(replaced_at(self.mjcf, self._paths[place], [new]))

    def _change(self, place: str, change: Callable[[AnyElement], AnyElement]) -> None:
        self._replace(place, change(self._node(place)))

    def _live(self, place: str | None = None) -> ET.Element:
        """The live ElementTree element of ``place`` (of the whole document for ``None``)."""
        if self._appended is not None:
            self._write_appended()
        return self._view.at(() if place is None else self._paths[place])

    @property
    def asset(self) -> ET.Element:
        """The ``<asset>`` element (live)."""
        return self._live("asset")

    def merge_assets(self, other: Any) -> None:
        """Append the assets of ``other`` (ours or robosuite's) whose tag and name are new.

        Unlike robosuite, the assets are copied, not shared between both trees.
        """
        mine = self._node("asset")
        added: list[AnyElement] = []
        for item in section_children(other, "asset"):
            name = attribute_text(item, "name")
            if find(mine, item.tag, name=name) is None and all(
                find(a, item.tag, name=name) is None for a in added
            ):
                added.append(item)
        if added:
            self._replace("asset", with_children(mine, [*mine.children, *added]))
