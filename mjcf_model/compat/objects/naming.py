"""robosuite's names of an object: prefixed, and recorded by category, once per shape.

A tree's *naming skeleton* (shape, tags, naming attributes) decides where the prefix goes
and which names robosuite records, so both are computed once per skeleton.

>>> from mjcf_model import GenericElement
>>> def box(size):
...     geom = GenericElement(tag="geom", attributes={"name": "g0", "size": size})
...     return GenericElement(tag="body", attributes={"name": "main"}, children=[geom])
>>> naming_skeleton(box("0.1")) == naming_skeleton(box("0.2"))
True
>>> robosuite_prefixed(box("0.1"), "cube_").children[0].attributes
AttributeMap({'name': 'cube_g0', 'size': '0.1'})
"""

from __future__ import annotations

from collections.abc import Callable, Hashable
from typing import Any

from mjcf_model.caching import BoundedCache, IdentityCache
from mjcf_model.compat.mjcf_utils.naming import already_prefixed
from mjcf_model.compat.mjcf_utils.queries import categorized
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    GenericElement,
    Node,
    attribute_items,
    attribute_text,
)
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.transforms.naming.renaming import prefixed
from mjcf_model.transforms.naming.repeated import PrefixPlan
from mjcf_model.values import Value

__all__ = ["recorded_names", "robosuite_prefixed", "skeleton_memo"]

#: The name lists robosuite caches, in the order of ``sort_elements``' categories.
_CATEGORIES = ("bodies", "joints", "actuators", "sites", "sensors", "contact_geoms", "visual_geoms")

#: Attributes a skeleton keeps: naming ones, reference targets, ``file`` and ``group``.
_SKELETON_ATTRIBUTES = frozenset(
    {"file", "group"}
    | {name for spec in SCHEMA.values() for name in (*spec.declares, *spec.references)}
    | {target[1:] for spec in SCHEMA.values() for target in spec.references.values()}
)
#: Elements that make or hide names: trees holding one have no skeleton.
_GENERATORS = frozenset(
    {"replicate", "flexcomp", "attach", "model", "skin", "include", "composite"}
)
#: How deep a skeleton follows a tree.
_DEPTH = 100

#: What is known of each naming skeleton: one dict for every tree with that skeleton.
_BY_SKELETON: BoundedCache[Hashable, dict[str, Any]] = BoundedCache(128)
#: Those dicts for the last trees asked about, by identity (one tree is asked twice or more).
_OF_TREES: IdentityCache[dict[str, Any] | None] = IdentityCache(8)


def skeleton_memo(node: AnyElement) -> dict[str, Any] | None:
    """A dict shared by every tree with ``node``'s naming skeleton (``None``: no skeleton)."""

    def shared() -> dict[str, Any] | None:
        skeleton = naming_skeleton(node)
        return None if skeleton is None else _BY_SKELETON.recall(skeleton, dict)

    return _OF_TREES.recall_for(node, shared)


def naming_skeleton(node: AnyElement) -> Hashable:
    """What prefixing ``node`` and sorting its names read; ``None`` with generators or too deep."""
    return _skeleton(node, 0)


def _skeleton(node: Node, depth: int) -> Hashable:
    if not isinstance(node, Element):
        return ()
    if node.tag in _GENERATORS or depth > _DEPTH:
        return None
    children = []
    for child in node.children:
        inner = _skeleton(child, depth + 1)
        if inner is None:
            return None
        children.append(inner)
    named: list[tuple[str, Value]]
    if isinstance(node, GenericElement):
        texts = node.attributes
        named = [(key, texts[key]) for key in texts if key in _SKELETON_ATTRIBUTES]
    else:
        named = [item for item in attribute_items(node) if item[0] in _SKELETON_ATTRIBUTES]
    return type(node), node.tag, tuple(named), tuple(children)


def robosuite_prefixed(
    node: AnyElement, prefix: str, exclude: Callable[[str], bool] | None = None
) -> AnyElement:
    """Like robosuite's ``add_prefix``: names without ``prefix`` get it, unless ``exclude``d."""
    if not prefix:
        return node

    def skip(name: str) -> bool:
        return already_prefixed(name, prefix) or (exclude is not None and bool(exclude(name)))

    memo = skeleton_memo(node)
    plan: PrefixPlan | None = None
    if memo is not None:
        seen = memo.get("prefixed", 0)
        memo["prefixed"] = seen + 1
        if seen == 1:  # the second time: this skeleton recurs, so its plan pays
            memo["plan"] = PrefixPlan.traced(node, _every_reference, by_name=True)
        plan = memo.get("plan")
    if plan is None:
        return prefixed(node, prefix, undeclared=True, exclude=skip)
    return plan.applied(node, prefix, keep=skip)


def _every_reference(node: AnyElement, prefix: str) -> AnyElement:
    return prefixed(node, prefix, undeclared=True)


def recorded_names(node: AnyElement) -> tuple[AnyElement, dict[str, Any]]:
    """The root body of ``node`` (exactly one) and robosuite's raw names (``_root_body``...)."""
    found = categorized(node)
    if len(found.root_body) != 1:
        raise MjcfValueError(
            "Invalid number of root bodies found for robot model. Expected 1,"
            f"got {len(found.root_body)}"
        )
    root = found.root_body[0]
    names: dict[str, Any] = {"_root_body": attribute_text(root, "name")}
    names["_bodies"] = [attribute_text(e, "name") for e in (root, *found.bodies)]
    for category in _CATEGORIES[1:]:
        names[f"_{category}"] = [attribute_text(e, "name") for e in getattr(found, category)]
    return root, names
