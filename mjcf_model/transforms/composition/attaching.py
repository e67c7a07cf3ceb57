"""Composing models: :func:`attach` merges one model into another, as MuJoCo would compile both.

The child's world is added to the parent's world (or inside one of its bodies),
and everything else follows: assets, default classes, actuators, sensors,
tendons, equality constraints, contacts, custom data, deformables, plugins and
keyframes. No wrapper body is added. Names the two models both declare are an
error (give the child a ``prefix``), except assets that are the same element in
both, which are kept once.

>>> from mjcf_model import dumps, loads
>>> world = loads('<mujoco><worldbody><geom name="floor" type="plane" size="1 1 1"/>'
...               '</worldbody></mujoco>')
>>> cube = loads('<mujoco><worldbody><body name="cube"><freejoint/><geom size=".1"/></body>'
...              '</worldbody></mujoco>')
>>> scene = attach(attach(world, cube, prefix="a_"), cube, prefix="b_")
>>> [body.name for body in scene.worldbody.bodies]
['a_cube', 'b_cube']
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import cast

import attrs

from mjcf_model.files.provenance import Folders, relocated
from mjcf_model.nodes.base import (
    AnyElement,
    Node,
)
from mjcf_model.nodes.default import Default
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers.skins import inline_skin_files
from mjcf_model.transforms.composition.conventions import in_conventions
from mjcf_model.transforms.composition.defaults import classed, merged_settings, sets_values
from mjcf_model.transforms.composition.keyframes import (
    KeyframePolicy,
    PartStates,
    SceneKeys,
    adds_state,
    attach_pose,
    check_policy,
    has_keys,
    keys_of,
)
from mjcf_model.transforms.composition.main_defaults import CLASSED_SECTIONS, with_main_as_class
from mjcf_model.transforms.composition.part_states import IDENTITY, Pose
from mjcf_model.transforms.composition.places import (
    AttachKind,
    Where,
    attach_point,
    placement_frame,
    wrapped,
)
from mjcf_model.transforms.composition.sections import (
    LISTS,
    SETTINGS,
    by_tag,
    check_collisions,
    dropped_settings,
    inserted,
    merged_into,
    warn_dropped,
    with_keys,
)
from mjcf_model.transforms.composition.shared_assets import shared_assets
from mjcf_model.transforms.naming.renaming import declarations, declared_names, prefixed_declared
from mjcf_model.transforms.naming.repeated import RepeatedPrefixing
from mjcf_model.tree.traversal import keyed_walk, refuse_opaque, with_children

__all__ = ["AttachKind", "attach", "attach_all", "attach_in_frame"]


def attach(
    parent: Mujoco,
    child: Mujoco,
    *,
    at: str | None = None,
    prefix: str = "",
    at_kind: AttachKind | None = None,
    pos: Iterable[float] | None = None,
    quat: Iterable[float] | None = None,
    euler: Iterable[float] | None = None,
    keyframes: KeyframePolicy = "separate",
    share_assets: bool = False,
) -> Mujoco:
    """The parent model with the child model merged into it.

    Args:
        parent: The model to add to.
        child: The model added; with ``prefix``, every name it declares is prefixed first.
        at: The name of the parent body, frame or site the child's world goes to
            (default: the world). At a body, the child's world is added to the
            body's children; at a frame or a site, it is placed at that frame or
            site, in the body that holds it, as MuJoCo's ``MjSpec`` attaches there.
        prefix: Prepended to the child's names (see :func:`mjcf_model.prefixed`).
        at_kind: ``"body"``, ``"frame"`` or ``"site"``: which kind of element
            ``at`` names, needed only when the parent has several kinds by that name.
        pos: Where the child's world (its root bodies, frames, geoms and sites)
            is placed, relative to the attach point (default: at it).
        quat: The orientation of the child's world relative to the attach point,
            as a quaternion (w, x, y, z).
        euler: The same as Euler angles instead of ``quat``, read with the
            parent's ``<compiler>`` ``angle`` units and ``eulerseq``.
        keyframes: ``"separate"`` keeps the child's keys as keys of their own
            (under their prefixed names); ``"merged"`` makes a child key whose name
            (before prefixing) a parent key has part of that key, so one ``home``
            sets every part; unnamed keys merge by their place among the unnamed
            keys (the child's first with the parent's first), and a merged key keeps
            the parent's ``time`` unless that is zero.
        share_assets: Keep once each named asset (mesh, texture, height field, skin,
            material) that repeats another but for its name, and point every
            reference at the one kept
            (:mod:`mjcf_model.transforms.composition.shared_assets`): a scene of N
            copies of a robot then loads each mesh once. Off by default,
            as ``MjSpec`` attaches: the repeats' names (``b_link0``) are gone from
            the result, and code that looks them up by name would not find them.

    At a frame or a site the child's world is appended to the body holding it
    (or the world), inside unnamed ``<frame>`` elements that copy the pose of
    every frame enclosing the target within that body, then the site's pose
    (``pos`` and orientation as the site compiles them, read through its default
    classes; orientation attributes are kept as written, so they are read in the
    parent's units), then ``pos``/``quat``/``euler``. MuJoCo compiles these
    frames to the same poses ``MjSpec`` gives (``spec.attach(child, site=...)``,
    ``site.attach_body``, ``frame.attach_body``), and the child's bodies and
    geoms come last in that body, in ``MjSpec``'s order. Where a ``childclass``
    of the parent reaches the attach point, the innermost frame sets
    ``childclass="main"`` so that the child's elements do not take the parent
    body's class (``MjSpec`` keeps them in the child's own classes).

    The parent keeps its ``<compiler>`` (the child is converted into it),
    ``<option>``, ``<size>``, ``<statistic>`` and ``<visual>``. Top-level default
    settings stay with their model: the child's become a class ``<prefix>main``
    (``child_main`` without prefix), the parent's a class ``parent_main``
    (:mod:`mjcf_model.transforms.composition.main_defaults`), named by the elements they reach.
    Keyframes follow the placement. Every key of the result is written whole
    (:mod:`mjcf_model.transforms.composition.keyframes`): a part's own key holds
    the part's state as the part alone defines it (MuJoCo completing a short
    key), moved by the pose the part is attached at, so a free joint's
    position and orientation and a mocap body's pose move with the part (a
    free joint's linear velocity turns with it; hinge, slide and ball values,
    ``ctrl``, ``act`` and ``time`` are kept); every other part's entries are
    its initial state as placed (``qpos0``, a free body where it was placed,
    no velocity, control or activation). Those states are read from each part
    compiled alone, so with keyframes each part must compile on its own.

    Raises:
        MjcfValueError: on a name collision, a child ``<compiler>`` setting whose
            meaning cannot be kept under the parent's (the message names it; see
            :mod:`mjcf_model.transforms.composition.conventions`), a kept
            ``<include>``, a keyframe that cannot be completed, both ``quat`` and
            ``euler``, a vector of the wrong length, a target inside a
            ``<replicate>``, a site placed by ``fromto``, or, with keyframes, a
            part whose free joints or mocap bodies would not be at the top level
            (MuJoCo's rule: attach such a part at the world, or at a frame or a
            site of the world body).
        MjcfCompileError: With keyframes, a part that does not compile alone.
        MjcfLookupError: when the parent has no body, frame or site named ``at``
            (the message lists those it has), or several kinds by that name and
            no ``at_kind``.

    Examples:
        >>> from mjcf_model import Body, Geom, Mujoco, Site, Worldbody
        >>> arm_body = Body(name="arm", children=[Geom(size=[1])])
        >>> arm = Mujoco(children=[Worldbody(children=[arm_body])])
        >>> table = Mujoco(children=[Worldbody(children=[Body(name="table")])])
        >>> attach(table, arm, at="table", prefix="r_").worldbody.bodies[0].bodies[0].name
        'r_arm'

        A gripper at the hand's site, turned a quarter about the site's z axis:

        >>> from mjcf_model import dumps
        >>> hand = Body(name="hand", children=[Site(name="tool", pos=[0, 0, 0.1])])
        >>> robot = Mujoco(children=[Worldbody(children=[hand])])
        >>> gripper = Mujoco(children=[Worldbody(children=[Body(name="palm")])])
        >>> turn = [0.7071068, 0, 0, 0.7071068]
        >>> scene = attach(robot, gripper, at="tool", prefix="g_", quat=turn)
        >>> print(dumps(scene.worldbody), end="")
        <worldbody>
          <body name="hand">
            <site name="tool" pos="0 0 0.1"/>
            <frame pos="0 0 0.1">
              <frame quat="0.7071068 0 0 0.7071068">
                <body name="g_palm"/>
              </frame>
            </frame>
          </body>
        </worldbody>

    """
    return attach_all(
        parent,
        [(child, prefix)],
        at=at,
        at_kind=at_kind,
        pos=pos,
        quat=quat,
        euler=euler,
        keyframes=keyframes,
        share_assets=share_assets,
    )


def attach_all(
    parent: Mujoco,
    children: Iterable[tuple[Mujoco, str]],
    *,
    at: str | None = None,
    at_kind: AttachKind | None = None,
    pos: Iterable[float] | None = None,
    quat: Iterable[float] | None = None,
    euler: Iterable[float] | None = None,
    keyframes: KeyframePolicy = "separate",
    share_assets: bool = False,
) -> Mujoco:
    """The parent with each ``(child, prefix)`` attached in turn, in one pass.

    The same as calling :func:`attach` for each child (with the same ``at``,
    ``at_kind``, placement and ``share_assets``), but the parent's names and sections
    are read once, so attaching N children costs time linear in N.

    Examples:
        >>> from mjcf_model import loads
        >>> cup = loads('<mujoco><worldbody><body name="cup"/></worldbody></mujoco>')
        >>> scene = attach_all(loads("<mujoco/>"), [(cup, f"c{i}_") for i in range(3)])
        >>> [b.name for b in scene.worldbody.bodies]
        ['c0_cup', 'c1_cup', 'c2_cup']

    """
    where = Where(at, at_kind, placement_frame(pos, quat, euler))
    composed = _composed(parent, children, where, check_policy(keyframes))
    return shared_assets(composed) if share_assets else composed


def attach_in_frame(parent: Mujoco, child: Mujoco, *, frame: str, prefix: str = "") -> Mujoco:
    """The parent with the child's world inside its frame ``frame``, where that frame stands.

    As :func:`attach`, but the child's world keeps the frame's place in document
    order (MuJoCo's numbering) among its siblings, as MuJoCo's ``<attach>`` does.

    Examples:
        >>> from mjcf_model import loads
        >>> parent = loads('<mujoco><worldbody><body name="a"/><frame name="here"/>'
        ...                '<body name="z"/></worldbody></mujoco>')
        >>> cup = loads('<mujoco><worldbody><body name="cup"/></worldbody></mujoco>')
        >>> from mjcf_model.tree.queries import find_all
        >>> scene = attach_in_frame(parent, cup, frame="here", prefix="c_")
        >>> [b.name for b in find_all(scene, "body")]
        ['a', 'c_cup', 'z']

    """
    return _composed(parent, [(child, prefix)], Where(frame, "frame", None, inside=True))


def _composed(
    parent: Mujoco,
    children: Iterable[tuple[Mujoco, str]],
    where: Where,
    policy: KeyframePolicy = "separate",
) -> Mujoco:
    for element, key, _ in keyed_walk(parent):
        refuse_opaque(element, key, "attach")
    composer = _Composer(parent, where, policy)
    for child, prefix in children:
        composer.add(child, prefix)
    return composer.result()


class _Composer:
    """The parent being composed: its sections, names and what is to be appended."""

    def __init__(self, parent: Mujoco, where: Where, policy: KeyframePolicy) -> None:
        self.declared: dict[str, set[str]] = {
            namespace: set(names) for namespace, names in declared_names(parent).items()
        }
        main = self._new_class("parent_main")
        if (demoted := with_main_as_class(parent, main)) is not parent:
            parent = demoted
            self.declared.setdefault("class", set()).add(main)
        self._set_parent(parent)
        #: Every asset so far, with the number of the model that brought it (0: the parent).
        self.assets: dict[AnyElement, int] = {
            e: 0 for section in by_tag(parent).get("asset", ()) for e in section.elements
        }
        #: How many children were added.
        self.added = 0
        self.pending: dict[str, list[Node]] = {}
        self.names: dict[int, tuple[Mujoco, RepeatedPrefixing, dict[str, frozenset[str]]]] = {}
        self.world: list[Node] = []
        #: The scene's keys, once a part brings or meets keyframes.
        self.scene_keys: SceneKeys | None = None
        #: Where the children are placed in world coordinates, once keys need it.
        self.pose: Pose | None = None
        self.policy = policy
        self.where = where
        self.point = attach_point(parent, where)

    def add(self, child: Mujoco, prefix: str) -> None:
        original = child
        copies, names = self._prepared(child)
        child = cast(Mujoco, copies.prefixed(prefix) if prefix else copies.model)
        theirs = {ns: {prefix + n for n in found} for ns, found in names.items()}
        if self.policy == "merged":  # keys of one name become one key: not a clash
            theirs.pop("key", None)
        sections = by_tag(child)
        child_assets = [e for section in sections.get("asset", ()) for e in section.elements]
        self.added += 1
        shared: list[AnyElement] = []
        for asset in child_assets:  # kept once when an earlier model has it (one hash each)
            if self.assets.setdefault(asset, self.added) != self.added:
                shared.append(asset)
        for asset in shared:
            key, folder = f"asset/{asset.tag}", self.parent.base_dir  # the paths are rebased
            for _, namespace, name in declarations(asset, key, base_dir=folder):
                theirs.get(namespace, set()).discard(name)
        check_collisions(self.declared, theirs)
        for namespace, found in theirs.items():
            self.declared.setdefault(namespace, set()).update(found)
        keys = self.scene_keys is not None or self.parent_keys or has_keys(child)
        if keys and adds_state(child):
            self._merge_keys(original, child)
        main = self._add_defaults(sections.get("default", []), prefix)
        for tag in SETTINGS:
            if tag not in self.parent_tags and not self.pending.get(tag):
                self.pending[tag] = list(sections.get(tag, ()))
            elif tag in sections:
                held = self.pending.get(tag) or by_tag(self.parent).get(tag, [])
                warn_dropped(dropped_settings(held, sections[tag]), prefix)
        kept = {id(asset) for asset in shared}
        for tag in LISTS:
            nodes = [node for section in sections.get(tag, ()) for node in section.children]
            if kept and tag == "asset":
                nodes = [n for n in nodes if id(n) not in kept]
            if main is not None and tag in CLASSED_SECTIONS:
                nodes = classed(nodes, main, tag)
            self.pending.setdefault(tag, []).extend(nodes)
        world = [node for section in sections.get("worldbody", ()) for node in section.children]
        if main is not None:
            world = classed(world, main, "body")
        self.world.extend(world)

    def _set_parent(self, parent: Mujoco) -> None:
        """Compose onto ``parent``: its sections, and what :meth:`add` asks of them."""
        self.parent = parent
        self.sections: list[Node] = list(parent.children)
        #: The tags of the parent's sections.
        self.parent_tags = set(by_tag(parent))
        #: Whether the parent has keyframes (then every child is merged key by key).
        self.parent_keys = has_keys(parent)

    def _in_parent_terms(self, child: Mujoco) -> Mujoco:
        """The child with its paths and values meaning under the parent's ``<compiler>``.

        File paths are rewritten to name the child's files from the parent's folder
        (:func:`mjcf_model.files.provenance.relocated`); angles, limits and inertia are
        converted (:func:`mjcf_model.transforms.composition.conventions.in_conventions`).
        """
        child = relocated(child, self.parent.base_dir, Folders.of(self.parent))
        return in_conventions(child, self.parent)

    def _prepared(self, child: Mujoco) -> tuple[RepeatedPrefixing, dict[str, frozenset[str]]]:
        """The child ready to be renamed, and the names it declares; once per child model.

        Includes are refused. Skins read from ``.skn`` files name their bodies inside
        the file, so renaming would lose them: they are written inline first, from
        the child's folder. Then the child is put in the parent's terms (the same
        for every copy of it, so attaching one model N times converts it once, and
        plans its prefixing once:
        :class:`~mjcf_model.transforms.naming.repeated.RepeatedPrefixing`).
        """
        cached = self.names.get(id(child))
        if cached is None or cached[0] is not child:
            for element, key, _ in keyed_walk(child):
                refuse_opaque(element, key, "attach")

            ready = self._in_parent_terms(inline_skin_files(child))
            names = declared_names(ready)
            copies = RepeatedPrefixing(
                ready, lambda node, prefix: prefixed_declared(node, prefix, names)
            )
            cached = self.names[id(child)] = (child, copies, names)
        return cached[1], cached[2]

    def _add_defaults(self, defaults: list[AnyElement], prefix: str) -> Default | None:
        """Add the child's defaults; return the class its top-level settings became, if any."""
        added: list[Node] = [n for d in defaults for n in d.children]
        main = None
        if any(sets_values(default) for default in defaults):
            name = f"{prefix}main" if prefix else self._new_class("child_main")
            self.declared.setdefault("class", set()).add(name)
            main = Default(dclass=name, children=merged_settings(defaults))
            added = [main]
        self.pending.setdefault("default", []).extend(added)
        return main

    def _new_class(self, wanted: str) -> str:
        """``wanted``, or ``wanted_2``, ``wanted_3``... : a class name nobody declares yet."""
        taken = self.declared.get("class", set())
        name, count = wanted, 1
        while name in taken:
            count += 1
            name = f"{wanted}_{count}"
        return name

    def _merge_keys(self, original: Mujoco, child: Mujoco) -> None:
        """Add the child's entries and keys to the scene's keys (read once from the parent)."""
        if self.scene_keys is None:
            so_far = self.result()
            self.point = attach_point(so_far, self.where)
            holder = None if self.point is None else self.point.holder
            self.scene_keys = SceneKeys.of(so_far, holder)
            self._set_parent(so_far)
            self.pending, self.world = {}, []
        part = PartStates.of(original)
        pose = IDENTITY  # each part is checked: only one with free joints or mocap bodies moves
        if part.moves_with_placement:
            if self.pose is None:
                self.pose = attach_pose(self.parent, self.point, self.where.at, part)
            pose = self.pose
        self.scene_keys.add(part, keys_of(original), keys_of(child), pose, self.policy)
        if self.policy == "merged":
            self.declared.setdefault("key", set()).update(self.scene_keys.names)

    def result(self) -> Mujoco:
        sections = list(self.sections)
        for tag in ("default", *SETTINGS, *LISTS):
            nodes = self.pending.get(tag, [])
            if tag in SETTINGS:
                sections.extend(nodes)
            elif nodes:
                merged_into(sections, tag, nodes)
        world = wrapped(self.point.frames, self.world) if self.point and self.world else []
        world = world or self.world
        holder = None if self.point is None else self.point.holder
        if holder is None:
            if world:
                merged_into(sections, "worldbody", world)
        elif world:
            sections = list(inserted(with_children(self.parent, sections), holder, world).children)
        if self.scene_keys is not None:
            sections = with_keys(sections, self.scene_keys.nodes())
        return attrs.evolve(self.parent, children=sections)
