"""Typed node constructors with robosuite's defaults and attribute order.

Each ``new_*`` function mirrors the function of the same name in robosuite's
``mjcf_utils``: the same defaults, the same attribute order (extra keyword
arguments first, in the order given, then the named parameters in robosuite's
order, then ``name``), recorded in the node's ``attribute_order`` so the
writer emits it. ``None`` values are dropped. Values may be text, numbers,
lists, tuples or numpy arrays; numbers are written in the shortest form
(``"0 0 0"``, not robosuite's ``"0.0 0.0 0.0"`` for float arrays).

>>> from serializers import dumps
>>> print(dumps(new_geom("g", "box", [0.1, 0.1, 0.1])), end="")
<geom type="box" size="0.1 0.1 0.1" pos="0 0 0" group="0" name="g"/>
>>> print(dumps(new_site("s")), end="")
<site pos="0 0 0" size="0.005" rgba="1 0 0 1" name="s"/>
"""

from __future__ import annotations

from typing import Any, TypeVar

import attrs

from mjcf_model.errors import MjcfLookupError
from mjcf_model.nodes.actuator import ActuatorElement
from mjcf_model.nodes.base import (
    AnyElement,
    GenericElement,
    TypedElement,
    field_table,
    with_attributes,
)
from mjcf_model.nodes.body import Body, Inertial, Joint
from mjcf_model.nodes.geom import Geom, Site
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema.namespaces import child_key, guess_context
from mjcf_model.values import Value, format_value, plain_value, to_str

__all__ = [
    "RED",
    "new_actuator",
    "new_body",
    "new_element",
    "new_geom",
    "new_inertial",
    "new_joint",
    "new_site",
    "typed_node",
]

#: robosuite's ``RED``: the default colour of :func:`new_site`.
RED: tuple[float, ...] = (1.0, 0.0, 0.0, 1.0)

#: Keyword arguments that stand for another MJCF attribute (``class`` is a Python keyword).
_KEYWORD_ATTRIBUTES = {"dclass": "class"}

_T = TypeVar("_T", bound=TypedElement)

#: The actuator classes, by tag, for :func:`new_actuator`.
_ACTUATORS: dict[str, type[ActuatorElement]] = {
    key.split("/", 1)[1]: cls
    for key, cls in CLASS_BY_KEY.items()
    if key.startswith("actuator/") and issubclass(cls, ActuatorElement)
}


def _items(attributes: dict[str, Any], *named: tuple[str, Any]) -> list[tuple[str, Any]]:
    """The attributes in robosuite's order, MJCF names, ``None`` values dropped."""
    items: dict[str, Any] = {}
    for key, value in (*attributes.items(), *named):
        name = _KEYWORD_ATTRIBUTES.get(key, key)
        if value is not None:
            items[name] = plain_value(value)
    return list(items.items())


def _text_field_values(cls: type[TypedElement], items: list[tuple[str, Any]]) -> dict[str, Value]:
    """The values ready for :func:`with_attributes`: numbers for text fields become text."""
    table = field_table(cls)
    converters: dict[str, object] = {f.name: f.converter for f in attrs.fields(cls)}
    changes: dict[str, Value] = {}
    for name, value in items:
        field = table.get(name)
        is_text = field is not None and converters[field] is to_str
        if is_text and not isinstance(value, str):
            value = format_value(value)
        changes[name] = value
    return changes


def typed_node(cls: type[_T], items: list[tuple[str, Any]]) -> _T:
    """A ``cls`` node with MJCF attributes ``items``, written in that order.

    Example:
        >>> from mjcf_model import Site
        >>> typed_node(Site, [("size", [0.1]), ("name", "s")]).attribute_order
        ('size', 'name')

    """
    element = with_attributes(cls(), _text_field_values(cls, items))
    return attrs.evolve(element, attribute_order=tuple(name for name, _ in items))


def _build(tag: str, items: list[tuple[str, Any]]) -> AnyElement:
    key = child_key(guess_context(tag), tag)
    cls = CLASS_BY_KEY.get(key) if key is not None else None
    if cls is None:
        return with_attributes(GenericElement(tag=tag), dict(items))
    return typed_node(cls, items)


def new_element(tag: str, name: str | None = None, **attributes: Any) -> AnyElement:
    """A new element of ``tag``: robosuite's ``new_element``, as a typed node.

    The class is the one ``tag`` has in its most likely context (a ``geom`` in a
    body, a ``motor`` in the actuator section); a tag the table does not know
    gives a :class:`~mjcf_model.GenericElement`. Attributes the class does not
    model go to ``extra``.

    Args:
        tag: The XML tag.
        name: The ``name`` attribute, written last; ``None`` writes none.
        **attributes: MJCF attributes, written in this order; ``dclass`` stands
            for ``class``; ``None`` values are dropped.

    Example:
        >>> body = new_element("body", None, pos=[0, 0, 1], quat=None, mass=0.5, flag=True)
        >>> type(body).__name__, body.pos, body.extra["flag"]
        ('Body', (0.0, 0.0, 1.0), 'true')
        >>> new_element("wheel", "w", spokes=5).attributes
        AttributeMap({'spokes': '5', 'name': 'w'})

    """
    return _build(tag, _items(attributes, ("name", name)))


def new_joint(name: str | None = None, **attributes: Any) -> Joint:
    r"""A new ``<joint>``: robosuite's ``new_joint``.

    Example:
        >>> from serializers import dumps
        >>> dumps(new_joint("j", type="free", damping="0.0005"))
        '<joint type="free" damping="0.0005" name="j"/>\n'

    """
    return typed_node(Joint, _items(attributes, ("name", name)))


def new_actuator(
    name: str | None, joint: str, act_type: str = "motor", **attributes: Any
) -> ActuatorElement:
    r"""A new actuator driving ``joint``: robosuite's ``new_actuator``.

    The attributes come in robosuite's order: ``attributes``, then ``name``,
    then ``joint``. robosuite's default ``act_type`` is ``"actuator"``, which is
    the section tag and not an actuator MuJoCo knows; here it is ``"motor"``.

    Raises:
        MjcfLookupError: ``act_type`` is not an actuator tag.

    Example:
        >>> from serializers import dumps
        >>> dumps(new_actuator(joint="gz", act_type="position", name="a", kp="500"))
        '<position kp="500" name="a" joint="gz"/>\n'
        >>> type(new_actuator("m", "elbow")).__name__
        'Motor'

    """
    cls = _ACTUATORS.get(act_type)
    if cls is None:
        raise MjcfLookupError(
            f"no actuator element {act_type!r}; the actuator tags are "
            + ", ".join(sorted(_ACTUATORS))
        )
    return typed_node(cls, _items(attributes, ("name", name), ("joint", joint)))


def new_site(
    name: str | None = None,
    rgba: Any = RED,
    pos: Any = (0, 0, 0),
    size: Any = (0.005,),
    **attributes: Any,
) -> Site:
    """A new ``<site>``: robosuite's ``new_site`` (a small red sphere by default).

    Example:
        >>> site = new_site("tip", rgba=None, size=[0.01])
        >>> site.size, site.rgba, site.attribute_order
        ((0.01,), None, ('pos', 'size', 'name'))

    """
    return typed_node(
        Site, _items(attributes, ("pos", pos), ("size", size), ("rgba", rgba), ("name", name))
    )


def new_geom(
    name: str | None,
    type: str | None,
    size: Any,
    pos: Any = (0, 0, 0),
    group: Any = 0,
    **attributes: Any,
) -> Geom:
    """A new ``<geom>``: robosuite's ``new_geom`` (group 0, at the origin by default).

    Example:
        >>> geom = new_geom("g", "sphere", [0.1], group=None, rgba=None, material="m")
        >>> geom.attribute_order, geom.group
        (('material', 'type', 'size', 'pos', 'name'), None)

    """
    return typed_node(
        Geom,
        _items(
            attributes,
            ("type", type),
            ("size", size),
            ("pos", pos),
            ("group", group),
            ("name", name),
        ),
    )


def new_body(name: str | None = None, pos: Any = (0, 0, 0), **attributes: Any) -> Body:
    r"""A new ``<body>``: robosuite's ``new_body`` (at the origin by default).

    Example:
        >>> from serializers import dumps
        >>> dumps(new_body("b")), dumps(new_body(None, pos=None))
        ('<body pos="0 0 0" name="b"/>\n', '<body/>\n')

    """
    return typed_node(Body, _items(attributes, ("pos", pos), ("name", name)))


def new_inertial(pos: Any = (0, 0, 0), mass: Any = None, **attributes: Any) -> Inertial:
    r"""A new ``<inertial>``: robosuite's ``new_inertial`` (``mass`` before ``pos``, no name).

    Example:
        >>> from serializers import dumps
        >>> dumps(new_inertial(mass=1.0, diaginertia=[1, 1, 1]))
        '<inertial diaginertia="1 1 1" mass="1" pos="0 0 0"/>\n'

    """
    return typed_node(Inertial, _items(attributes, ("mass", mass), ("pos", pos)))
