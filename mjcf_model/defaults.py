"""Default classes: which class an element takes its unwritten values from.

MuJoCo resolves an attribute an element does not write through its class (its
``class``, else the nearest ``childclass`` above it, else ``main``), then that
class's parents. Transforms that depend on a value written elsewhere (a joint's
``type`` decides whether its ``range`` is a length) ask :class:`DefaultClasses`.

>>> from serializers import loads
>>> model = loads('''<mujoco><default><default class="rail"><joint type="slide"/></default>
... </default><worldbody><body childclass="rail"><joint name="j"/></body></worldbody></mujoco>''')
>>> classes = DefaultClasses.of(model)
>>> classes.lookup("rail", "joint", "type")
('slide', 'rail')
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from types import MappingProxyType

import attrs

from mjcf_model.base import AnyElement, GenericElement, TypedElement, get_attribute
from mjcf_model.values import Value

__all__ = ["MAIN", "DefaultClasses"]

#: The name of the top-level default class.
MAIN = "main"


@attrs.frozen(kw_only=True)
class DefaultClasses:
    """The default classes of a model: their nesting and the element settings in each.

    Example:
        >>> DefaultClasses.empty().chain("main")
        ('main',)

    """

    #: Each class's parent class (``None`` for ``main``).
    parents: Mapping[str, str | None]
    #: The default element of each ``(class, tag)``, e.g. ``("arm", "geom")``.
    settings: Mapping[tuple[str, str], AnyElement]

    @classmethod
    def empty(cls) -> DefaultClasses:
        """No classes but ``main``, with nothing in it."""
        return cls(parents=MappingProxyType({MAIN: None}), settings=MappingProxyType({}))

    @classmethod
    def of(cls, model: AnyElement) -> DefaultClasses:
        """Read the classes of a model (an element other than ``<mujoco>`` has none).

        Example:
            >>> from serializers import loads
            >>> m = loads('<mujoco><default><default class="a"/></default></mujoco>')
            >>> dict(DefaultClasses.of(m).parents)
            {'main': None, 'a': 'main'}

        """
        parents: dict[str, str | None] = {MAIN: None}
        settings: dict[tuple[str, str], AnyElement] = {}

        def read(default: AnyElement, name: str, parent: str | None) -> None:
            parents[name] = parent
            for child in default.children:
                if not isinstance(child, (TypedElement, GenericElement)):
                    continue
                if child.tag == "default":
                    inner = get_attribute(child, "class")
                    read(child, inner if isinstance(inner, str) else "", name)
                else:
                    settings[(name, child.tag)] = child

        if model.tag == "mujoco":
            for child in model.children:
                if isinstance(child, (TypedElement, GenericElement)) and child.tag == "default":
                    read(child, MAIN, None)
        return cls(parents=MappingProxyType(parents), settings=MappingProxyType(settings))

    def chain(self, name: str) -> tuple[str, ...]:
        """``name`` and its ancestors, innermost first (an unknown class is just itself).

        Example:
            >>> classes = DefaultClasses(parents={"main": None, "a": "main"}, settings={})
            >>> classes.chain("a")
            ('a', 'main')

        """
        found: list[str] = []
        current: str | None = name
        while current is not None and current not in found:
            found.append(current)
            current = self.parents.get(current)
        return tuple(found)

    def lookup(self, name: str, tag: str, attribute: str) -> tuple[Value, str] | None:
        """The value of ``attribute`` for ``tag`` elements in class ``name``, and its class.

        The class is the one that writes the value; ``None`` when no class does.

        Example:
            >>> from mjcf_model import Geom
            >>> classes = DefaultClasses(
            ...     parents={"main": None, "a": "main"},
            ...     settings={("main", "geom"): Geom(size=[1])},
            ... )
            >>> classes.lookup("a", "geom", "size")
            ((1.0,), 'main')

        """
        for current in self.chain(name):
            setting = self.settings.get((current, tag))
            if setting is not None:
                value = get_attribute(setting, attribute)
                if value is not None:
                    return value, current
        return None

    def class_of(self, element: AnyElement, ancestors: Sequence[AnyElement]) -> str:
        """The class ``element`` takes defaults from: its own, an inherited ``childclass``, or main.

        For an element inside ``<default>`` it is the enclosing class.

        Example:
            >>> from mjcf_model import Body, Geom
            >>> DefaultClasses.empty().class_of(Geom(), (Body(childclass="arm"),))
            'arm'

        """
        for ancestor in reversed(ancestors):
            if ancestor.tag == "default":
                own = get_attribute(ancestor, "class")
                return own if isinstance(own, str) else MAIN
        own = get_attribute(element, "class")
        if isinstance(own, str):
            return own
        for ancestor in reversed(ancestors):
            inherited = get_attribute(ancestor, "childclass")
            if isinstance(inherited, str):
                return inherited
        return MAIN

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

        Example:
            >>> from mjcf_model import Geom
            >>> classes = DefaultClasses(parents={"main": None},
            ...                          settings={("main", "geom"): Geom(type="box")})
            >>> classes.resolve(Geom(), (), "type")
            'box'

        """
        own = get_attribute(element, attribute)
        if own is not None:
            return own
        name = self.class_of(element, ancestors)
        if ancestors and ancestors[-1].tag == "default":
            parent = self.parents.get(name)
            if parent is None:
                return None
            name = parent
        found = self.lookup(name, tag or element.tag, attribute)
        return None if found is None else found[0]
