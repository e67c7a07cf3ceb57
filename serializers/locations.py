r"""Where an element of a model stands: its file, line and element path, for error messages.

>>> from mjcf_model import loads
>>> from mjcf_model.errors import MjcfAssetError
>>> model = loads('<mujoco>\n<asset>\n<mesh file="hand.stl"/>\n</asset>\n</mujoco>',
...               filename="arm.xml")
>>> mesh = model.asset.elements[0]
>>> str(located_in(MjcfAssetError("cannot read 'hand.stl'"), model, mesh))
"arm.xml:3: /mujoco/asset/mesh: cannot read 'hand.stl'"
"""

from __future__ import annotations

from typing import TypeVar

from mjcf_model.errors import MjcfError
from mjcf_model.nodes.base import AnyElement, Element, attribute_text
from mjcf_model.serializers.layout import layout_of
from mjcf_model.serializers.parsed_elements import element_step
from mjcf_model.tree.traversal import Path, walk

__all__ = ["element_at", "element_path", "located_in", "read_from"]

_Error = TypeVar("_Error", bound=MjcfError)


def element_at(root: AnyElement, path: Path) -> tuple[AnyElement, str] | None:
    """The element of ``root`` at the index ``path``, and its element path; ``None``: none.

    Examples:
        >>> from mjcf_model import Body, Geom, Mujoco, Worldbody
        >>> model = Mujoco(children=[Worldbody(children=[Geom(), Body(name="arm")])])
        >>> element_at(model, (0, 1))[1], element_at(model, (0, 5))
        ("/mujoco/worldbody/body[@name='arm']", None)

    """
    current = root
    steps = [f"/{root.tag}"]
    for index in path:
        children = current.children
        if index >= len(children):
            return None
        child = children[index]
        if not isinstance(child, Element):
            return None
        same = sum(
            1 for c in children[: index + 1] if isinstance(c, Element) and c.tag == child.tag
        )
        name = attribute_text(child, "name")
        steps.append("/" + element_step(child.tag, [("name", name)] if name else [], same))
        current = child
    return current, "".join(steps)


def element_path(root: AnyElement, element: AnyElement) -> str | None:
    """The element path of ``element`` (this very object) in ``root``; ``None``: not in it.

    Examples:
        >>> from mjcf_model import Geom, Mujoco, Worldbody
        >>> geom = Geom(name="floor")
        >>> element_path(Mujoco(children=[Worldbody(children=[Geom(), geom])]), geom)
        "/mujoco/worldbody/geom[@name='floor']"

    """
    for path, candidate in walk(root):
        if candidate is element:
            found = element_at(root, path)
            return found[1] if found is not None else None
    return None


def read_from(element: AnyElement) -> tuple[str | None, int | None]:
    r"""The file and line ``element`` was read from; ``(None, None)`` for one built in code.

    Examples:
        >>> from mjcf_model import Geom, loads
        >>> read_from(loads("<mujoco>\n<worldbody/>\n</mujoco>", filename="m.xml").worldbody)
        ('m.xml', 2)
        >>> read_from(Geom())
        (None, None)

    """
    layout = layout_of(element)
    if layout is None:
        return None, None
    return layout.origin.filename, layout.origin.line(layout.begin)


def located_in(error: _Error, root: AnyElement, element: AnyElement) -> _Error:
    """``error``, its missing file, line and element path filled in from ``element``."""
    file, line = read_from(element)
    located = error.located(file=file, line=line, path=element_path(root, element))
    for name in ("errno", "strerror", "filename"):  # an OSError's reason travels with it
        if hasattr(error, name):
            setattr(located, name, getattr(error, name))
    return located
