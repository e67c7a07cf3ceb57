"""Which compiled row each element of a model is: MuJoCo's own numbering, asked once.

MuJoCo numbers bodies, geoms, joints and the rest in an order of its own (a ``<frame>``
or a default class changes nothing, a ``<body>`` is numbered before the bodies inside
it). Rather than mirror that order, :func:`numbering` gives every element it numbers a
unique name in a copy, has MuJoCo compile the copy (names do not change the numbering),
and asks MuJoCo the row of each name. What :func:`mjcf_model.patched` writes and what
:func:`mjcf_model.lint` reports are placed with it.

Examples:
    >>> from mjcf_model import loads
    >>> model = loads(
    ...     "<mujoco><worldbody><body><geom size='1'/><body name='b'><joint/>"
    ...     "<geom size='1'/></body></body></worldbody>"
    ...     "<keyframe><key qpos='1'/></keyframe></mujoco>"
    ... )
    >>> rows = numbering(model)
    >>> rows.path_of("body", 2), rows.path_of("geom", 1), rows.path_of("key", 0)
    ((0, 0, 1), (0, 0, 1, 1), (1, 0))
    >>> rows.rows[(0, 0, 1, 0)]  # the joint, by its path
    0

"""

from __future__ import annotations

from typing import Any

import attrs

from mjcf_model.bridge.compiling import compiled
from mjcf_model.caching import IdentityCache
from mjcf_model.nodes.base import AnyElement, Element, get_attribute, with_attributes
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import child_key
from mjcf_model.tree.traversal import with_children

__all__ = ["Numbering", "numbering"]

#: The kind of object MuJoCo numbers an element as, by the element's key (and by the
#: first part of keys such as ``actuator/position``).
_KINDS = {
    "body": "body",
    "body/geom": "geom",
    "body/joint": "joint",
    "body/freejoint": "joint",
    "body/site": "site",
    "body/camera": "camera",
    "body/light": "light",
    "keyframe/key": "key",
    "asset/material": "material",
}

#: The sections whose every element is numbered as one kind, named after the section.
_SECTIONS = frozenset({"actuator", "tendon", "sensor", "equality"})

#: Where the names :func:`numbering` gives unnamed elements begin.
_LABEL = "mjcf_row_"


@attrs.frozen
class Numbering:
    """The compiled row of each numbered element of one model, both ways."""

    #: The row of each numbered element, by its index path in the model (an
    #: ``<inertial>`` is numbered as its body: its values are the body's row).
    rows: dict[tuple[int, ...], int]
    #: The index path of each numbered element, by its kind (``"geom"``...) and row.
    paths: dict[tuple[str, int], tuple[int, ...]]

    def path_of(self, kind: str, row: int) -> tuple[int, ...] | None:
        """The index path of the element compiled as ``row`` of ``kind``, if numbered."""
        return self.paths.get((kind, row))


#: The numbering of the last few models asked about.
_NUMBERINGS: IdentityCache[Numbering] = IdentityCache(8)


def numbering(model: Mujoco) -> Numbering:
    """The compiled row of every body, geom, joint, site, actuator, key and their kin.

    Bodies, geoms, joints, sites, cameras, lights, keys, materials, actuators, tendons,
    sensors and equalities are numbered; elements inside a ``<replicate>`` (whose
    copies would share a name) or pulled in by ``<attach>`` are not. The last few
    models asked about are remembered (a variant loop asks about one).

    Raises:
        MjcfError: MuJoCo rejects the model (see :func:`mjcf_model.compiled`).

    """
    return _NUMBERINGS.recall_for(model, lambda: _numbered(model))


def _numbered(model: Mujoco) -> Numbering:
    import mujoco

    labels: dict[tuple[str, str], tuple[int, ...]] = {}
    inertials: dict[tuple[int, ...], tuple[int, ...]] = {}
    named = _labelled(model, None, (), labels, inertials)
    physics = compiled(named)
    rows: dict[tuple[int, ...], int] = {}
    paths: dict[tuple[str, int], tuple[int, ...]] = {}
    for (kind, label), path in labels.items():
        row = mujoco.mj_name2id(physics, getattr(mujoco.mjtObj, f"mjOBJ_{kind.upper()}"), label)
        if row >= 0:
            rows[path] = row
            paths[(kind, row)] = path
    for inertial, body in inertials.items():
        if body in rows:
            rows[inertial] = rows[body]
    return Numbering(rows, paths)


def _kind(key: str) -> str | None:
    """The kind MuJoCo numbers an element with ``key`` as (``None``: not numbered here)."""
    section, _, rest = key.partition("/")
    if section in _SECTIONS and rest and "/" not in rest:
        return section
    return _KINDS.get(key)


def _labelled(
    element: AnyElement,
    context: str | None,
    path: tuple[int, ...],
    labels: dict[tuple[str, str], tuple[int, ...]],
    inertials: dict[tuple[int, ...], tuple[int, ...]],
) -> Any:
    """``element`` with every element below it that MuJoCo numbers given a name.

    ``labels`` gets the path of each (kind, name); ``inertials`` each body's
    ``<inertial>`` path, by the body's.
    """
    key = (
        child_key(context, element.tag) if context is not None or element.tag == "mujoco" else None
    )
    if key is None or key.startswith("default") or element.tag == "replicate":
        return element
    children: list[Any] = []
    for index, child in enumerate(element.children):
        if not isinstance(child, Element):
            children.append(child)
            continue
        if child.tag == "inertial":
            inertials[(*path, index)] = path
        children.append(_labelled(child, key, (*path, index), labels, inertials))
    labelled = with_children(element, children)
    kind = _kind(key)
    if kind is None:
        return labelled
    name = get_attribute(element, "name")
    if name:  # named already: MuJoCo finds it by that name (references to it stay right)
        labels[(kind, str(name))] = path
        return labelled
    label = f"{_LABEL}{kind}_{len(labels)}"
    labels[(kind, label)] = path
    return with_attributes(labelled, {"name": label})
