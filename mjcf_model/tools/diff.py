"""What changed between two models, element by element, rather than line by line.

:func:`changes_between` matches the elements of two models and lists what was
added, removed, moved or changed, ignoring how the files are written: formatting,
comments, attribute order and number spelling (``0.10`` is ``.1``).

* An element that declares a name (a body, a geom, a default class...) is matched
  by its namespace and name, wherever it stands; one that stands under another
  parent has **moved**.
* An element without a name is matched by its parent and its position among the
  parent's unnamed children of the same tag.

Paths are written as in error messages: ``/mujoco/worldbody/body[@name='arm']/geom[2]``
is the second unnamed ``geom`` of the body ``arm``.
* An added or removed element is listed once: what is below it is not listed again.

>>> from mjcf_model import loads
>>> a = loads('<mujoco><worldbody><body name="arm"><geom size="0.10"/></body></worldbody></mujoco>')
>>> b = loads('<mujoco><worldbody><body name="arm"><geom size=".1" rgba="1 0 0 1"/>'
...           '<site name="tip"/></body></worldbody></mujoco>')
>>> for change in changes_between(a, b):
...     print(change)
~ /mujoco/worldbody/body[@name='arm']/geom rgba: (not written) -> 1 0 0 1
+ /mujoco/worldbody/body[@name='arm']/site[@name='tip']
"""

from __future__ import annotations

import bisect
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any, Literal

import attrs

from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    Node,
    TypedElement,
    attribute_items,
    get_attribute,
)
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.transforms.naming.generated_names import declarations
from mjcf_model.tree.traversal import keyed_walk
from mjcf_model.values import Value, format_value

__all__ = ["Change", "ChangeKind", "changes_between"]

#: ``added``: only in the second model; ``removed``: only in the first; ``moved``:
#: under another parent, or in another order among its parent's children; ``changed``:
#: one attribute (or the text) differs.
ChangeKind = Literal["added", "removed", "moved", "changed"]

#: The sign :meth:`Change.__str__` starts a line with, by kind.
_SIGNS = {"added": "+", "removed": "-", "moved": ">", "changed": "~"}


@attrs.frozen(kw_only=True)
class Change:
    """One difference between two models.

    Examples:
        >>> print(Change(kind="changed", path="/mujoco/worldbody/geom", attribute="size",
        ...              old="0.1", new="0.2"))
        ~ /mujoco/worldbody/geom size: 0.1 -> 0.2

    """

    #: What happened to the element.
    kind: ChangeKind
    #: Where the element stands: in the second model (in the first for ``removed``).
    path: str
    #: Where a moved element stood in the first model.
    old_path: str | None = None
    #: The attribute that changed; ``None`` for the element's text (and other kinds).
    attribute: str | None = None
    #: The old text (``None``: not written).
    old: str | None = None
    #: The new text (``None``: not written).
    new: str | None = None

    def to_dict(self) -> dict[str, Any]:
        """The change as a JSON-ready dict (keys with ``None`` left out).

        Examples:
            >>> Change(kind="added", path="/mujoco/worldbody/site").to_dict()
            {'kind': 'added', 'path': '/mujoco/worldbody/site'}

        """
        return {key: value for key, value in attrs.asdict(self).items() if value is not None}

    def __str__(self) -> str:
        line = f"{_SIGNS[self.kind]} {self.path}"
        if self.kind == "moved":
            line += " (order changed)" if self.old_path == self.path else f" (was {self.old_path})"
        elif self.kind == "changed":
            what = "text" if self.attribute is None else self.attribute
            line += f" {what}: {_shown(self.old)} -> {_shown(self.new)}"
        return line


def _shown(text: str | None) -> str:
    return "(not written)" if text is None else text


@attrs.frozen
class _Seen:
    """An element of one model as the diff sees it."""

    #: What it is matched by (see the module docstring).
    identity: tuple[Any, ...]
    #: Its parent's identity (``None`` for the root).
    parent: tuple[Any, ...] | None
    #: Where it stands, for people.
    path: str
    #: The element.
    element: AnyElement


def changes_between(first: Node, second: Node) -> list[Change]:
    """The differences from ``first`` to ``second``: removals first, then the rest in order.

    Examples:
        >>> from mjcf_model import loads
        >>> a = loads('<mujoco><worldbody><body name="a"><body name="b"/></body></worldbody>'
        ...           '</mujoco>')
        >>> b = loads('<mujoco><worldbody><body name="a"/><body name="b"/></worldbody></mujoco>')
        >>> [moved] = changes_between(a, b)
        >>> moved.kind, moved.path
        ('moved', "/mujoco/worldbody/body[@name='b']")
        >>> moved.old_path
        "/mujoco/worldbody/body[@name='a']/body[@name='b']"
        >>> changes_between(a, a)
        []

    """
    old = {seen.identity: seen for seen in _elements(first)}
    new = {seen.identity: seen for seen in _elements(second)}
    found: list[Change] = [
        Change(kind="removed", path=seen.path)
        for seen in old.values()
        if seen.identity not in new and (seen.parent is None or seen.parent in new)
    ]
    reordered = _reordered(old, new)
    for seen in new.values():
        before = old.get(seen.identity)
        if before is None:
            if seen.parent is None or seen.parent in old:
                found.append(Change(kind="added", path=seen.path))
            continue
        if before.parent != seen.parent or seen.identity in reordered:
            found.append(Change(kind="moved", path=seen.path, old_path=before.path))
        found.extend(_changed(before.element, seen.element, seen.path))
    return found


def _reordered(old: dict[tuple[Any, ...], _Seen], new: dict[tuple[Any, ...], _Seen]) -> set[Any]:
    """The elements that kept their parent but not their order among its other children.

    Per parent, the children in both models keep the longest run that is in the same
    order in both; the others are the ones that moved (MuJoCo numbers elements in
    document order, so order is part of the model).
    """
    rank = {identity: index for index, identity in enumerate(old)}
    siblings: dict[Any, list[tuple[Any, ...]]] = {}
    for identity, seen in new.items():
        before = old.get(identity)
        if before is not None and before.parent == seen.parent:
            siblings.setdefault(seen.parent, []).append(identity)
    moved: set[Any] = set()
    for children in siblings.values():
        kept = _longest_increasing([rank[identity] for identity in children])
        moved.update(identity for index, identity in enumerate(children) if index not in kept)
    return moved


def _longest_increasing(values: list[int]) -> set[int]:
    """The positions of a longest strictly increasing subsequence of ``values``."""
    tails: list[int] = []  # tails[k]: position ending the best run of length k + 1
    ends: list[int] = []  # the values at those positions
    before: list[int] = [-1] * len(values)
    for position, value in enumerate(values):
        low = bisect.bisect_left(ends, value)
        if low:
            before[position] = tails[low - 1]
        if low == len(tails):
            tails.append(position)
            ends.append(value)
        else:
            tails[low] = position
            ends[low] = value
    kept: set[int] = set()
    position = tails[-1] if tails else -1
    while position >= 0:
        kept.add(position)
        position = before[position]
    return kept


def _changed(old: AnyElement, new: AnyElement, path: str) -> Iterator[Change]:
    """The attributes (and text) that differ between two matched elements."""
    before, after = dict(attribute_items(old)), dict(attribute_items(new))
    for name in [*before, *(name for name in after if name not in before)]:
        was, now = before.get(name), after.get(name)
        if _comparable(was, old) != _comparable(now, new):
            yield Change(kind="changed", path=path, attribute=name, old=_text(was), new=_text(now))
    if (old.text or "").strip() != (new.text or "").strip():
        yield Change(kind="changed", path=path, old=old.text, new=new.text)


def _text(value: Value | None) -> str | None:
    return None if value is None else format_value(value)


def _comparable(value: Value | None, element: AnyElement) -> object:
    """A value as compared: a typed element's as read, a generic one's numbers as floats.

    ``0.10`` and ``0.1`` read to the same float; names stay text (``"1"`` is not ``"1.0"``).
    """
    if not isinstance(value, str) or isinstance(element, TypedElement):
        return value
    words = value.split()
    try:
        return tuple(float(word) for word in words)
    except ValueError:
        return value


def _elements(root: Node) -> Iterator[_Seen]:
    """Every element of ``root`` with its identity, in document order."""
    if not isinstance(root, Element):
        return
    base_dir = root.base_dir if isinstance(root, Mujoco) else None
    # One level per parent: keyed by its ``Ancestors`` object (one per parent it walks into,
    # kept alive here), entered right after the parent itself is seen.
    levels: dict[int, tuple[_Level, Sequence[AnyElement]]] = {}
    previous: _Seen | None = None
    for element, key, ancestors in keyed_walk(root):
        if previous is None:
            previous = _Seen(("root", element.tag), None, f"/{element.tag}", element)
            yield previous
            continue
        level = levels.get(id(ancestors))
        if level is None:
            level = levels[id(ancestors)] = (_Level(previous, base_dir), ancestors)
        previous = level[0].seen_child(element, key)
        yield previous


class _Level:
    """One parent in :func:`_elements`: its identity and path, and its children's counts."""

    def __init__(self, parent: _Seen, base_dir: Path | None) -> None:
        self.parent = parent
        self.base_dir = base_dir
        self._unnamed: dict[str, int] = {}
        self._named: dict[tuple[str, str], int] = {}

    def seen_child(self, child: AnyElement, key: str | None) -> _Seen:
        declared = self._declared(child, key)
        if declared is None:
            index = self._unnamed[child.tag] = self._unnamed.get(child.tag, 0) + 1
            identity: tuple[Any, ...] = (self.parent.identity, child.tag, index)
            step = child.tag if index == 1 else f"{child.tag}[{index}]"
        else:
            attribute, namespace, name = declared
            again = self._named[namespace, name] = self._named.get((namespace, name), 0) + 1
            identity = ("named", namespace, name, again)  # ``again``: a name repeated
            step = f"{child.tag}[@{attribute}={name!r}]" + (f"[{again}]" if again > 1 else "")
        return _Seen(identity, self.parent.identity, f"{self.parent.path}/{step}", child)

    def _declared(self, element: AnyElement, key: str | None) -> tuple[str, str, str] | None:
        """The attribute, namespace and name ``element`` declares (``None``: none).

        The names MuJoCo gives (a mesh's file stem too); an element the schema does
        not know is named by its ``name`` in a namespace of its tag.
        """
        if key in SCHEMA:
            return next(declarations(element, key, base_dir=self.base_dir), None)
        name = get_attribute(element, "name")
        return ("name", element.tag, name) if isinstance(name, str) and name else None
