"""Names: which a model declares, and renaming or prefixing them with every reference.

Everything here reads the namespace table (:mod:`mjcf_model.schema.namespaces`), so a
body, a mesh, a default class and a keyframe are renamed by the same code, and
every attribute that refers to them follows: ``geom mesh``, ``childclass``,
sensor ``objname`` (in the namespace its ``objtype`` names), flex ``body`` lists.

Assets read from a file without a ``name`` (meshes, textures, height fields,
skins) have the file's stem as their name in MuJoCo; an asset ``<model>`` has
the ``model`` attribute of its file's root instead (read from the file, found
through the model's ``base_dir``). Renaming one writes the new name explicitly.

Names MuJoCo makes while reading (``<replicate>`` copies, ``<flexcomp>`` bodies,
``<attach>`` prefixes) follow the name or prefix they are made from, and so do
references to them: see :mod:`mjcf_model.transforms.naming.generated_names`. An ``<attach>``
without ``model`` copies a body or frame of the same model, so its ``body`` and
``frame`` are renamed with that model's names. A skin read from a file names its
bones' bodies inside the file: renaming bodies then raises, saying to write the
skin inline first.

>>> from mjcf_model import dumps, loads
>>> model = loads('''<mujoco><worldbody><body name="arm"><joint name="elbow"/></body></worldbody>
... <actuator><motor joint="elbow" name="m"/></actuator></mujoco>''')
>>> print(dumps(prefixed(model, "left_"), canonical=True), end="")
<mujoco>
  <worldbody>
    <body name="left_arm">
      <joint name="left_elbow"/>
    </body>
  </worldbody>
  <actuator>
    <motor joint="left_elbow" name="left_m"/>
  </actuator>
</mujoco>
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable, Mapping, Sequence
from pathlib import Path
from typing import cast

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, get_attribute, with_attributes
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import NAMESPACES, SCHEMA, ElementSpec, reference_namespace
from mjcf_model.serializers.skins import inline_skin_files
from mjcf_model.transforms.naming.generated_names import (
    DECLARING_KEYS,
    MAIN_CLASS,
    SAME_MODEL_ATTACH,
    GeneratedNames,
    declarations,
)
from mjcf_model.tree.queries import attribute_reader
from mjcf_model.tree.traversal import (
    GUESS,
    SKIN_KEYS,
    keyed_walk,
    map_elements,
    refuse_file_skin,
    refuse_opaque,
)
from mjcf_model.values import Value

__all__ = [
    "ALL",
    "declarations",
    "declared_names",
    "prefix_map",
    "prefixed",
    "prefixed_declared",
    "renamed",
]

#: Every namespace, the default of ``namespaces=`` arguments.
ALL: frozenset[str] = NAMESPACES

#: Skins, which may read the bodies of their bones from a file.

#: ``rename(namespace, name)``: the new name, or the same one to keep it.
Renamer = Callable[[str, str], str]


def declared_names(node: AnyElement) -> dict[str, frozenset[str]]:
    """The names ``node`` and its descendants declare, by namespace.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><asset><mesh file="parts/hand.stl"/></asset>'
        ...               '<worldbody><body name="b"><geom name="g"/></body></worldbody></mujoco>')
        >>> sorted(declared_names(model).items())
        [('body', frozenset({'b'})), ('geom', frozenset({'g'})), ('mesh', frozenset({'hand'}))]

    """
    found: dict[str, set[str]] = {}
    base_dir = node.base_dir if isinstance(node, Mujoco) else None
    for element, key, _ in keyed_walk(node):
        if key in DECLARING_KEYS:
            plan = _PLANS[key]
            for _, namespace, name in _declared(element, key, plan, base_dir, plan.values(element)):
                found.setdefault(namespace, set()).add(name)
    return {namespace: frozenset(names) for namespace, names in found.items()}


def _checked_namespaces(namespaces: Collection[str]) -> frozenset[str]:
    chosen = frozenset(namespaces)
    unknown = chosen - NAMESPACES
    if unknown:
        raise MjcfValueError(
            f"unknown namespace(s) {sorted(unknown)}; the namespaces are {sorted(NAMESPACES)}"
        )
    return chosen


def _excluder(exclude: Callable[[str], bool] | Collection[str] | None) -> Callable[[str], bool]:
    if exclude is None:
        return lambda name: False
    if callable(exclude):
        return exclude
    names = frozenset(exclude)
    return names.__contains__


def prefix_map(
    node: AnyElement,
    prefix: str,
    *,
    namespaces: Collection[str] = ALL,
    exclude: Callable[[str], bool] | Collection[str] | None = None,
) -> dict[str, dict[str, str]]:
    """The renaming :func:`prefixed` applies: namespace to old name to new name.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> prefix_map(Body(name="b", children=[Geom(name="g")]), "p_", exclude={"g"})
        {'body': {'b': 'p_b'}}

    """
    chosen = _checked_namespaces(namespaces)
    excluded = _excluder(exclude)
    return {
        namespace: {name: prefix + name for name in sorted(names) if not excluded(name)}
        for namespace, names in declared_names(node).items()
        if namespace in chosen and any(not excluded(name) for name in names)
    }


class _Plan:
    """What renaming reads on the elements of one schema key, worked out once per key."""

    __slots__ = (
        "count",
        "declared",
        "declares",
        "names",
        "namespaces",
        "readers",
        "references",
        "spec",
    )

    def __init__(self, spec: ElementSpec) -> None:
        #: The table's entry.
        self.spec = spec
        #: Whether the element declares a name.
        self.declares = bool(spec.declares)
        #: The attributes that declare names, read at once, how many, and the namespace of each.
        self.declared = tuple(spec.declares)
        self.count = len(self.declared)
        self.namespaces = tuple(spec.declares.values())
        #: The reference attributes, read at once.
        self.names = tuple(spec.references)
        #: Per reference: its namespace (``None`` when an ``objtype``-style attribute
        #: names it), that attribute, and whether it holds a list of names.
        self.references = tuple(
            (
                None if target.startswith("@") else target,
                target[1:] if target.startswith("@") else None,
                attribute in spec.list_references,
            )
            for attribute, target in spec.references.items()
        )
        #: Per element class: what reads the declaring, then the reference attributes.
        self.readers: dict[type, Callable[[AnyElement], tuple[Value | None, ...]]] = {}

    def values(self, element: AnyElement) -> tuple[Value | None, ...]:
        """The declaring attributes' values, then the references', of ``element``."""
        reader = self.readers.get(element.__class__)
        if reader is None:
            reader = attribute_reader(element.__class__, self.declared + self.names)
            self.readers[element.__class__] = reader
        return reader(element)


#: The plan of each schema key that declares or refers to a name.
_PLANS = {key: _Plan(spec) for key, spec in SCHEMA.items() if spec.declares or spec.references}
_SAME_MODEL_PLAN = _Plan(SAME_MODEL_ATTACH)

#: The keys of elements renaming leaves alone when they have no children.
_NOTHING_TO_RENAME = frozenset(SCHEMA) - _PLANS.keys() - SKIN_KEYS - {"include", "body/attach"}


def _declared(
    element: AnyElement,
    key: str | None,
    plan: _Plan,
    base_dir: Path | None,
    values: tuple[Value | None, ...],
) -> Iterable[tuple[str, str, str]]:
    """``declarations(element, key)``, from ``values`` where every declaring attribute is written.

    ``values``: the element's :meth:`_Plan.values`. The names are then the attributes'
    values (but for ``<default class="main">``, which declares none); an element named
    after its file, or not named, takes the general rule.
    """
    count = plan.count
    if count == 1:  # nearly every element: one ``name``
        name = values[0]
        if type(name) is str and name:
            namespace = plan.namespaces[0]
            if name == MAIN_CLASS[0] and namespace == MAIN_CLASS[1]:
                return ()
            return ((plan.declared[0], namespace, name),)
        return declarations(element, key, base_dir=base_dir)
    names = values[:count]
    if all(type(name) is str and name for name in names):
        written = cast(tuple[str, ...], names)
        return [
            (attribute, namespace, name)
            for attribute, namespace, name in zip(plan.declared, plan.namespaces, written)  # noqa: B905
            if (name, namespace) != MAIN_CLASS
        ]
    return declarations(element, key, base_dir=base_dir)


def _renamed_attributes(
    element: AnyElement, key: str | None, rename: Renamer, follow: Renamer, base_dir: Path | None
) -> dict[str, Value | None]:
    """The attribute changes that rename what ``element`` declares and refers to.

    ``rename`` renames declared names, ``follow`` references (generated names too).
    """
    plan = _PLANS.get(key) if key is not None else None
    if plan is None:
        return {}
    if key == "body/attach" and get_attribute(element, "model") is None:
        plan = _SAME_MODEL_PLAN
    values = plan.values(element)
    changes: dict[str, Value | None] = {}
    if plan.declares:
        for attribute, namespace, name in _declared(element, key, plan, base_dir, values):
            new = rename(namespace, name)
            if new != name:
                changes[attribute] = new
    if not plan.names:
        return changes
    references = values[plan.count :]
    if references.count(None) == len(references):  # most elements refer to nothing
        return changes
    for attribute, value, (target, selector, listed) in zip(  # noqa: B905 (same lengths)
        plan.names, references, plan.references
    ):
        if type(value) is not str or not value:
            continue
        if selector is not None:
            target = reference_namespace(
                plan.spec, attribute, {selector: get_attribute(element, selector)}
            )
        if target is None:
            continue
        if listed:
            joined = " ".join(follow(target, part) for part in value.split())
            if joined != " ".join(value.split()):
                changes[attribute] = joined
        elif (renamed_value := follow(target, value)) != value:
            changes[attribute] = renamed_value
    return changes


def _apply(node: AnyElement, rename: Renamer, attach_prefix: str | None) -> AnyElement:
    """``node`` renamed by ``rename``; each ``<attach>`` prefix gains ``attach_prefix``."""
    base_dir = node.base_dir if isinstance(node, Mujoco) else None
    generators: list[GeneratedNames] = []

    def generated() -> GeneratedNames:
        if not generators:  # read only when a name is not renamed by ``rename`` itself
            generators.append(GeneratedNames.of(node, base_dir))
        return generators[0]

    def follow(namespace: str, name: str) -> str:
        new = rename(namespace, name)
        if new != name:
            return new
        return generated().renamed(namespace, name, follow, attach_prefix)

    def visit(element: AnyElement, key: str | None, _: Sequence[AnyElement]) -> AnyElement:
        if key is None or key == "include":
            refuse_opaque(element, key, "rename names in")
        if key in SKIN_KEYS and get_attribute(element, "file"):
            _refuse_file_skin(element, generated().renames_bodies(rename, attach_prefix))
        changes = _renamed_attributes(element, key, rename, follow, base_dir)
        if attach_prefix and key == "body/attach":
            inner = get_attribute(element, "prefix")
            changes["prefix"] = attach_prefix + (inner if isinstance(inner, str) else "")
        return with_attributes(element, changes)

    return map_elements(visit, node, GUESS, kept=_NOTHING_TO_RENAME)


def _refuse_file_skin(skin: AnyElement, renames_bodies: bool) -> None:
    """Raise when bodies are renamed while a skin names its bodies inside a file."""
    if renames_bodies:
        refuse_file_skin(
            skin,
            "rename the bodies of",
            "names the bodies its bones bind to, and MuJoCo would not find them",
        )


def renamed(
    node: AnyElement, mapping: Mapping[str, str] | Mapping[str, Mapping[str, str]]
) -> AnyElement:
    """A copy with names changed as ``mapping`` says, and every reference to them.

    ``mapping`` maps old names to new ones in every namespace, or maps namespace
    names (``"body"``, ``"mesh"``, ``"class"``...) to such maps. Names it does not
    mention, and references to them, stay.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(name="base", children=[Geom(name="base")])
        >>> new = renamed(body, {"geom": {"base": "base_geom"}})
        >>> new.name, new.geoms[0].name
        ('base', 'base_geom')

    """
    if not mapping:
        return node
    if all(isinstance(value, str) for value in mapping.values()):
        flat: Mapping[str, str] = mapping  # type: ignore[assignment]

        def rename(namespace: str, name: str) -> str:
            return flat.get(name, name)
    else:
        nested: Mapping[str, Mapping[str, str]] = mapping  # type: ignore[assignment]
        _checked_namespaces(nested)

        def rename(namespace: str, name: str) -> str:
            return nested.get(namespace, {}).get(name, name)

    return _apply(node, rename, None)


def prefixed(
    node: AnyElement,
    prefix: str,
    *,
    namespaces: Collection[str] = ALL,
    exclude: Callable[[str], bool] | Collection[str] | None = None,
    undeclared: bool = False,
) -> AnyElement:
    """A copy where every name ``node`` declares, and every reference to it, starts with ``prefix``.

    Exact and composable: ``prefixed(prefixed(m, a), b) == prefixed(m, b + a)``;
    a name that already starts with ``prefix`` is prefixed again.

    Args:
        node: A model or any element of one.
        prefix: The text put before each name.
        namespaces: The namespaces to prefix (default all; see
            :data:`mjcf_model.schema.namespaces.NAMESPACES`).
        exclude: Names to leave alone: a collection, or a predicate on the name.
        undeclared: Also prefix references to names ``node`` does not declare
            (by default they are left alone: they may point into a parent model).

    With all namespaces, an ``<attach>`` element's ``prefix`` also gets ``prefix``
    in front, so the names it brings in are prefixed too. Names MuJoCo makes
    (replicate copies, flexcomp bodies, attached names) follow what makes them,
    and so do references to them: ``rope_3`` becomes ``p_rope_3`` when the
    flexcomp ``rope`` becomes ``p_rope``. An ``<attach>`` without ``model``
    copies a body of this model: its copies are then named ``prefix`` + the
    attach's prefix + ``prefix`` + the original name.

    Raises:
        MjcfValueError: Bodies would be renamed while a skin reads their names
            from a ``.skn`` file and the model does not know its folder (a loaded
            model has its skin files written inline first; otherwise call
            ``mjcf_model.serializers.skins.inline_skin_files(model, folder)``).
        MjcfAssetError: An asset ``<model>`` without ``name`` has a file that
            cannot be read (its name is its file root's ``model`` attribute).

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(name="b", childclass="c", children=[Geom(name="g", material="m")])
        >>> new = prefixed(body, "p_")
        >>> new.name, new.childclass, new.geoms[0].name, new.geoms[0].material
        ('p_b', 'c', 'p_g', 'm')
        >>> prefixed(body, "p_", undeclared=True).geoms[0].material
        'p_m'

    """
    chosen = _checked_namespaces(namespaces)
    if not prefix:
        return node
    if "body" in chosen:
        node = inline_skin_files(node)
    excluded = _excluder(exclude)
    if undeclared:

        def rename(namespace: str, name: str) -> str:
            keep = namespace not in chosen or excluded(name)
            return name if keep else prefix + name
    else:
        declared = declared_names(node)
        if chosen == ALL and exclude is None:
            return prefixed_declared(node, prefix, declared)

        def rename(namespace: str, name: str) -> str:
            keep = (
                namespace not in chosen or name not in declared.get(namespace, ()) or excluded(name)
            )
            return name if keep else prefix + name

    return _apply(node, rename, prefix if chosen == ALL else None)


def prefixed_declared(
    node: AnyElement, prefix: str, declared: Mapping[str, Collection[str]]
) -> AnyElement:
    """:func:`prefixed` in every namespace, given the names ``node`` declares.

    For callers that prefix the same model many times (composition): the names
    are read once instead of on every call.

    Examples:
        >>> from mjcf_model import Body
        >>> body = Body(name="b")
        >>> prefixed_declared(body, "p_", declared_names(body)).name
        'p_b'

    """

    def rename(namespace: str, name: str) -> str:
        return prefix + name if name in declared.get(namespace, ()) else name

    return _apply(node, rename, prefix)
