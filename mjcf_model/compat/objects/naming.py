"""Prefixing an object's names as robosuite does, once planned for every object of the same shape.

robosuite's ``add_prefix`` puts the object's name before every name and
reference of its body (or, for XML objects, of its whole document).
:func:`robosuite_prefixed` does so with the library's namespace table. An
environment makes the same objects at every reset, and objects of one kind
differ only in sizes and colours, not in the names prefixing reads: the
*naming skeleton* of a tree (:func:`naming_skeleton`: its shape, tags and the
attributes that name things) decides where the prefix goes, so that is traced
once per skeleton (:class:`~mjcf_model.transforms.naming.repeated.PrefixPlan`) and then
only written. The skeleton also decides the names robosuite records
(:func:`~mjcf_model.compat.objects.base.recorded_names`), which read the geom
groups too.

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

from mjcf_model.compat.mjcf_utils.naming import already_prefixed
from mjcf_model.compat.objects.memo import Memo
from mjcf_model.nodes.base import AnyElement, GenericElement, Node, TypedElement, attribute_items
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.transforms.naming.renaming import prefixed
from mjcf_model.transforms.naming.repeated import PrefixPlan
from mjcf_model.values import Value

__all__ = ["naming_skeleton", "robosuite_prefixed", "skeleton_memo"]

#: What a skeleton keeps of an element: every attribute that may declare or refer to
#: a name, or say where a reference points, a file (assets are named by it), and the
#: geom group (robosuite's categories read it).
_SKELETON_ATTRIBUTES = frozenset(
    {"file", "group"}
    | {name for spec in SCHEMA.values() for name in (*spec.declares, *spec.references)}
    | {target[1:] for spec in SCHEMA.values() for target in spec.references.values()}
)
#: Elements that make names from other attributes, or hide them: trees holding one
#: have no skeleton, and are prefixed without a plan.
_GENERATORS = frozenset(
    {"replicate", "flexcomp", "attach", "model", "skin", "include", "composite"}
)
#: How deep a skeleton follows a tree.
_DEPTH = 100

#: What is known of each naming skeleton: one dict for every tree with that skeleton.
_BY_SKELETON: Memo[dict[str, Any]] = Memo(128)
#: Those dicts for the last trees asked about, by identity (one tree is asked twice or more).
_OF_TREES: Memo[dict[str, Any] | None] = Memo(8)


def skeleton_memo(node: AnyElement) -> dict[str, Any] | None:
    """A dict shared by every tree with ``node``'s naming skeleton; ``None`` for a tree without one.

    What is computed from a tree's naming skeleton alone (a prefix plan, the
    names robosuite records) is kept there, under a name of the caller's.

    Example:
        >>> from mjcf_model import GenericElement
        >>> one = GenericElement(tag="geom", attributes={"name": "g", "size": "1"})
        >>> two = GenericElement(tag="geom", attributes={"name": "g", "size": "2"})
        >>> skeleton_memo(one) is skeleton_memo(two)
        True

    """

    def shared() -> dict[str, Any] | None:
        skeleton = naming_skeleton(node)
        return None if skeleton is None else _BY_SKELETON.get(skeleton, dict)

    return _OF_TREES.of(node, shared)


def naming_skeleton(node: AnyElement) -> Hashable:
    """What prefixing ``node`` and sorting its names read; ``None`` for a tree without one.

    The shape of the tree, each element's type and tag, and its attributes that
    name things (:data:`_SKELETON_ATTRIBUTES`). A tree with name generators
    (``<replicate>``, ``<flexcomp>``, ``<attach>``...), or deeper than a
    skeleton follows, has none.

    Example:
        >>> from mjcf_model import GenericElement
        >>> naming_skeleton(GenericElement(tag="geom", attributes={"name": "g", "size": "1"}))
        (<class 'mjcf_model.nodes.base.GenericElement'>, 'geom', (('name', 'g'),), ())

    """
    return _skeleton(node, 0)


def _skeleton(node: Node, depth: int) -> Hashable:
    if not isinstance(node, (TypedElement, GenericElement)):
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
    """Like robosuite's ``add_prefix``: names and references get ``prefix`` unless they have it.

    :func:`mjcf_model.prefixed` with every reference prefixed (also to names
    the subtree does not declare, as robosuite does) and, as ``exclude``,
    robosuite's test (:func:`~mjcf_model.compat.mjcf_utils.naming.already_prefixed`)
    or the caller's predicate. The namespace table decides which attributes
    are names, so a few differ from robosuite's fixed attribute list, on
    purpose: equality ``site1``/``site2``, actuator ``refsite`` and sensor
    ``refname`` are prefixed too (robosuite leaves them and MuJoCo then cannot
    find them), and a file asset without a ``name`` gets one (its file stem,
    prefixed) so references to it still work. The compatible
    ``mjcf_utils.add_prefix`` (:mod:`~mjcf_model.compat.mjcf_utils.naming`) keeps
    robosuite's attribute list exactly, because its callers expect robosuite's
    text; the objects want a model MuJoCo loads.

    Where the prefix goes is traced once per :func:`naming_skeleton`, the
    second time a tree of that skeleton is prefixed (objects of a kind are made
    again and again; a tree prefixed once is not worth a plan).

    Example:
        >>> from mjcf_model import GenericElement
        >>> body = GenericElement(tag="body", attributes={"name": "main"}, children=[
        ...     GenericElement(tag="geom", attributes={"mesh": "can_mesh", "material": "m"})])
        >>> new = robosuite_prefixed(body, "can_")
        >>> new.attributes["name"], dict(new.children[0].attributes)
        ('can_main', {'mesh': 'can_mesh', 'material': 'can_m'})

    """
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
