"""The state of every compat object: an immutable document, named places in it, its ElementTree.

>>> from mjcf_model import GenericElement
>>> class Doc(ModelBacked):
...     pass
>>> doc = Doc()
>>> doc._init_document(GenericElement(tag="mujoco", children=[GenericElement(tag="asset")]),
...                    {"asset": (0,)})
>>> live = doc.asset
>>> doc._change("asset", lambda a: with_children(a, [GenericElement(tag="mesh")]))
>>> doc.asset is live, [child.tag for child in live]
(True, ['mesh'])
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable
from typing import Any

from mjcf_model.compat.objects.etree_view import EtreeView
from mjcf_model.compat.objects.habits import attribute
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, GenericElement, TypedElement
from mjcf_model.tree.queries import find
from mjcf_model.tree.traversal import Path, appended_at, replaced_at, subtree_at, with_children
from serializers import from_etree

__all__ = ["ModelBacked", "as_node"]


def as_node(value: object) -> AnyElement:
    """A node from a node or an ElementTree element (as robosuite subclasses hand them over)."""
    if isinstance(value, (TypedElement, GenericElement)):
        return value
    if isinstance(value, ET.Element):
        node = from_etree(value, typed=False)
        assert isinstance(node, (TypedElement, GenericElement))
        return node
    raise MjcfValueError(f"expected a node or an ElementTree element, found {value!r}")


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
        if isinstance(other, ModelBacked):
            theirs = list(other._node("asset").elements)
        else:
            theirs = [as_node(child) for child in other.asset]
        mine = self._node("asset")
        added: list[AnyElement] = []
        for item in theirs:
            name = attribute(item, "name")
            if find(mine, item.tag, name=name) is None and all(
                find(a, item.tag, name=name) is None for a in added
            ):
                added.append(item)
        if added:
            self._replace("asset", with_children(mine, [*mine.children, *added]))
