"""What a model holds, and the attributes an element really has after its default classes.

:func:`model_summary` counts elements per tag, lists the names declared per
namespace, the ``<compiler>`` settings and the default-class tree.
:func:`effective_attributes` answers the question hand-written resolvers get
wrong: which value each attribute of one element has once its class (its own
``class``, else the nearest ``childclass`` above it, else ``main``) and that
class's parents are applied, and which class supplied it.

>>> from mjcf_model import loads
>>> model = loads('''<mujoco><default><geom rgba="1 0 0 1"/>
...   <default class="steel"><geom density="7800"/></default></default>
...   <worldbody><body childclass="steel"><geom name="g" size="0.1"/></body></worldbody>
... </mujoco>''')
>>> for item in effective_attributes(model, "geom", "g"):
...     print(item)
name = g (written)
size = 0.1 (written)
density = 7800 (class steel)
rgba = 1 0 0 1 (class main)
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping

import attrs

from mjcf_model.errors import MjcfLookupError
from mjcf_model.nodes.base import AnyElement, attribute_items
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.transforms.composition.compiler_settings import compiler_settings
from mjcf_model.transforms.naming.generated_names import declarations
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.traversal import keyed_walk
from mjcf_model.values import Value, format_value

__all__ = ["EffectiveAttribute", "ModelSummary", "effective_attributes", "model_summary"]


@attrs.frozen(kw_only=True)
class EffectiveAttribute:
    """One attribute of an element as MuJoCo reads it.

    Examples:
        >>> print(EffectiveAttribute(name="rgba", value=(1.0, 0.0, 0.0, 1.0), source="main"))
        rgba = 1 0 0 1 (class main)

    """

    #: The MJCF attribute.
    name: str
    #: Its value.
    value: Value
    #: The default class that supplies it; ``None`` when the element writes it itself.
    source: str | None

    def __str__(self) -> str:
        where = "written" if self.source is None else f"class {self.source}"
        return f"{self.name} = {format_value(self.value)} ({where})"


def effective_attributes(model: Mujoco, kind: str, name: str) -> list[EffectiveAttribute]:
    """The attributes of the element ``kind``/``name`` after default classes and ``childclass``.

    ``kind`` is the element's tag (``geom``, ``motor``) or the namespace of its name
    (``actuator``, ``sensor``). The attributes it writes come first, in its order;
    then those its classes supply, nearest class first. Actuators share one default
    per class (``<general>``, ``<motor>``... all set it), and tendons read their
    class's ``<tendon>``, as in MuJoCo; an attribute the element's own tag does not
    have (a ``kp`` set by ``<position>`` for a ``<motor>``) is not listed. Attributes
    nothing writes keep MuJoCo's built-in defaults and are not listed.

    Raises:
        MjcfLookupError: No element of that kind has that name.

    """
    classes = DefaultClasses.of(model)
    for element, key, ancestors in keyed_walk(model):
        if _is(element, key, kind, name, model):
            written = attribute_items(element)
            own = {attribute for attribute, _ in written}
            found = [EffectiveAttribute(name=a, value=v, source=None) for a, v in written]
            given = classes.given_to(element, ancestors)
            chain = classes.chain(classes.class_of(element, ancestors))
            spec = SCHEMA.get(key or "")
            known = spec.attributes if spec is not None else None  # a motor reads no kp
            inherited = sorted(
                (
                    item
                    for item in given.items()
                    if item[0] not in own and (known is None or item[0] in known)
                ),
                key=lambda item: chain.index(item[1][1]) if item[1][1] in chain else len(chain),
            )
            found.extend(
                EffectiveAttribute(name=attribute, value=value, source=source)
                for attribute, (value, source) in inherited
            )
            return found
    raise MjcfLookupError(f"no {kind} named {name!r} in the model; {_names_of_kind(model, kind)}")


#: How many names a lookup error lists before it says how many more there are.
_NAMES_LISTED = 12


def _names_of_kind(model: Mujoco, kind: str) -> str:
    """The names the model's elements of ``kind`` (a tag or a namespace) have, in words."""
    names: list[str] = []
    for element, key, _ in keyed_walk(model):
        for _, namespace, declared in declarations(element, key, base_dir=model.base_dir):
            if kind in (element.tag, namespace) and declared not in names:
                names.append(declared)
    if not names:
        return f"it has no named {kind}"
    listed = ", ".join(names[:_NAMES_LISTED])
    more = f" and {len(names) - _NAMES_LISTED} more" if len(names) > _NAMES_LISTED else ""
    return f"its {kind} names: {listed}{more}"


def _is(element: AnyElement, key: str | None, kind: str, name: str, model: Mujoco) -> bool:
    """Whether ``element`` (of schema ``key``) is the ``kind`` element named ``name``."""
    return any(
        declared == name and kind in (element.tag, namespace)
        for _, namespace, declared in declarations(element, key, base_dir=model.base_dir)
    )


#: The tags that name elements of more than one schema key (``joint`` in a body, a
#: fixed tendon or an equality).
_SHARED_TAGS = frozenset(
    tag
    for tag, count in Counter(
        key.rpartition("/")[2] for key in SCHEMA if not key.startswith("default/")
    ).items()
    if count > 1
)


def _kind(key: str | None, tag: str) -> str:
    """What :attr:`ModelSummary.counts` counts an element as (see there)."""
    if key is None or (tag not in _SHARED_TAGS and "/" in key):
        return tag
    return key.removeprefix("body/")


@attrs.frozen(kw_only=True)
class ModelSummary:
    """What :func:`model_summary` reports."""

    #: The ``model`` attribute of ``<mujoco>``.
    name: str | None
    #: How many elements of each kind the model writes (default settings not counted): the
    #: tag, or where one tag names several kinds, the schema key (``joint`` for a body's
    #: joints, ``tendon/fixed/joint`` for a fixed tendon's).
    counts: Mapping[str, int]
    #: The names declared in each namespace, in document order (default classes not included).
    names: Mapping[str, tuple[str, ...]]
    #: The ``<compiler>`` settings MuJoCo will use (written, else its defaults).
    compiler: Mapping[str, str]
    #: Each default class's parent (``None`` for ``main``).
    classes: Mapping[str, str | None]
    #: The tags each default class sets.
    class_settings: Mapping[str, tuple[str, ...]]


def model_summary(model: Mujoco) -> ModelSummary:
    """Counts, names, compiler settings and default classes of ``model``.

    Examples:
        >>> from mjcf_model import loads
        >>> summary = model_summary(loads('<mujoco model="m"><worldbody><body name="a">'
        ...                               '<geom size="1"/></body></worldbody></mujoco>'))
        >>> dict(summary.counts), dict(summary.names)
        ({'mujoco': 1, 'worldbody': 1, 'body': 1, 'geom': 1}, {'body': ('a',)})

    """
    counts: Counter[str] = Counter()
    names: dict[str, list[str]] = {}
    for element, key, _ in keyed_walk(model):
        if key is not None and key.startswith("default"):
            continue
        counts[_kind(key, element.tag)] += 1
        for _, namespace, name in declarations(element, key, base_dir=model.base_dir):
            names.setdefault(namespace, []).append(name)
    classes = DefaultClasses.of(model)
    settings: dict[str, list[str]] = {name: [] for name in classes.parents}
    for owner, tag in classes.settings:
        settings.setdefault(owner, []).append(tag)
    return ModelSummary(
        name=model.model,
        counts=dict(counts),
        names={namespace: tuple(declared) for namespace, declared in names.items()},
        compiler=dict(compiler_settings(model)),
        classes=dict(classes.parents),
        class_settings={name: tuple(tags) for name, tags in settings.items()},
    )
