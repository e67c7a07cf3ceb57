"""The parent's top-level defaults moved into a class, so that they stay with the parent.

MuJoCo's top-level ``<default>`` (the class ``main``) reaches every element that
names no class, and every default class inherits from it. A child merged into a
parent would therefore take the parent's top-level settings, where MuJoCo's own
attaching (``<attach>``, ``MjSpec.attach``) keeps the child's elements as the
child defines them. :func:`with_main_as_class` moves those settings into a class
of their own, nests every other class of the parent inside it and names it on
the parent's elements they reach (as :func:`mjcf_model.transforms.composition.defaults.classed`
does for a child), so the top-level class is left empty and the parent compiles
as before.

>>> from mjcf_model import dumps, loads
>>> model = loads('<mujoco><default><geom rgba="1 0 0 1"/></default>'
...               '<worldbody><body><geom size="1"/></body></worldbody></mujoco>')
>>> print(dumps(with_main_as_class(model, "parent_main"), canonical=True), end="")
<mujoco>
  <default>
    <default class="parent_main">
      <geom rgba="1 0 0 1"/>
    </default>
  </default>
  <worldbody>
    <body childclass="parent_main">
      <geom size="1"/>
    </body>
  </worldbody>
</mujoco>
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

import attrs

from mjcf_model.nodes.base import AnyElement, Element, Node, get_attribute, with_attributes
from mjcf_model.nodes.default import Default
from mjcf_model.nodes.root import Mujoco
from mjcf_model.transforms.composition.defaults import classed, merged_settings, sets_values
from mjcf_model.tree.defaults import MAIN
from mjcf_model.tree.traversal import map_elements, with_children

__all__ = ["CLASSED_SECTIONS", "with_main_as_class"]

#: Sections whose elements take defaults, and the section name ``classed`` knows them by.
CLASSED_SECTIONS = ("asset", "contact", "equality", "tendon", "actuator")
#: Containers in the world whose children take classes but that have no ``childclass``.
_TRANSPARENT = frozenset({"replicate"})


def _classed_world(nodes: Sequence[Node], main: Default) -> list[Node]:
    """:func:`classed` for the world, going into the replicates at its top level.

    A replicate has no ``childclass``; its copies take the classes of the world.
    Nested replicates are entered from an explicit stack: any depth is classed.
    """
    # Each level: the classed nodes still to go through, what is done, and the
    # replicate they belong to (``None`` for the world itself).
    stack: list[tuple[Iterator[Node], list[Node], AnyElement | None]] = [
        (iter(classed(nodes, main, "body")), [], None)
    ]
    while True:
        pending, done, owner = stack[-1]
        for node in pending:
            if isinstance(node, Element) and node.tag in _TRANSPARENT:
                stack.append((iter(classed(node.children, main, "body")), [], node))
                break
            done.append(node)
        else:
            stack.pop()
            if owner is None:
                return done
            stack[-1][1].append(with_children(owner, done))


def _main_renamed(model: Mujoco, name: str) -> Mujoco:
    """``model`` with every explicit ``class="main"`` (and ``childclass``) naming ``name``."""

    def visit(
        element: AnyElement, _key: str | None, _ancestors: Sequence[AnyElement]
    ) -> AnyElement:
        changes = {
            attribute: name
            for attribute in ("class", "childclass")
            if element.tag != "default" and get_attribute(element, attribute) == MAIN
        }
        return with_attributes(element, changes) if changes else element

    return map_elements(visit, model)


def with_main_as_class(model: Mujoco, name: str) -> Mujoco:
    """``model`` with its top-level default settings in the class ``name`` instead.

    The top-level ``<default>`` sections become one holding only the class
    ``name``, which holds their settings (merged, later ones winning) and their
    classes; the elements those settings reach name ``name`` (bodies and frames
    at the top of the world through ``childclass``), and explicit references to
    ``main`` name it too. MuJoCo compiles the result as it compiles ``model``.
    A model whose top-level defaults set nothing is returned as it is.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><default><default class="a"/></default></mujoco>')
        >>> with_main_as_class(model, "m") is model
        True

    """
    defaults = [c for c in model.elements if c.tag == "default"]
    if not any(sets_values(default) for default in defaults):
        return model
    main = Default(dclass=name, children=merged_settings(defaults))
    sections: list[Node] = []
    for section in _main_renamed(model, name).children:
        tag = getattr(section, "tag", None)
        if tag == "default":
            if not any(getattr(s, "tag", None) == "default" for s in sections):
                sections.append(Default(children=[main]))
            continue
        if isinstance(section, Element):
            if tag == "worldbody":
                section = with_children(section, _classed_world(section.children, main))
            elif tag in CLASSED_SECTIONS:
                section = with_children(section, classed(section.children, main, str(tag)))
        sections.append(section)
    return attrs.evolve(model, children=sections)
