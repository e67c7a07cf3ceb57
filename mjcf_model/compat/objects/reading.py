"""Reading an MJCF file the way robosuite's ``MujocoXML`` does, into an immutable node.

:func:`read_like_robosuite` returns the document robosuite's ``MujocoXML``
holds after its constructor: sections added, default classes written inline
and removed, asset files made absolute. Attribute text is kept exactly as in
the file (``pos="0 0 0."`` stays), because robosuite hands it on unchanged;
that is why the nodes are generic elements (``from_etree(..., typed=False)``).
:func:`split_geoms` is the geom handling of ``MujocoXMLObject``.

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

__all__ = [
    "SECTIONS",
    "absolute_files",
    "inline_defaults",
    "read_like_robosuite",
    "split_geoms",
    "visual_twin",
]

#: The sections ``MujocoXML`` makes sure exist, in the order it adds missing ones.
SECTIONS = ("worldbody", "actuator", "sensor", "asset", "tendon", "equality", "contact")


def _elements(node: AnyElement) -> list[AnyElement]:
    return [c for c in node.children if isinstance(c, (TypedElement, GenericElement))]


def read_like_robosuite(fname: str) -> tuple[AnyElement, dict[str, Path]]:
    """The document robosuite's ``MujocoXML(fname)`` ends up with, and where its sections are.

    1. the file is parsed with ElementTree (comments dropped);
    2. each of :data:`SECTIONS` that is missing is added, empty, at the end;
    3. the first ``<default>`` is written inline (:func:`inline_defaults`) and removed;
    4. the ``file`` of each element of the first ``<asset>`` is joined to the
       file's absolute directory (not normalised: ``.../objects/../textures/x.png``).

    The node is immutable, so a file read again unchanged (same path,
    modification time and size) gives the node read before, as robosuite's
    objects read the same few files over and over.

    Returns:
        The root node and the path of each section (and of ``worldbody``).

    """
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
    """``asset`` with the ``file`` of each child joined to ``folder`` (robosuite's asset step).

    As robosuite's ``resolve_asset_dependency``: not normalised, and an
    absolute ``file`` stays (``os.path.join`` keeps it).

    Example:
        >>> asset = GenericElement(tag="asset", children=[
        ...     GenericElement(tag="mesh", attributes={"file": "m.stl"}), GenericElement(tag="x")])
        >>> [c.attributes.get("file") for c in absolute_files(asset, "/d").children]
        ['/d/m.stl', None]

    """
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
    """Write the default classes of ``default`` into the elements that use them.

    As robosuite's ``_replace_defaults_inline``: an element's ``class`` is
    removed and each attribute of that class's setting for the element's tag
    that the element lacks is appended, in the setting's order; the main
    (unnamed) class is ignored, as robosuite ignores it (robosuite's models
    were tuned without it). Where robosuite fails on valid MJCF, this does what
    MuJoCo does instead:

    * nested classes: a class also gives what its enclosing classes (not main)
      set and it does not (robosuite raises ``KeyError``);
    * ``childclass``: descendants without a ``class`` of their own take that
      class, and the attribute is removed (robosuite keeps it, prefixes it,
      and MuJoCo then rejects the model: "unknown default class").

    Raises:
        MjcfLookupError: an element names a class that does not exist.

    Example:
        >>> from serializers import from_etree
        >>> default = from_etree(ET.fromstring(
        ...     '<default><default class="a"><geom group="1"/><default class="b">'
        ...     '<geom rgba="1 0 0 1"/></default></default></default>'), typed=False)
        >>> body = from_etree(ET.fromstring('<body childclass="b"><geom/></body>'), typed=False)
        >>> dict(inline_defaults(body, default).children[0].attributes)
        {'rgba': '1 0 0 1', 'group': '1'}

    """
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
    """``MujocoXMLObject``'s geom pass: drop, name, and give collision geoms a visual twin.

    In document order, geom ``i`` (counting every geom of ``body``'s subtree,
    the dropped ones too) is dropped unless its group is in ``groups`` (groups
    2 and up always go); a kept geom without a name is named ``g<i>``. With
    ``duplicate``, a collision geom (group 0 or none) gets a visual copy
    (``group="1" conaffinity="0" contype="0" mass="1e-8"``, name + ``_visual``)
    appended at the end of its parent, and itself becomes
    ``rgba="0.5 0 0 1"`` without a material. A geom without ``group`` is a
    collision geom here, as in MuJoCo (robosuite raises ``TypeError``).

    Example:
        >>> from serializers import from_etree
        >>> body = from_etree(ET.fromstring(
        ...     '<body><geom group="3"/><geom group="0" material="m"/></body>'), typed=False)
        >>> new = split_geoms(body, {0, 1}, True)
        >>> [dict(g.attributes) for g in new.children]  # doctest: +NORMALIZE_WHITESPACE
        [{'group': '0', 'name': 'g1', 'rgba': '0.5 0 0 1'},
         {'group': '1', 'material': 'm', 'name': 'g1_visual', 'conaffinity': '0',
          'contype': '0', 'mass': '1e-8'}]

    """
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
    """The visual copy of collision geom ``geom`` named ``name``: group 1, no contacts, no mass.

    Example:
        >>> geom = GenericElement(tag="geom", attributes={"name": "g", "group": "0"})
        >>> dict(visual_twin(geom, "g").attributes)  # doctest: +NORMALIZE_WHITESPACE
        {'name': 'g_visual', 'group': '1', 'conaffinity': '0', 'contype': '0',
         'mass': '1e-8'}

    """
    changes: dict[str, Any] = {
        "group": "1",
        "conaffinity": "0",
        "contype": "0",
        "mass": "1e-8",
        "name": name + "_visual",
    }
    return with_texts(geom, changes)
