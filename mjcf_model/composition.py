"""Composing models: :func:`attach` merges one model into another, as MuJoCo would compile both.

The child's world is added to the parent's world (or inside one of its bodies),
and everything else follows: assets, default classes, actuators, sensors,
tendons, equality constraints, contacts, custom data, deformables, plugins and
keyframes. No wrapper body is added. Names the two models both declare are an
error (give the child a ``prefix``), except assets that are the same element in
both, which are kept once.

>>> from serializers import dumps, loads
>>> world = loads('<mujoco><worldbody><geom name="floor" type="plane" size="1 1 1"/>'
...               '</worldbody></mujoco>')
>>> cube = loads('<mujoco><worldbody><body name="cube"><freejoint/><geom size=".1"/></body>'
...              '</worldbody></mujoco>')
>>> scene = attach(attach(world, cube, prefix="a_"), cube, prefix="b_")
>>> [body.name for body in scene.worldbody.bodies]
['a_cube', 'b_cube']
"""

from __future__ import annotations

from collections.abc import Collection, Iterable, Mapping, Sequence

import attrs

from mjcf_model.base import (
    AnyElement,
    GenericElement,
    Node,
    TypedElement,
    attribute_items,
    get_attribute,
    with_attributes,
)
from mjcf_model.composition_keys import merged_keyframes
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.namespaces import SCHEMA
from mjcf_model.naming import declarations, declared_names, prefixed_declared
from mjcf_model.nodes.default import Default
from mjcf_model.nodes.keyframe import Keyframe
from mjcf_model.nodes.root import Mujoco
from mjcf_model.queries import find, find_all
from mjcf_model.registry import CLASS_BY_KEY
from mjcf_model.traversal import keyed_walk, refuse_opaque, with_children

__all__ = ["attach", "attach_all"]

#: Sections whose settings the parent keeps; a parent without one adopts the child's.
_SETTINGS = ("compiler", "option", "size", "statistic", "visual")
#: Sections whose elements are added to the parent's section of the same tag.
_LISTS = (
    "extension",
    "custom",
    "asset",
    "deformable",
    "contact",
    "equality",
    "tendon",
    "actuator",
    "sensor",
)
#: Sections whose elements take defaults and so need the child's class when it has one.
_CLASSED_SECTIONS = ("asset", "contact", "equality", "tendon", "actuator")


def _elements(node: AnyElement) -> list[AnyElement]:
    return [c for c in node.children if isinstance(c, (TypedElement, GenericElement))]


def _sections(model: Mujoco, tag: str) -> list[AnyElement]:
    return [c for c in _elements(model) if c.tag == tag]


def _section_children(model: Mujoco, tag: str) -> list[Node]:
    return [child for section in _sections(model, tag) for child in section.children]


def _check_compilers(mine: Sequence[Node], child: Mujoco) -> None:
    theirs = _sections(child, "compiler")
    if mine and theirs and mine != theirs:
        raise MjcfValueError(
            "the parent and the child have different <compiler> settings, so the child's "
            "angles, paths or limits would be read differently; make them agree first "
            f"(parent: {mine[0]!r}, child: {theirs[0]!r})"
        )


def _check_collisions(declared: dict[str, set[str]], theirs: Mapping[str, Collection[str]]) -> None:
    """Raise when the child's names ``theirs`` meet the parent's ``declared`` ones."""
    clashes = {
        namespace: sorted(set(names) & declared.get(namespace, set()))
        for namespace, names in theirs.items()
    }
    clashes = {namespace: names for namespace, names in clashes.items() if names}
    if clashes:
        listed = "; ".join(
            f"{namespace}: {', '.join(names)}" for namespace, names in clashes.items()
        )
        raise MjcfValueError(
            f"the child declares names the parent already has ({listed}); attach it with a prefix"
        )


def _has_settings(default: AnyElement) -> bool:
    """Whether a top-level ``<default>`` sets anything itself (not only nested classes)."""
    return any(e.tag != "default" for e in _elements(default))


def _merged_settings(nodes: list[Node]) -> list[Node]:
    """Several top-level defaults as one class: settings of one tag merged, later ones winning."""
    merged: list[Node] = []
    first: dict[str, int] = {}
    for node in nodes:
        tag = getattr(node, "tag", None)
        if not isinstance(tag, str) or tag == "default":
            merged.append(node)
        elif tag in first:
            earlier = merged[first[tag]]
            assert isinstance(earlier, (TypedElement, GenericElement))
            assert isinstance(node, (TypedElement, GenericElement))
            merged[first[tag]] = with_attributes(earlier, dict(attribute_items(node)))
        else:
            first[tag] = len(merged)
            merged.append(node)
    return merged


def _with_class(element: AnyElement, attribute: str, name: str) -> AnyElement:
    return (
        element
        if get_attribute(element, attribute) is not None
        else with_attributes(element, {attribute: name})
    )


#: The ``<default>`` tags that set actuator defaults: each of them reaches every actuator.
_ACTUATOR_DEFAULTS = frozenset(
    key.partition("/")[2]
    for key in SCHEMA
    if key.startswith("default/") and f"actuator/{key.partition('/')[2]}" in SCHEMA
)


def _reached_by(key: str, settings: frozenset[str]) -> bool:
    """Whether default settings with the tags ``settings`` reach an element of schema ``key``."""
    section, _, tag = key.rpartition("/")
    if section in ("tendon", "equality"):
        return section in settings
    if section == "actuator":
        return bool(settings & _ACTUATOR_DEFAULTS)
    return tag in settings


def _classed(nodes: Sequence[Node], main: Default, section: str) -> list[Node]:
    """The children of the child's ``section`` naming its class ``main`` where it applies.

    Only elements that a setting of ``main`` reaches name it: the others read the
    parent's defaults either way, and an older MuJoCo rejects ``class`` on some of
    them (``<texture>`` before 4.0). Bodies and frames in the world take it as
    ``childclass``.
    """
    assert main.dclass is not None
    settings = frozenset(e.tag for e in _elements(main) if e.tag != "default")
    result: list[Node] = []
    for node in nodes:
        if isinstance(node, (TypedElement, GenericElement)):
            key = f"{section}/{node.tag}"
            if section == "body" and node.tag in ("body", "frame"):
                node = _with_class(node, "childclass", main.dclass)
            elif key in SCHEMA and "class" in SCHEMA[key].attributes and _reached_by(key, settings):
                node = _with_class(node, "class", main.dclass)
        result.append(node)
    return result


def attach(parent: Mujoco, child: Mujoco, *, at: str | None = None, prefix: str = "") -> Mujoco:
    """The parent model with the child model merged into it.

    Args:
        parent: The model to add to.
        child: The model added; with ``prefix``, every name it declares is prefixed first.
        at: The name of the parent body the child's world goes into (default: the world).
        prefix: Prepended to the child's names (see :func:`mjcf_model.prefixed`).

    The parent keeps its ``<compiler>`` (the child's must be the same or absent;
    a parent without one adopts the child's), ``<option>``, ``<size>``,
    ``<statistic>`` and ``<visual>``. The child's top-level default settings
    become a class ``<prefix>main`` in the parent's defaults, and the child's
    elements that relied on them name that class. Keyframes are merged by
    position: a child key is completed with the parent's initial ``qpos``
    (reference positions; a free body's own position), a parent key is
    completed by MuJoCo with the child's.

    Raises:
        MjcfValueError: on a name collision, different compilers, a kept
            ``<include>``, or a keyframe that cannot be completed.
        MjcfLookupError: when no parent body is named ``at``.

    Example:
        >>> from mjcf_model import Body, Geom, Mujoco, Worldbody
        >>> arm_body = Body(name="arm", children=[Geom(size=[1])])
        >>> arm = Mujoco(children=[Worldbody(children=[arm_body])])
        >>> table = Mujoco(children=[Worldbody(children=[Body(name="table")])])
        >>> attach(table, arm, at="table", prefix="r_").worldbody.bodies[0].bodies[0].name
        'r_arm'

    """
    return attach_all(parent, [(child, prefix)], at=at)


def attach_all(
    parent: Mujoco, children: Iterable[tuple[Mujoco, str]], *, at: str | None = None
) -> Mujoco:
    """The parent with each ``(child, prefix)`` attached in turn, in one pass.

    The same as calling :func:`attach` for each child, but the parent's names and
    sections are read once, so attaching N children costs time linear in N.

    Example:
        >>> from serializers import loads
        >>> cup = loads('<mujoco><worldbody><body name="cup"/></worldbody></mujoco>')
        >>> scene = attach_all(loads("<mujoco/>"), [(cup, f"c{i}_") for i in range(3)])
        >>> [b.name for b in scene.worldbody.bodies]
        ['c0_cup', 'c1_cup', 'c2_cup']

    """
    for element, key, _ in keyed_walk(parent):
        refuse_opaque(element, key, "attach")
    composer = _Composer(parent, at)
    for child, prefix in children:
        composer.add(child, prefix)
    return composer.result()


class _Composer:
    """The parent being composed: its sections, names and what is to be appended."""

    def __init__(self, parent: Mujoco, at: str | None) -> None:
        self.parent = parent
        self.sections: list[Node] = list(parent.children)
        self.declared: dict[str, set[str]] = {
            namespace: set(names) for namespace, names in declared_names(parent).items()
        }
        self.assets: set[AnyElement] = {
            e for section in _sections(parent, "asset") for e in _elements(section)
        }
        self.pending: dict[str, list[Node]] = {}
        self.names: dict[int, tuple[Mujoco, dict[str, frozenset[str]]]] = {}
        self.world: list[Node] = []
        self.keys: list[Node] | None = None
        self.target: AnyElement | None = None
        if at is not None:
            self.target = find(parent, "body", name=at)
            if self.target is None:
                found = (get_attribute(b, "name") for b in find_all(parent, "body"))
                names = sorted(str(name) for name in found if name)
                raise MjcfLookupError(
                    f"the parent has no body named {at!r}; its bodies are {names}"
                )

    def add(self, child: Mujoco, prefix: str) -> None:
        names = self._names_of(child)
        if prefix:
            child = prefixed_declared(child, prefix, names)  # type: ignore[assignment]
            names = {ns: frozenset(prefix + n for n in found) for ns, found in names.items()}
        _check_compilers(
            _sections(self.parent, "compiler") or self.pending.get("compiler", []), child
        )
        child_assets = [e for section in _sections(child, "asset") for e in _elements(section)]
        shared = {e for e in child_assets if e in self.assets}
        theirs = {ns: set(found) for ns, found in names.items()}
        for asset in shared:
            for _, namespace, name in declarations(asset, f"asset/{asset.tag}"):
                theirs.get(namespace, set()).discard(name)
        _check_collisions(self.declared, theirs)
        for namespace, found in theirs.items():
            self.declared.setdefault(namespace, set()).update(found)
        self.assets.update(child_assets)
        if _keys_of(self.parent) or _keys_of(child):
            self._merge_keys(child)
        main = self._add_defaults(child, prefix)
        for tag in _SETTINGS:
            if not _sections(self.parent, tag) and not self.pending.get(tag):
                self.pending[tag] = list(_sections(child, tag))
        for tag in _LISTS:
            nodes = _section_children(child, tag)
            if tag == "asset":
                nodes = [n for n in nodes if n not in shared]
            if main is not None and tag in _CLASSED_SECTIONS:
                nodes = _classed(nodes, main, tag)
            self.pending.setdefault(tag, []).extend(nodes)
        world = _section_children(child, "worldbody")
        if main is not None:
            world = _classed(world, main, "body")
        self.world.extend(world)

    def _names_of(self, child: Mujoco) -> dict[str, frozenset[str]]:
        """The names ``child`` declares, read once per child model (includes refused)."""
        cached = self.names.get(id(child))
        if cached is None or cached[0] is not child:
            for element, key, _ in keyed_walk(child):
                refuse_opaque(element, key, "attach")
            cached = self.names[id(child)] = (child, declared_names(child))
        return cached[1]

    def _add_defaults(self, child: Mujoco, prefix: str) -> Default | None:
        """Add the child's defaults; return the class its top-level settings became, if any."""
        defaults = _sections(child, "default")
        added: list[Node] = [n for d in defaults for n in d.children]
        main = None
        if any(_has_settings(default) for default in defaults):
            if not prefix:
                raise MjcfValueError(
                    "the child's top-level defaults set values; attach it with a prefix so "
                    "they can become a class of their own"
                )
            main = Default(dclass=f"{prefix}main", children=_merged_settings(added))
            added = [main]
        self.pending.setdefault("default", []).extend(added)
        return main

    def _merge_keys(self, child: Mujoco) -> None:
        """Keyframes need the parent as composed so far: build it, then splice."""
        so_far = self.result()
        self.keys = merged_keyframes(so_far, child, _same(so_far, self.target))
        self.parent, self.sections = so_far, list(so_far.children)
        self.pending, self.world = {}, []
        if self.target is not None:
            self.target = _same(so_far, self.target)

    def result(self) -> Mujoco:
        sections = list(self.sections)
        for tag in ("default", *_SETTINGS, *_LISTS):
            nodes = self.pending.get(tag, [])
            if tag in _SETTINGS:
                sections.extend(nodes)
            elif nodes:
                _merge_into(sections, tag, nodes)
        if self.target is None:
            if self.world:
                _merge_into(sections, "worldbody", self.world)
        elif self.world:
            sections = [_inserted(c, self.target, self.world) for c in sections]
        if self.keys is not None:
            sections = [c for c in sections if getattr(c, "tag", None) != "keyframe"]
            if self.keys:
                sections.append(Keyframe(children=self.keys))
        return attrs.evolve(self.parent, children=sections)


def _keys_of(model: Mujoco) -> bool:
    return any(section.elements for section in _sections(model, "keyframe"))


def _same(model: Mujoco, target: AnyElement | None) -> AnyElement | None:
    """The body in ``model`` named like ``target`` (the target after the model was rebuilt)."""
    if target is None:
        return None
    return find(model, "body", name=get_attribute(target, "name"))


def _merge_into(sections: list[Node], tag: str, nodes: list[Node]) -> None:
    """Append ``nodes`` to the last ``tag`` section, or add a new section at the end."""
    for index in range(len(sections) - 1, -1, -1):
        section = sections[index]
        if isinstance(section, (TypedElement, GenericElement)) and section.tag == tag:
            sections[index] = with_children(section, [*section.children, *nodes])
            return
    sections.append(CLASS_BY_KEY[tag](children=nodes))


def _inserted(node: Node, target: AnyElement, nodes: list[Node]) -> Node:
    """``node`` with ``nodes`` appended to the children of ``target`` (found by identity)."""
    if node is target:
        assert isinstance(node, (TypedElement, GenericElement))
        return with_children(node, [*node.children, *nodes])
    if isinstance(node, (TypedElement, GenericElement)) and node.children:
        return with_children(node, [_inserted(c, target, nodes) for c in node.children])
    return node
