"""Default classes: which class an element takes its unwritten values from.

MuJoCo resolves an attribute an element does not write through its class (its
``class``, else the nearest ``childclass`` above it, else ``main``), then that
class's parents. Transforms that depend on a value written elsewhere (a joint's
``type`` decides whether its ``range`` is a length) ask :class:`DefaultClasses`.

>>> from mjcf_model import loads
>>> model = loads('''<mujoco><default><default class="rail"><joint type="slide"/></default>
... </default><worldbody><body childclass="rail"><joint name="j"/></body></worldbody></mujoco>''')
>>> classes = DefaultClasses.of(model)
>>> classes.lookup("rail", "joint", "type")
('slide', 'rail')
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from types import MappingProxyType
from typing import Any, cast

import attrs

from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    GenericElement,
    Node,
    TypedElement,
    attribute_items,
    get_attribute,
)
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.tree.ancestry import fold_ancestors
from mjcf_model.tree.queries import attribute_values
from mjcf_model.values import Value

__all__ = ["ACTUATOR_DEFAULT_TAGS", "MAIN", "DefaultClasses"]

#: The name of the top-level default class.
MAIN = "main"

#: The ``<default>`` tags that set actuator defaults: each of them reaches every actuator.
ACTUATOR_DEFAULT_TAGS = frozenset(
    key.partition("/")[2]
    for key in SCHEMA
    if key.startswith("default/") and f"actuator/{key.partition('/')[2]}" in SCHEMA
)


@attrs.frozen(kw_only=True)
class DefaultClasses:
    """The default classes of a model: their nesting and the element settings in each.

    Examples:
        >>> DefaultClasses.empty().chain("main")
        ('main',)

    """

    #: Each class's parent class (``None`` for ``main``).
    parents: Mapping[str, str | None]
    #: The default element of each ``(class, tag)``, e.g. ``("arm", "geom")`` (the last
    #: written, where two top-level ``<default>`` sections both set ``main``'s).
    settings: Mapping[tuple[str, str], AnyElement]
    #: Every default element of each ``(class, tag)`` in the order written: MuJoCo applies
    #: each over the one before (two top-level ``<default>`` sections, one from an
    #: ``<include>``, both set ``main``'s). By default, :attr:`settings`' one each.
    layers: Mapping[tuple[str, str], tuple[AnyElement, ...]] = attrs.field(
        default=attrs.Factory(
            lambda self: MappingProxyType({key: (value,) for key, value in self.settings.items()}),
            takes_self=True,
        ),
        eq=False,
        repr=False,
    )
    #: Chains and merged settings, worked out on first use (the classes never change).
    _memo: dict[tuple[object, ...], Any] = attrs.field(
        factory=dict, init=False, eq=False, repr=False
    )
    #: The tags some class sets an attribute of (see :meth:`sets`).
    _tags: frozenset[str] = attrs.field(init=False, eq=False, repr=False)

    @_tags.default
    def _set_tags(self) -> frozenset[str]:
        return frozenset(tag for (_, tag), held in self.layers.items() if any(map(_writes, held)))

    @classmethod
    def empty(cls) -> DefaultClasses:
        """No classes but ``main``, with nothing in it."""
        return cls(parents=MappingProxyType({MAIN: None}), settings=MappingProxyType({}))

    @classmethod
    def of(cls, model: AnyElement) -> DefaultClasses:
        """Read the classes of a model (an element other than ``<mujoco>`` has none).

        Examples:
            >>> from mjcf_model import loads
            >>> m = loads('<mujoco><default><default class="a"/></default></mujoco>')
            >>> dict(DefaultClasses.of(m).parents)
            {'main': None, 'a': 'main'}

        """
        parents: dict[str, str | None] = {MAIN: None}
        settings: dict[tuple[str, str], AnyElement] = {}
        layers: dict[tuple[str, str], tuple[AnyElement, ...]] = {}

        tops = [c for c in model.children if isinstance(c, Element) and c.tag == "default"]
        for top in tops if model.tag == "mujoco" else []:
            parents[MAIN] = None
            # Each level: the children of a <default> still to read, and its class name;
            # an explicit stack, read in document order, so classes nest to any depth.
            stack: list[tuple[Iterator[Node], str]] = [(iter(top.children), MAIN)]
            while stack:
                pending, name = stack[-1]
                for child in pending:
                    if not isinstance(child, Element):
                        continue
                    if child.tag == "default":
                        inner = get_attribute(child, "class")
                        inner_name = inner if isinstance(inner, str) else ""
                        parents[inner_name] = name
                        stack.append((iter(child.children), inner_name))
                        break
                    settings[(name, child.tag)] = child
                    layers[(name, child.tag)] = (*layers.get((name, child.tag), ()), child)
                else:
                    stack.pop()
        return cls(
            parents=MappingProxyType(parents),
            settings=MappingProxyType(settings),
            layers=MappingProxyType(layers),
        )

    def chain(self, name: str) -> tuple[str, ...]:
        """``name`` and its ancestors, innermost first (an unknown class is just itself).

        Examples:
            >>> classes = DefaultClasses(parents={"main": None, "a": "main"}, settings={})
            >>> classes.chain("a")
            ('a', 'main')

        """
        memo = self._memo.get(("chain", name))
        if memo is not None:
            chain: tuple[str, ...] = memo
            return chain
        found: list[str] = []
        current: str | None = name
        while current is not None and current not in found:
            found.append(current)
            current = self.parents.get(current)
        self._memo[("chain", name)] = tuple(found)
        return tuple(found)

    def sets(self, tag: str) -> bool:
        """Whether any class sets an attribute of ``tag`` elements.

        Examples:
            >>> from mjcf_model import Geom
            >>> classes = DefaultClasses(parents={"main": None},
            ...                          settings={("main", "geom"): Geom(type="box")})
            >>> classes.sets("geom"), classes.sets("site")
            (True, False)

        """
        return tag in self._tags

    def given(self, name: str, tag: str) -> Mapping[str, tuple[Value, str]]:
        """Every attribute class ``name`` gives ``tag`` elements, with the class that writes it.

        Examples:
            >>> from mjcf_model import Geom
            >>> classes = DefaultClasses(
            ...     parents={"main": None, "a": "main"},
            ...     settings={("main", "geom"): Geom(size=[1]), ("a", "geom"): Geom(type="box")},
            ... )
            >>> dict(classes.given("a", "geom"))
            {'size': ((1.0,), 'main'), 'type': ('box', 'a')}

        """
        memo = self._memo.get(("given", name, tag))
        if memo is not None:
            known: Mapping[str, tuple[Value, str]] = memo
            return known
        merged: dict[str, tuple[Value, str]] = {}
        for current, setting in self._along(name, tag):
            for attribute, value in attribute_items(setting):
                merged[attribute] = (value, current)
        shared = self._memo[("given", name, tag)] = MappingProxyType(merged)  # read-only
        return shared

    def lookup(self, name: str, tag: str, attribute: str) -> tuple[Value, str] | None:
        """The value of ``attribute`` for ``tag`` elements in class ``name``, and its class.

        The class is the one that writes the value; ``None`` when no class does.

        Examples:
            >>> from mjcf_model import Geom
            >>> classes = DefaultClasses(
            ...     parents={"main": None, "a": "main"},
            ...     settings={("main", "geom"): Geom(size=[1])},
            ... )
            >>> classes.lookup("a", "geom", "size")
            ((1.0,), 'main')

        """
        return self.given(name, tag).get(attribute)

    def settings_along(self, name: str, tag: str) -> tuple[AnyElement, ...]:
        """The default elements class ``name`` and its ancestors hold for ``tag``, outermost first.

        MuJoCo starts an element from these, each written value over the one before
        (a value of fewer numbers than the last replaces only its first numbers), then
        applies what the element writes itself. ``tag`` ``"actuator"`` gives every
        actuator default element of each class in the order written: ``<general>``,
        ``<motor>``, ``<position>``... set one shared actuator default.

        Examples:
            >>> from mjcf_model import Geom
            >>> classes = DefaultClasses(
            ...     parents={"main": None, "a": "main"},
            ...     settings={("main", "geom"): Geom(size=[1]), ("a", "geom"): Geom(type="box")},
            ... )
            >>> [setting.size for setting in classes.settings_along("a", "geom")]
            [(1.0,), None]

        """
        return tuple(setting for _, setting in self._along(name, tag))

    def _along(self, name: str, tag: str) -> tuple[tuple[str, AnyElement], ...]:
        """:meth:`settings_along`, each with the class that holds it (worked out once)."""
        memo: tuple[tuple[str, AnyElement], ...] | None = self._memo.get(("along", name, tag))
        if memo is not None:
            return memo
        found: list[tuple[str, AnyElement]] = []
        for current in reversed(self.chain(name)):
            if tag == "actuator":
                found += [
                    (current, setting)
                    for (owner, kind), held in self.layers.items()
                    if owner == current and kind in ACTUATOR_DEFAULT_TAGS
                    for setting in held
                ]
            else:
                found += [(current, setting) for setting in self.layers.get((current, tag), ())]
        along = self._memo[("along", name, tag)] = tuple(found)
        return along

    def class_of(self, element: AnyElement, ancestors: Sequence[AnyElement]) -> str:
        """The class ``element`` takes defaults from: its own, an inherited ``childclass``, or main.

        For an element inside ``<default>`` it is the enclosing class.

        Examples:
            >>> from mjcf_model import Body, Geom
            >>> DefaultClasses.empty().class_of(Geom(), (Body(childclass="arm"),))
            'arm'

        """
        enclosing, inherited = _scope_of(ancestors)
        if enclosing is not None:
            return enclosing
        own = get_attribute(element, "class")
        if isinstance(own, str):
            return own
        return MAIN if inherited is None else inherited

    def inherited(
        self, element: AnyElement, ancestors: Sequence[AnyElement], tag: str | None = None
    ) -> Mapping[str, tuple[Value, str]]:
        """What ``element``'s classes give it (see :meth:`given`), whatever it writes itself.

        For an element inside ``<default>``, what the enclosing class inherits.
        ``tag`` as in :meth:`resolve`.

        Examples:
            >>> from mjcf_model import Geom
            >>> classes = DefaultClasses(parents={"main": None},
            ...                          settings={("main", "geom"): Geom(type="box")})
            >>> dict(classes.inherited(Geom(type="sphere"), ()))
            {'type': ('box', 'main')}

        """
        tag = tag or element.tag
        if not self.sets(tag):
            return _NOTHING
        name = self._giver(element, ancestors)
        return _NOTHING if name is None else self.given(name, tag)

    def given_to(
        self, element: AnyElement, ancestors: Sequence[AnyElement]
    ) -> Mapping[str, tuple[Value, str]]:
        """What ``element``'s classes give it, read where MuJoCo reads it, with the giving class.

        A tendon reads its class's ``<tendon>``, an equality its ``<equality>``; an
        actuator reads every actuator element of its class (``<general>``,
        ``<motor>``, ``<position>``... set one shared actuator default, the last
        written winning); other elements read the element of their own tag (see
        :meth:`inherited`).

        Examples:
            >>> from mjcf_model import loads
            >>> model = loads('<mujoco><default><general ctrlrange="-1 1"/><motor gear="2"/>'
            ...               '</default><actuator><position name="p" joint="j"/></actuator>'
            ...               '<worldbody><body><joint name="j"/></body></worldbody></mujoco>')
            >>> classes = DefaultClasses.of(model)
            >>> actuator = model.actuator.elements[0]
            >>> dict(classes.given_to(actuator, (model, model.actuator)))
            {'ctrlrange': ((-1.0, 1.0), 'main'), 'gear': ((2.0,), 'main')}

        """
        section = ancestors[-1].tag if ancestors else ""
        if section in ("tendon", "equality"):  # one default for every kind in the section
            return self.inherited(element, ancestors, section)
        if section != "actuator":
            return self.inherited(element, ancestors)
        name = self._giver(element, ancestors)
        if name is None:
            return _NOTHING
        return self.given(name, "actuator")

    def _giver(self, element: AnyElement, ancestors: Sequence[AnyElement]) -> str | None:
        """The class whose settings ``element`` inherits (``None``: none, in the main default)."""
        name = self.class_of(element, ancestors)
        if _scope_of(ancestors)[0] is not None and ancestors[-1].tag == "default":
            return self.parents.get(name)  # a default element: its class's parent gives
        return name

    def resolve(
        self,
        element: AnyElement,
        ancestors: Sequence[AnyElement],
        attribute: str,
        tag: str | None = None,
    ) -> Value | None:
        """The value ``attribute`` has for ``element``: written on it, or from its classes.

        ``tag`` names the default element to look in when it is not the element's
        own tag (``"tendon"`` for a ``<spatial>`` tendon).

        Examples:
            >>> from mjcf_model import Geom
            >>> classes = DefaultClasses(parents={"main": None},
            ...                          settings={("main", "geom"): Geom(type="box")})
            >>> classes.resolve(Geom(), (), "type")
            'box'

        """
        own = get_attribute(element, attribute)
        if own is not None:
            return own
        found = self.inherited(element, ancestors, tag).get(attribute)
        return None if found is None else found[0]

    def resolve_many(
        self,
        element: AnyElement,
        ancestors: Sequence[AnyElement],
        attributes: tuple[str, ...],
        tag: str | None = None,
    ) -> tuple[Value | None, ...]:
        """:meth:`resolve` for several attributes at once.

        Examples:
            >>> from mjcf_model import Geom
            >>> classes = DefaultClasses(parents={"main": None},
            ...                          settings={("main", "geom"): Geom(type="box")})
            >>> classes.resolve_many(Geom(size=[1]), (), ("type", "size", "mass"))
            ('box', (1.0,), None)

        """
        own = attribute_values(element, attributes)
        if None not in own:
            return own
        tag = tag or element.tag
        if tag not in self._tags:
            return own
        name = self._giver(element, ancestors)
        if name is None:
            return own
        key = ("values", name, tag, attributes)
        inherited = self._memo.get(key)
        if inherited is None:
            given = self.given(name, tag)
            inherited = tuple(_value(given.get(attribute)) for attribute in attributes)
            self._memo[key] = inherited
        return tuple(
            [value if value is not None else got for value, got in zip(own, inherited, strict=True)]
        )


#: What an element's ancestors say about its class: the class of the nearest
#: ``<default>`` around it, and the nearest ``childclass`` (``None``: none).
_Scope = tuple[str | None, str | None]
_NO_SCOPE: _Scope = (None, None)
_NOTHING: Mapping[str, tuple[Value, str]] = MappingProxyType({})


def _writes(setting: AnyElement) -> bool:
    """Whether a default element writes any attribute."""
    if isinstance(setting, GenericElement):
        return bool(setting.attributes)
    info = type(setting).__node_info__
    return bool(cast(TypedElement, setting).extra) or any(
        value is not None for value in info.getter(setting)
    )


def _value(found: tuple[Value, str] | None) -> Value | None:
    return None if found is None else found[0]


def _scope_of(ancestors: Sequence[AnyElement]) -> _Scope:
    """The scope of an element with these ancestors."""
    return fold_ancestors(ancestors, _scope, _NO_SCOPE)


def _scope(scope: _Scope, ancestor: AnyElement) -> _Scope:
    """The scope below ``ancestor``, given the scope it stands in."""
    if ancestor.tag == "default":
        own = get_attribute(ancestor, "class")
        return (own if isinstance(own, str) else MAIN, scope[1])
    inherited = get_attribute(ancestor, "childclass")
    return (scope[0], inherited) if isinstance(inherited, str) else scope
