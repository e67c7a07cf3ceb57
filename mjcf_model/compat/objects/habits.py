"""robosuite's habits as node functions: number text, attribute order, scaling, file reading.

Built on the compatible ``mjcf_utils`` wherever robosuite's objects call ``mjcf_utils``.
Files are read into generic elements, so attribute text stays exactly as written.

>>> value_text(np.float32(0.5)), value_text([0.5, 0, 1])
('0.5', '0.5 0 1')
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
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any

import numpy as np

from mjcf_model.caching import BoundedCache
from mjcf_model.compat.mjcf_utils import constants as utils_constants
from mjcf_model.compat.mjcf_utils.scaling import (
    scaled_body,
    scaled_geom,
    scaled_joint,
    scaled_mesh,
    scaled_site,
)
from mjcf_model.compat.mjcf_utils.text import array_to_string, text_of
from mjcf_model.compat.objects.document import as_node, is_element
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.nodes.base import (
    AnyElement,
    GenericElement,
    Node,
    attribute_text,
    with_attributes,
)
from mjcf_model.serializers.dumping import attribute_texts
from mjcf_model.transforms.scaling.transform import three_factors
from mjcf_model.tree.ancestry import fold_ancestors
from mjcf_model.tree.defaults import MAIN, DefaultClasses
from mjcf_model.tree.traversal import Path, map_elements, map_tree, with_children

__all__ = [
    "OBJECT_COLLISION_RGBA_TEXT",
    "absolute_files",
    "named_geoms",
    "named_specs",
    "read_like_robosuite",
    "robosuite_scaled",
    "split_geoms",
    "value_text",
    "visual_twin",
]

#: robosuite's ``OBJECT_COLLISION_COLOR`` (a list), as its objects write it: ``"0.5 0 0 1"``.
OBJECT_COLLISION_RGBA_TEXT = array_to_string(utils_constants.OBJECT_COLLISION_COLOR)

#: ``scale_mjcf_model``'s rule per tag (robosuite's objects pass ``scale_slide_joints=False``).
_SCALING_RULES: Mapping[str, Callable[[Node, Any], Node]] = {
    "geom": scaled_geom,
    "site": scaled_site,
    "body": scaled_body,
    "joint": lambda node, factors: scaled_joint(node, factors, scale_slide_joints=False),
    "mesh": scaled_mesh,
}

#: The sections ``MujocoXML`` makes sure exist, in the order it adds missing ones.
SECTIONS = ("worldbody", "actuator", "sensor", "asset", "tendon", "equality", "contact")


def value_text(value: Any) -> str:
    """Like robosuite's ``convert_to_string``, also accepting numpy scalars (robosuite raises)."""
    if type(value) is str:  # most values are text already
        return value
    text = text_of(value, exact=False)
    if text is None:
        raise MjcfValueError(f"unsupported attribute value type: got {type(value)} ({value!r})")
    return text


def named_specs(
    specs: Any, stem: str, default: dict[str, str] | None = None, by_position: bool = True
) -> list[dict[str, Any]]:
    """Attribute dicts as robosuite takes them: ``"default"`` is ``[default]``; names added.

    The caller's dicts are named ``<stem><k>`` in place, ``k`` their position (not
    ``by_position``: the count of unnamed ones before, robosuite's composite rule).
    """
    if isinstance(specs, str) and specs == "default":
        specs = [default]
    named: list[dict[str, Any]] = specs
    unnamed = 0
    for index, spec in enumerate(named):
        if "name" not in spec:
            spec["name"] = f"{stem}{index if by_position else unnamed}"
            unnamed += 1
    return named


def robosuite_scaled(node: AnyElement, scale: Any, tags: Iterable[str]) -> AnyElement:
    """What robosuite's objects scale below ``node`` (tags ``tags``), written as robosuite does."""
    chosen = frozenset(tags) & _SCALING_RULES.keys()
    factors = np.array(three_factors(scale))

    def scale_one(node: Node) -> Node:
        if not is_element(node) or node.tag not in chosen:
            return node
        try:
            return _SCALING_RULES[node.tag](node, factors)
        except ValueError as error:
            raise MjcfValueError(f"<{node.tag}> cannot be scaled: {error}") from error

    return with_children(node, [map_tree(scale_one, child) for child in node.children])


def read_like_robosuite(fname: str) -> tuple[AnyElement, dict[str, Path]]:
    """The document robosuite's ``MujocoXML(fname)`` ends up with, and its section paths."""
    try:
        stat = os.stat(fname)
    except OSError:
        return _read(fname)  # raises as ElementTree does
    key = (os.path.abspath(fname), stat.st_ino, stat.st_mtime_ns, stat.st_ctime_ns, stat.st_size)
    document, paths = _READ.recall(key, lambda: _read(fname))
    return document, dict(paths)


#: The documents :func:`read_like_robosuite` read, by path, modification time and size.
_READ: BoundedCache[tuple[Any, ...], tuple[AnyElement, dict[str, Path]]] = BoundedCache(32)


def _read(fname: str) -> tuple[AnyElement, dict[str, Path]]:
    root = as_node(ET.parse(fname).getroot())
    children: list[Node] = list(root.children)
    for section in SECTIONS:
        if not any(is_element(c, section) for c in children):
            children.append(GenericElement(tag=section))
    default = next((c for c in children if is_element(c, "default")), None)
    if default is not None:
        children.remove(default)
        assert is_element(default)
        root = inline_defaults(with_children(root, children), default)
        children = list(root.children)
    folder = os.path.abspath(os.path.dirname(fname))
    paths: dict[str, Path] = {}
    for index, child in enumerate(children):
        if is_element(child) and child.tag in SECTIONS:
            paths.setdefault(child.tag, (index,))
    asset = children[paths["asset"][0]]
    assert is_element(asset)
    children[paths["asset"][0]] = absolute_files(asset, folder)
    return with_children(root, children), paths


def absolute_files(asset: AnyElement, folder: str) -> AnyElement:
    """``asset`` with each child's ``file`` joined to ``folder``, not normalised, as robosuite."""
    return with_children(
        asset,
        [
            with_attributes(c, {"file": os.path.join(folder, file)})
            if is_element(c) and (file := attribute_text(c, "file")) is not None
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

    def visit(element: AnyElement, _key: str | None, ancestors: Sequence[AnyElement]) -> AnyElement:
        own = attribute_text(element, "class")
        chosen = own if own is not None else fold_ancestors(ancestors, _below, None)
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
        childclass = attribute_text(element, "childclass")
        if childclass is not None:
            chain(childclass)
            changes["childclass"] = None
        return with_attributes(element, changes)

    return map_elements(visit, root)


def _below(inherited: str | None, ancestor: AnyElement) -> str | None:
    """The class ``ancestor``'s children inherit (its ``childclass``), given the one it inherits."""
    childclass = attribute_text(ancestor, "childclass")
    return inherited if childclass is None else childclass


def split_geoms(body: AnyElement, groups: set[int], duplicate: bool) -> AnyElement:
    """``MujocoXMLObject``'s geom pass: keep ``groups``, name geom ``i`` ``g<i>``, add twins.

    Geom ``i`` is the ``i``-th in document order, dropped ones counted; a parent's
    twins follow its other children.
    """
    counter = 0
    dropped: dict[int, Node] = {}  # by identity, each kept alive while it is the key
    twins: dict[int, Node] = {}

    def visit(node: Node) -> Node:
        nonlocal counter
        if is_element(node, "geom"):  # geoms hold no geoms: visited in document order
            index = counter
            counter += 1
            group = attribute_text(node, "group")
            if (0 if group is None else int(group)) not in groups:
                dropped[id(node)] = node
                return node
            name = attribute_text(node, "name")
            if name is None:
                name = f"g{index}"
            geom = with_attributes(node, {"name": name})
            if duplicate and group in (None, "0"):
                twin = visual_twin(geom, name)
                geom = with_attributes(geom, {"rgba": OBJECT_COLLISION_RGBA_TEXT, "material": None})
                twins[id(geom)] = twin
            return geom
        if not is_element(node) or not any(
            id(child) in dropped or id(child) in twins for child in node.children
        ):
            return node
        kept = [child for child in node.children if id(child) not in dropped]
        return with_children(node, kept + [twins[id(c)] for c in kept if id(c) in twins])

    split = map_tree(visit, body)
    assert is_element(split)
    return split


def visual_twin(geom: AnyElement, name: str) -> AnyElement:
    """The visual twin ``<name>_visual`` of collision geom ``geom``: group 1, no contact or mass."""
    changes = {"group": "1", "conaffinity": "0", "contype": "0", "mass": "1e-8"}
    return with_attributes(geom, {**changes, "name": name + "_visual"})


#: ``MujocoXMLModel``'s suffix of an unnamed geom, by its group.
_GEOM_KINDS = {None: "col", "0": "col", "1": "vis"}


def named_geoms(node: AnyElement) -> AnyElement:
    """Name unnamed geoms ``g<k>_col`` (group 0 or none) and ``g<k>_vis`` (group 1), in order."""
    counters = {"col": 0, "vis": 0}

    def name(geom: Node) -> Node:
        if not is_element(geom, "geom") or attribute_text(geom, "name") is not None:
            return geom
        kind = _GEOM_KINDS.get(attribute_text(geom, "group"))
        if kind is None:
            return geom
        counters[kind] += 1
        return with_attributes(geom, {"name": f"g{counters[kind] - 1}_{kind}"})

    named = map_tree(name, node)  # geoms are leaves: children first is document order for them
    assert is_element(named)
    return named
