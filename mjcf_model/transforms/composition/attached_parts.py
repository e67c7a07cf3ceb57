"""What MuJoCo's ``<attach>`` copies from a model: a subtree and what refers only to it.

``<attach model="m" body="b" prefix="p"/>`` copies the body ``b`` of the model
``m`` with its subtree (``frame="f"``, MuJoCo 4.0: the frame ``f`` with its
contents; neither: everything in ``m``'s world). Measured on MuJoCo 3.9 and 4.0:

* The body keeps its own pose; frames around it in ``m`` are dropped. Its
  elements keep the classes they have in ``m``, the ``childclass`` of an
  ancestor included.
* Every asset and default class of ``m`` is copied, used or not; ``m``'s
  ``<option>``, ``<size>``, ``<statistic>`` and ``<visual>`` are not.
* An element outside the tree (tendon, actuator, sensor, equality, contact pair
  or exclude, custom tuple, flex) is copied when everything it refers to in the
  tree is in the copied subtree (tendons and actuators it refers to: copied
  ones). An element that refers to nothing is copied too, except an empty tuple.
  A reference to the world body is kept by a sensor's ``refname`` and by an
  exclude that also names a copied body; by an equality or a tuple only on
  MuJoCo 4.0 (:func:`copies_world_references`). Any other is refused.
* Without ``model`` (MuJoCo 4.0), the body or frame is copied from the same
  model, with the elements outside the tree that refer to it and the sensors
  that refer to nothing; assets, default classes and custom numbers and texts
  are not copied.

:func:`attached_part` is that copy as a model of its own, ready for
:func:`mjcf_model.transforms.composition.attaching.attach_in_frame`; keyframes are
left out (MuJoCo fills each with the whole model's initial state, see
:mod:`mjcf_model.transforms.composition.inlining`).

>>> from mjcf_model import loads
>>> arm = loads('''<mujoco><worldbody><body name="base"><joint name="j0"/>
...   <body name="hand"><joint name="j1"/><geom size="1"/></body></body></worldbody>
...   <actuator><motor joint="j0"/><motor joint="j1"/></actuator></mujoco>''')
>>> part = attached_part(arm, body="hand", frame=None, same_model=False)
>>> [b.name for b in part.worldbody.bodies], [m.joint for m in part.actuator.elements]
(['hand'], ['j1'])
"""

from __future__ import annotations

import functools
from collections.abc import Iterator, Sequence

import attrs

from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.nodes.base import AnyElement, Element, Node, get_attribute, with_attributes
from mjcf_model.nodes.body import Worldbody
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import SCHEMA, reference_namespace
from mjcf_model.transforms.naming.generated_names import GeneratedNames, declarations
from mjcf_model.tree.traversal import keyed_walk, with_children

__all__ = ["attached_part", "copies_world_references", "element_references"]

#: Sections of the child that are not copied.
_DROPPED = frozenset({"option", "size", "statistic", "visual", "keyframe"})
#: Sections a copy from the same model keeps (the others are already there).
_SAME_MODEL_SECTIONS = frozenset(
    {
        "compiler",
        "worldbody",
        "deformable",
        "tendon",
        "actuator",
        "sensor",
        "equality",
        "contact",
        "custom",
    }
)
#: Sections whose elements are copied only when what they refer to is, in the order in
#: which they are decided (a later one may refer to an earlier one's elements).
_FILTERED = ("deformable", "tendon", "actuator", "sensor", "equality", "contact", "custom")
#: Namespaces whose names must be copied for an element that refers to them to be.
_TREE = frozenset({"body", "joint", "geom", "site", "camera", "light", "frame", "flex"})
#: Namespaces of elements outside the tree that other elements refer to.
_DECIDED = frozenset({"flex", "skin", "tendon", "actuator", "sensor"})
#: The name of the world body.
_WORLD = "world"


def element_references(element: AnyElement, key: str | None) -> Iterator[tuple[str, str, str]]:
    """``(attribute, namespace, name)`` for each name ``element`` itself refers to.

    Examples:
        >>> from mjcf_model import Motor
        >>> list(element_references(Motor(joint="elbow"), "actuator/motor"))
        [('joint', 'joint', 'elbow')]

    """
    spec = SCHEMA.get(key) if key is not None else None
    if spec is None:
        return
    values = {attribute: get_attribute(element, attribute) for attribute in spec.references}
    selectors = {
        target[1:]: get_attribute(element, target[1:])
        for target in spec.references.values()
        if target.startswith("@")
    }
    for attribute, value in values.items():
        namespace = reference_namespace(spec, attribute, {**values, **selectors})
        if namespace is None or not isinstance(value, str) or not value:
            continue
        names = value.split() if attribute in spec.list_references else [value]
        for name in names:
            yield attribute, namespace, name


@functools.cache
def copies_world_references(section: str) -> bool:
    """Whether the installed MuJoCo copies an ``equality`` or ``custom`` tuple naming the world.

    MuJoCo 4.0 does, 3.9 does not; asked once of MuJoCo itself.

    Examples:
        >>> isinstance(copies_world_references("equality"), bool)
        True

    """
    import mujoco

    element = {
        "equality": '<equality><weld body1="b" body2="world"/></equality>',
        "custom": '<custom><tuple name="t"><element objtype="body" objname="world"/>'
        "</tuple></custom>",
    }[section]
    child = f'<mujoco><worldbody><body name="b"/></worldbody>{element}</mujoco>'
    parent = (
        '<mujoco><asset><model name="c" file="c.xml"/></asset>'
        '<worldbody><attach model="c" body="b" prefix="p"/></worldbody></mujoco>'
    )
    compiled = mujoco.MjModel.from_xml_string(parent, {"c.xml": child.encode()})
    return bool(compiled.neq if section == "equality" else compiled.ntuple)


def _world_reference(key: str, attribute: str) -> bool:
    """Whether MuJoCo keeps an element whose ``attribute`` names the world body."""
    section = key.partition("/")[0]
    if section == "sensor":
        return attribute == "refname"
    if key == "contact/exclude":
        return True
    if section in ("equality", "custom"):
        return copies_world_references(section)
    raise MjcfValueError(
        f"cannot expand an <attach> whose model has <{key.rpartition('/')[2]} "
        f'{attribute}="world">: whether MuJoCo copies it is not known; refer to a body instead'
    )


class _Copied:
    """The names a copy holds, by namespace, and the generators of the names MuJoCo makes."""

    def __init__(self, tree: Worldbody) -> None:
        self.names: dict[str, set[str]] = {}
        for element, key, _ in keyed_walk(tree):
            for _, namespace, name in declarations(element, key):
                self.names.setdefault(namespace, set()).add(name)
        self.generated = GeneratedNames.of(tree)

    def holds(self, namespace: str, name: str) -> bool:
        if name in self.names.get(namespace, ()):
            return True
        return namespace in _TREE and self.generated.source(namespace, name) is not None

    def kept(self, element: AnyElement, key: str, same_model: bool) -> bool:
        """Whether MuJoCo copies ``element`` (outside the tree, ``key`` its schema key)."""
        refers = False  # to something copied (the world counts, but not in an exclude)
        for inner, inner_key, _ in keyed_walk(element, key.rpartition("/")[0]):
            for attribute, namespace, name in element_references(inner, inner_key):
                if namespace not in _TREE | _DECIDED:
                    continue
                if namespace == "body" and name == _WORLD and inner_key is not None:
                    if not _world_reference(inner_key, attribute):
                        return False
                    refers = refers or key != "contact/exclude"
                elif self.holds(namespace, name):
                    refers = True
                else:
                    return False
        if key in ("custom/tuple", "contact/exclude") or (same_model and key.startswith("custom/")):
            return refers
        return True

    def add(self, element: AnyElement, key: str) -> None:
        for _, namespace, name in declarations(element, key):
            self.names.setdefault(namespace, set()).add(name)


def _located(child: Mujoco, key: str, name: str) -> tuple[AnyElement, Sequence[AnyElement]]:
    """The body or frame ``name`` of ``child`` and its ancestors; errors list what exists."""
    names = []
    for element, found, ancestors in keyed_walk(child):
        if found != key or not isinstance(element_name := get_attribute(element, "name"), str):
            continue
        if element_name == name:
            if any(a.tag == "replicate" for a in ancestors):
                raise MjcfValueError(
                    f"cannot expand <attach {key.rpartition('/')[2]}={name!r}>: it is inside "
                    "a <replicate>, whose copies have other names"
                )
            return element, ancestors
        names.append(element_name)
    kind = "body" if key == "body" else "frame"
    raise MjcfLookupError(
        f"the attached model has no {kind} named {name!r}; its {kind}s are {sorted(names)}"
    )


def _with_inherited_class(target: AnyElement, ancestors: Sequence[AnyElement]) -> AnyElement:
    """``target`` naming the ``childclass`` it inherits in its model, if it names none."""
    if get_attribute(target, "childclass") is not None:
        return target
    for ancestor in reversed(ancestors):
        inherited = get_attribute(ancestor, "childclass")
        if inherited is not None:
            return with_attributes(target, {"childclass": inherited})
    return target


def _kept_outside_the_tree(
    sections: Sequence[Node], copied: _Copied, same_model: bool
) -> dict[int, list[Node]]:
    """The children MuJoCo copies of each filtered section, by the section's index."""
    kept: dict[int, list[Node]] = {}
    for tag in _FILTERED:
        for index, section in enumerate(sections):
            if not isinstance(section, Element) or section.tag != tag:
                continue
            children: list[Node] = []
            for node in section.elements:
                key = f"{tag}/{node.tag}"
                if copied.kept(node, key, same_model):
                    children.append(node)
                    copied.add(node, key)
            kept[index] = children
    return kept


def attached_part(
    child: Mujoco, *, body: str | None, frame: str | None, same_model: bool
) -> Mujoco:
    """``child`` reduced to what ``<attach body=... frame=...>`` copies from it.

    Args:
        child: The attached model (its own ``<attach>`` elements already expanded).
        body: The body copied with its subtree (``None``: see ``frame``).
        frame: The frame copied with its contents (``None`` and no ``body``: the
            whole world).
        same_model: Whether ``child`` is the model that holds the ``<attach>``
            (no ``model`` attribute): only the tree and what refers to it are kept.

    Raises:
        MjcfLookupError: ``child`` has no such body or frame.
        MjcfValueError: Both ``body`` and ``frame`` are given, the body or frame
            is inside a ``<replicate>``, or an element refers to the world body
            in a way whose copying is not known.

    Examples:
        >>> from mjcf_model import loads
        >>> cup = loads('<mujoco><option timestep="0.1"/><worldbody><body name="cup"/>'
        ...             '</worldbody></mujoco>')
        >>> [s.tag for s in attached_part(cup, body=None, frame=None, same_model=False).elements]
        ['worldbody']

    """
    if body is not None and frame is not None:
        raise MjcfValueError("an <attach> names a body or a frame, not both")
    worlds = [s for s in child.elements if s.tag == "worldbody"]
    world = Worldbody(children=[n for w in worlds for n in w.children])
    if body is not None or frame is not None:
        key, name = ("body", body) if body is not None else ("body/frame", frame)
        assert name is not None
        target, ancestors = _located(child, key, name)
        world = Worldbody(children=[_with_inherited_class(target, ancestors)])
    sections = list(child.children)
    kept = _kept_outside_the_tree(sections, _Copied(world), same_model)
    result: list[Node] = []
    for index, section in enumerate(sections):
        section_tag = getattr(section, "tag", None)
        if section_tag in _DROPPED or (same_model and section_tag not in _SAME_MODEL_SECTIONS):
            continue
        if section_tag == "worldbody" and (body is not None or frame is not None):
            if section is not worlds[0]:
                continue
            section = world
        elif index in kept:
            assert isinstance(section, Element)
            section = with_children(section, kept[index])
        result.append(section)
    return attrs.evolve(child, children=result)
