"""Editing a tree at a path: the element there, replaced, grown, or edited in place.

A path is what :func:`~mjcf_model.tree.traversal.walk` gives: the index of each
step in its parent's ``children``. Only the elements on the path are rebuilt;
everything else is shared with the input.

>>> from mjcf_model import Body, Geom
>>> body = Body(children=[Body(name="inner")])
>>> appended_at(body, (0,), [Geom(name="g")]).bodies[0].geoms[0].name
'g'
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from typing import TypeVar

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    Node,
    with_attributes,
)
from mjcf_model.tree.traversal import Path, with_children, with_mapped_children
from mjcf_model.values import Value

__all__ = ["appended_at", "edited_at", "replaced_at", "subtree_at"]

_N = TypeVar("_N", bound=Node)
_A = TypeVar("_A", bound=Element)


def subtree_at(node: AnyElement, path: Path) -> AnyElement:
    """The element at ``path`` (child indexes from ``node`` down, as :func:`walk` gives them).

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> subtree_at(Body(children=[Body(children=[Geom(name="g")])]), (0, 0)).name
        'g'

    """
    current = node
    for index in path:
        child = current.children[index]
        if not isinstance(child, Element):
            raise MjcfValueError(f"no element at {path}: child {index} is a {type(child).__name__}")
        current = child
    return current


def replaced_at(node: _A, path: Path, new: Sequence[Node]) -> _A:
    """``node`` with the element at ``path`` (as :func:`walk` gives it) replaced by ``new``.

    ``new`` may hold several nodes, or none (the element is removed). Only the
    elements on the path are rebuilt; everything else is shared.

    Examples:
        >>> from mjcf_model import loads
        >>> from mjcf_model import Site
        >>> model = loads('<mujoco><worldbody><geom size="1"/></worldbody></mujoco>')
        >>> replaced_at(model, (0, 0), [Site(), Site()]).worldbody.elements
        (Site(), Site())

    """
    if not path:  # the root itself: only one node of its own kind can stand there
        if len(new) != 1 or not isinstance(new[0], type(node)):
            raise MjcfValueError(
                f"the root {type(node).__name__} can only be replaced by one node of its class,"
                f" not {[type(n).__name__ for n in new]}"
            )
        return new[0]
    chain: list[AnyElement] = [node]
    for index in path[:-1]:
        inner = chain[-1].children[index]
        assert isinstance(inner, Element)
        chain.append(inner)
    replacement: list[Node] = list(new)
    for holder, index in zip(reversed(chain), reversed(path), strict=True):
        children = list(holder.children)
        children[index : index + 1] = replacement
        replacement = [with_children(holder, children)]
    result = replacement[0]
    assert isinstance(result, type(node))
    return result


def appended_at(node: _A, path: Path, children: Sequence[Node]) -> _A:
    """``node`` with ``children`` appended to the element at ``path``; the rest is shared.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> appended_at(Body(children=[Body()]), (0,), [Geom()]).bodies[0].geoms
        (Geom(),)

    """
    target = subtree_at(node, path)
    grown = with_children(target, [*target.children, *children])
    return grown if not path else replaced_at(node, path, [grown])  # type: ignore[return-value]


def edited_at(node: _N, edits: Mapping[Path, Mapping[str, Value | None]]) -> _N:
    """``node`` with attribute changes applied by path (``None`` removes one); the rest shared.

    Only the elements on the edited paths are rebuilt, each once, however many
    edits lie below it; a path to a comment is skipped.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom(name="a"), Geom(name="b")])
        >>> new = edited_at(body, {(1,): {"name": "c"}, (): {"name": "top"}})
        >>> new.name, [g.name for g in new.geoms], new.children[0] is body.children[0]
        ('top', ['a', 'c'], True)

    """
    if not edits or not isinstance(node, Element):
        return node
    touched = {path[:depth] for path in edits for depth in range(len(path) + 1)}

    def finished(element: AnyElement, path: Path, mapped: list[Node] | None) -> AnyElement:
        if mapped is not None:
            element = with_mapped_children(element, mapped)
        changes = edits.get(path)
        return with_attributes(element, changes) if changes else element

    # An explicit stack, so trees of any depth are edited; untouched subtrees are not entered.
    stack: list[tuple[AnyElement, Path, list[Node], Iterator[tuple[int, Node]]]] = [
        (node, (), [], iter(enumerate(node.children)))
    ]
    while True:
        element, path, mapped, pending = stack[-1]
        for index, child in pending:
            below = (*path, index)
            if below not in touched or not isinstance(child, Element):
                mapped.append(child)
            elif child.children:
                stack.append((child, below, [], iter(enumerate(child.children))))
                break
            else:
                mapped.append(finished(child, below, None))
        else:
            stack.pop()
            result = finished(element, path, mapped)
            if not stack:
                return result  # type: ignore[return-value]
            stack[-1][2].append(result)
