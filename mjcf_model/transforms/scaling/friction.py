"""Scaling friction: the torsional and rolling coefficients are lengths, built-in ones too.

A geom's and a flex's ``friction`` is "sliding torsional rolling", a contact
pair's "tangent1 tangent2 spin roll1 roll2": the values from the torsional (spin)
one on are lengths and scale by the mean factor, the sliding (tangential) ones
stay. MuJoCo fills the values nobody writes from its built-in defaults (``1 0.005
0.0001`` for geoms and flexes, ``1 1 0.005 0.0001 0.0001`` for pairs; a pair does
not take them from its geoms), and those must scale too:

* in a whole model, the main default class writes every value, the missing ones
  its built-in defaults scaled: ``<default><geom friction="1 0.01 0.0002"/>``
  for a factor of 2. Every class, ``childclass`` and element writing fewer values
  inherits the rest from it, so the elements keep what they write (scaled). It is
  written only when some geom (or pair) leaves a value unwritten;
* in a part of a model (a body, a ``<contact>`` section), whose classes are not
  known, each geom and pair writing fewer values is completed itself, as if no
  class set its friction;
* a flex has no default class: its ``<contact>`` child is completed, and a flex
  (or flexcomp) without one is given one (:func:`with_flex_contact`).

>>> from mjcf_model import Geom
>>> rule = friction_rule("geom")
>>> rule(Geom(friction=[0.7]), (), ScaleContext(factors=(2.0, 2.0, 2.0)))
{'friction': (0.7, 0.01, 0.0002)}
"""

from __future__ import annotations

from collections.abc import Sequence

from mjcf_model.nodes.base import AnyElement, Element, get_attribute
from mjcf_model.nodes.contact import Pair
from mjcf_model.nodes.default import Default
from mjcf_model.nodes.deformable import FlexContact
from mjcf_model.nodes.geom import Geom
from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.pieces import Changes, Rule, builtin_default, combine, parts
from mjcf_model.tree.defaults import MAIN
from mjcf_model.tree.traversal import keyed_walk, with_children
from mjcf_model.values import numbers_of

__all__ = ["FLEX_KEYS", "friction_rule", "with_flex_contact", "with_friction_defaults"]

#: Where the lengths start in the friction of each tag.
_FIRST_LENGTH = {"geom": 1, "pair": 2, "flex": 1}
#: The class of the default element that gives each tag its friction.
_DEFAULTS: dict[str, type[Geom] | type[Pair]] = {"geom": Geom, "pair": Pair}
#: The schema keys of the elements whose friction MuJoCo completes from its defaults.
_MEMBERS = {"body/geom": "geom", "contact/pair": "pair"}
#: The sections a new ``<default>`` is written after.
_HEAD = frozenset({"compiler", "option", "size", "visual", "statistic", "extension", "custom"})


def _factors(tag: str, context: ScaleContext) -> tuple[float, ...]:
    start = _FIRST_LENGTH[tag]
    return (1.0,) * start + (context.mean,) * (len(builtin_default(tag, "friction")) - start)


def _written(tag: str, element: AnyElement) -> tuple[float, ...] | None:
    """The friction values ``element`` writes; ``None`` when it writes them all, or text."""
    value = get_attribute(element, "friction")
    own = () if value is None else numbers_of(value)
    return None if own is None or len(own) >= len(builtin_default(tag, "friction")) else own


def _completed(tag: str, own: tuple[float, ...], context: ScaleContext) -> tuple[float, ...]:
    """Every friction value scaled: ``own``, then MuJoCo's built-in defaults."""
    full = builtin_default(tag, "friction")
    values = (*own, *full[len(own) :])
    return tuple(v * f for v, f in zip(values, _factors(tag, context), strict=True))


def _completion(tag: str, element: AnyElement, context: ScaleContext) -> Changes:
    own = _written(tag, element)
    return {} if own is None else {"friction": _completed(tag, own, context)}


def _whole_model(context: ScaleContext) -> bool:
    return context.model is not None and context.model.tag == "mujoco"


def _unwritten(context: ScaleContext) -> frozenset[str]:
    """The tags of which some element in the model leaves a friction value unwritten."""

    def find() -> frozenset[str]:
        found: set[str] = set()
        for element, key, _ in keyed_walk(context.model) if context.model else ():
            tag = _MEMBERS.get(key or "")
            if tag is not None and tag not in found and _written(tag, element) is not None:
                found.add(tag)
        return frozenset(found)

    return context.cached("unwritten friction", find)


def friction_rule(tag: str) -> Rule:
    """The rule of the ``friction`` of ``tag`` elements (``"geom"``, ``"pair"``, ``"flex"``).

    Written values scale from the torsional one on. The main default class of a
    whole model, and an element outside default classes in a part of a model,
    are completed first (see the module's text).

    Examples:
        >>> from mjcf_model import Default, Mujoco, Pair
        >>> main = (Mujoco(), Default())
        >>> rule, context = friction_rule("pair"), ScaleContext(factors=(2.0, 2.0, 2.0))
        >>> rule(Pair(friction=[0.5, 0.5, 0.01]), main, context)
        {'friction': (0.5, 0.5, 0.02)}

    """
    start = _FIRST_LENGTH[tag]
    return combine(parts("friction", (1.0,) * start, start), _Completion(tag))


class _Completion:
    """The part of :func:`friction_rule` that completes a main class's (or a part's) friction."""

    __slots__ = ("tag",)

    def __init__(self, tag: str) -> None:
        #: ``"geom"``, ``"pair"`` or ``"flex"``.
        self.tag = tag

    def __call__(
        self, element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
    ) -> Changes:
        """The completed friction of ``element``, where it is completed."""
        tag = self.tag
        if tag not in _DEFAULTS or not _whole_model(context):  # no class gives it
            in_default = any(a.tag == "default" for a in ancestors)
            return {} if in_default else _completion(tag, element, context)
        main = len(ancestors) == 2 and ancestors[-1].tag == "default"
        return _completion(tag, element, context) if main and tag in _unwritten(context) else {}


def with_friction_defaults(model: AnyElement, context: ScaleContext) -> AnyElement:
    """A scaled ``<mujoco>`` whose main class gives the scaled built-in friction, where needed.

    Where the main class already has a ``<geom>`` (``<pair>``), :func:`friction_rule`
    completed it; otherwise one is written into the first top-level ``<default>``,
    or a new ``<default>`` after the model's head sections.

    Examples:
        >>> from mjcf_model import Body, Geom, Mujoco, Worldbody
        >>> model = Mujoco(children=[Worldbody(children=[Body(children=[Geom(size=[1])])])])
        >>> done = with_friction_defaults(model, ScaleContext(factors=(2.0,) * 3, model=model))
        >>> done.children[0]
        Default(children=(Geom(friction=(1.0, 0.01, 0.0002)),))

    """
    written = [
        _DEFAULTS[tag](friction=_completed(tag, (), context))
        for tag in sorted(_unwritten(context))
        if (MAIN, tag) not in context.classes.settings
    ]
    if not written:
        return model
    children = list(model.children)
    elements = [(i, c) for i, c in enumerate(children) if isinstance(c, Element)]
    for index, child in elements:
        if child.tag == "default":
            children[index] = with_children(child, [*written, *child.children])
            return with_children(model, children)
    at = next((i for i, c in elements if c.tag not in _HEAD), len(children))
    return with_children(model, [*children[:at], Default(children=written), *children[at:]])


#: The schema keys of the elements whose contact settings a ``<contact>`` child holds.
FLEX_KEYS = frozenset({"body/flexcomp", "deformable/flex"})


def with_flex_contact(flex: AnyElement, context: ScaleContext) -> AnyElement:
    """A scaled flex (or flexcomp) with a ``<contact>`` child giving its friction.

    One that has a ``<contact>`` child had it completed by :func:`friction_rule`;
    otherwise one is added with MuJoCo's built-in friction, scaled.

    Examples:
        >>> from mjcf_model import Flexcomp
        >>> with_flex_contact(Flexcomp(name="f"), ScaleContext(factors=(2.0,) * 3)).children
        (FlexContact(friction=(1.0, 0.01, 0.0002)),)

    """
    if any(child.tag == "contact" for child in flex.elements):
        return flex
    contact = FlexContact(friction=_completed("flex", (), context))
    return with_children(flex, [*flex.children, contact])
