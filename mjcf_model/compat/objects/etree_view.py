"""The ElementTree face of an immutable model: built on first read, then patched in place.

An update touches only what differs from the old model (subtrees shared by identity are
skipped): elements handed out stay live, and others' edits stay unless the model changes them.

>>> from mjcf_model import GenericElement
>>> body = GenericElement(tag="body", attributes={"name": "b"})
>>> view = EtreeView(body)
>>> handed_out = view.element
>>> view.update(GenericElement(tag="body", attributes={"name": "b", "pos": "0 0 1"}))
>>> view.element is handed_out, ET.tostring(handed_out, encoding="unicode")
(True, '<body name="b" pos="0 0 1" />')
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from mjcf_model.compat.mjcf_utils.etree_sync import sync_element
from mjcf_model.nodes.base import AnyElement, Comment, GenericElement, Node, TypedElement
from mjcf_model.tree.traversal import Path
from serializers import to_etree

__all__ = ["EtreeView"]


class EtreeView:
    """One ElementTree kept in step with a replaced model (``element``: one already showing it)."""

    def __init__(self, node: AnyElement, element: ET.Element | None = None) -> None:
        self._node = node
        #: The elements built for each element's children, in model order.
        self._kids: dict[ET.Element, list[ET.Element]] = {}
        #: The root element, built on first use (a model changed often is converted once).
        self._element = None if element is None else self._record(node, element)

    @property
    def node(self) -> AnyElement:
        """The model the ElementTree currently shows."""
        return self._node

    @property
    def element(self) -> ET.Element:
        """The root ElementTree element (the same object for the view's whole life)."""
        if self._element is None:
            self._element = self._build(self._node)
        return self._element

    def at(self, path: Path) -> ET.Element:
        """The element built for the model element at ``path``."""
        element = self.element
        for index in path:
            element = self._kids[element][index]
        return element

    def update(self, node: AnyElement) -> None:
        """Make the ElementTree show ``node``, editing the existing elements in place."""
        if node is not self._node:
            if self._element is not None:
                self._patch(self._node, node, self._element)
            self._node = node

    # -- building -----------------------------------------------------------------

    def _build(self, node: Node) -> ET.Element:
        """The element of ``node`` and its subtree, its children recorded."""
        element = to_etree(node)
        if isinstance(node, (TypedElement, GenericElement)):
            self._record(node, element)
        return element

    def _record(self, node: AnyElement, element: ET.Element) -> ET.Element:
        kids = list(element)
        self._kids[element] = kids
        for child, kid in zip(node.children, kids, strict=True):
            if isinstance(child, (TypedElement, GenericElement)):
                self._record(child, kid)
        return element

    def _forget(self, element: ET.Element) -> None:
        for kid in self._kids.pop(element, []):
            self._forget(kid)

    # -- patching -----------------------------------------------------------------

    def _patch(self, old: AnyElement, new: AnyElement, element: ET.Element) -> None:
        if old is new:
            return
        sync_element(element, old, new)
        if old.children is not new.children:
            self._patch_children(old, new, element)

    def _patch_children(self, old: AnyElement, new: AnyElement, element: ET.Element) -> None:
        kids = self._kids.get(element, [])
        pairs = list(zip(old.children, new.children, strict=False))
        if len(old.children) == len(new.children) and all(
            _same_tag(a, b) for a, b in pairs
        ):  # the same elements, some of them changed
            for (a, b), kid in zip(pairs, kids, strict=True):
                if a is not b and isinstance(a, (TypedElement, GenericElement)):
                    assert isinstance(b, (TypedElement, GenericElement))
                    self._patch(a, b, kid)
            return
        # Elements came or went: keep the elements of unchanged children, build the others.
        by_identity = {id(child): index for index, child in enumerate(old.children)}
        used: set[int] = set()
        new_kids: list[ET.Element] = []
        for child in new.children:
            index = by_identity.get(id(child))
            if index is not None and index not in used:
                used.add(index)
                new_kids.append(kids[index])
            else:
                new_kids.append(self._build(child))
        dropped = [kid for index, kid in enumerate(kids) if index not in used]
        live = list(element)
        if len(live) == len(kids) and all(a is b for a, b in zip(live, kids, strict=True)):
            element[:] = new_kids
        else:  # someone else edited the children: keep their edits, apply ours
            kept = {id(kid) for kid in kids}
            for kid in dropped:
                if any(kid is e for e in live):
                    element.remove(kid)
            for kid in new_kids:
                if id(kid) not in kept:
                    element.append(kid)
        for kid in dropped:
            self._forget(kid)
        self._kids[element] = new_kids


def _same_tag(a: Node, b: Node) -> bool:
    if isinstance(a, Comment) or isinstance(b, Comment):
        return isinstance(a, Comment) and isinstance(b, Comment)
    assert isinstance(a, (TypedElement, GenericElement))
    assert isinstance(b, (TypedElement, GenericElement))
    return a.tag == b.tag
