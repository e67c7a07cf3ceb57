"""Reading an MJCF file the way robosuite's ``MujocoXML`` does, into an immutable node.

Nodes are generic elements, so attribute text stays exactly as in the file.

>>> import tempfile, pathlib
>>> path = pathlib.Path(tempfile.mkdtemp()) / "m.xml"
>>> _ = path.write_text('<mujoco model="m"><default><default class="a"><geom group="1"/>'
...     '</default></default><worldbody><geom class="a" size="1"/></worldbody></mujoco>')
>>> root, paths = read_like_robosuite(str(path))
>>> [child.tag for child in root.children], paths["asset"]
(['worldbody', 'actuator', 'sensor', 'asset', 'tendon', 'equality', 'contact'], (3,))
>>> dict(root.children[0].children[0].attributes)
{'size': '1', 'group': '1'}
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from typing import Any

from mjcf_model.compat.objects.habits import OBJECT_COLLISION_COLOR, attribute, with_texts
from mjcf_model.compat.objects.memo import Memo
from mjcf_model.errors import MjcfLookupError
from mjcf_model.nodes.base import AnyElement, GenericElement, Node, TypedElement
from mjcf_model.tree.defaults import MAIN, DefaultClasses
from mjcf_model.tree.traversal import Path, with_children
from serializers import from_etree
from serializers.writer import attribute_texts

__all__ = ["absolute_files", "read_like_robosuite", "split_geoms", "visual_twin"]

#: The sections ``MujocoXML`` makes sure exist, in the order it adds missing ones.
SECTIONS = ("worldbody", "actuator", "sensor", "asset", "tendon", "equality", "contact")


def read_like_robosuite(fname: str) -> tuple[AnyElement, dict[str, Path]]:
    """The document robosuite's ``MujocoXML(fname)`` ends up with, and its section paths."""
    try:
        stat = os.stat(fname)
    except OSError:
        return _read(fname)  # raises as ElementTree does
    key = (os.path.abspath(fname), stat.st_ino, stat.st_mtime_ns, stat.st_ctime_ns, stat.st_size)
    document, paths = _READ.get(key, lambda: _read(fname))
    return document, dict(paths)


#: The documents :func:`read_like_robosuite` read, by path, modification time and size.
_READ: Memo[tuple[AnyElement, dict[str, Path]]] = Memo(32)


def _read(fname: str) -> tuple[AnyElement, dict[str, Path]]:
    element = ET.parse(fname).getroot()
    root = from_etree(element, typed=False)
    assert isinstance(root, (TypedElement, GenericElement))
    children: list[Node] = list(root.children)
    for section in SECTIONS:
        if not any(_is(c, section) for c in children):
            children.append(GenericElement(tag=section))
    default = next((c for c in children if _is(c, "default")), None)
    if default is not None:
        children.remove(default)
        assert isinstance(default, (TypedElement, GenericElement))
        root = inline_defaults(with_children(root, children), default)
        children = list(root.children)
    folder = os.path.abspath(os.path.dirname(fname))
    paths: dict[str, Path] = {}
    for index, child in enumerate(children):
        if isinstance(child, (TypedElement, GenericElement)) and child.tag in SECTIONS:
            paths.setdefault(child.tag, (index,))
    asset = children[paths["asset"][0]]
    assert isinstance(asset, (TypedElement, GenericElement))
    children[paths["asset"][0]] = absolute_files(asset, folder)
    return with_children(root, children), paths


def _is(node: Node, tag: str) -> bool:
    return isinstance(node, (TypedElement, GenericElement)) and node.tag == tag


def absolute_files(asset: AnyElement, folder: str) -> AnyElement:
    """``asset`` with each child's ``file`` joined to ``folder``, not normalised, as robosuite."""
    return with_children(
        asset,
        [
            with_texts(c, {"file": os.path.join(folder, file)})
            if isinstance(c, (TypedElement, GenericElement))
            and (file := attribute(c, "file")) is not None
            else c
            for c in asset.children
        ],
    )


def inline_defaults(root: AnyElement, default: AnyElement) -> AnyElement:
    """Write ``default``'s classes inline as robosuite does (nested, ``childclass``: as MuJoCo)."""
    classes = DefaultClasses.of(GenericElement(tag="mujoco", children=[default]))

    def chain(name: str) -> tuple[str, ...]:
        if name not in classes.parents:
            known = sorted(c for c in classes.parents if c != MAIN)
            raise MjcfLookupError(
                f"unknown default class {name!r}; the classes are {', '.join(known) or 'none'}"
            )
        return tuple(c for c in classes.chain(name) if c != MAIN)

    def visit(element: AnyElement, inherited: str | None) -> AnyElement:
        own = attribute(element, "class")
        chosen = own if own is not None else inherited
        changes: dict[str, str | None] = {}
        if own is not None:
            changes["class"] = None
        if chosen is not None:
            present = {name for name, _ in attribute_texts(element)}
            for name in chain(chosen):
                setting = classes.settings.get((name, element.tag))
                if setting is None:
                    continue
                for key, text in attribute_texts(setting):
                    if key not in present and key not in changes:
                        changes[key] = text
        below = inherited
        childclass = attribute(element, "childclass")
        if childclass is not None:
            chain(childclass)
            changes["childclass"] = None
            below = childclass
        children = [
            visit(c, below) if isinstance(c, (TypedElement, GenericElement)) else c
            for c in element.children
        ]
        return with_texts(with_children(element, children), changes)

    return visit(root, None)


def split_geoms(body: AnyElement, groups: set[int], duplicate: bool) -> AnyElement:
    """``MujocoXMLObject``'s geom pass: keep ``groups``, name geom ``i`` ``g<i>``, add twins."""
    counter = 0

    def visit(element: AnyElement) -> AnyElement:
        nonlocal counter
        kept: list[Node] = []
        twins: list[Node] = []
        for child in element.children:
            if not isinstance(child, (TypedElement, GenericElement)):
                kept.append(child)
            elif child.tag != "geom":
                kept.append(visit(child))
            else:
                index = counter
                counter += 1
                group = attribute(child, "group")
                if (0 if group is None else int(group)) not in groups:
                    continue
                name = attribute(child, "name")
                if name is None:
                    name = f"g{index}"
                geom = with_texts(child, {"name": name})
                if duplicate and group in (None, "0"):
                    twins.append(visual_twin(geom, name))
                    geom = with_texts(geom, {"rgba": OBJECT_COLLISION_COLOR, "material": None})
                kept.append(geom)
        return with_children(element, kept + twins)

    return visit(body)


def visual_twin(geom: AnyElement, name: str) -> AnyElement:
    """The visual twin ``<name>_visual`` of collision geom ``geom``: group 1, no contact or mass."""
    changes: dict[str, Any] = {
        "group": "1",
        "conaffinity": "0",
        "contype": "0",
        "mass": "1e-8",
        "name": name + "_visual",
    }
    return with_texts(geom, changes)
