"""Walking a node tree and rebuilding it with only the changed paths new.

Every transform in this package is built on :func:`map_tree` (or its schema-aware
twin :func:`map_elements`): children are rebuilt first, and an element whose
children all came back unchanged (``is``) is itself returned unchanged, so a
transform that changes nothing returns its input, and one that changes a leaf
shares every other subtree with the input.

>>> from mjcf_model import Body, Geom
>>> arm = Body(name="arm", children=[Geom(name="g", size=[0.1])])
>>> map_tree(lambda node: node, arm) is arm
True
>>> [(path, element.tag) for path, element in walk(arm)]
[((), 'body'), ((0,), 'geom')]
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Collection, Iterator, Sequence
from typing import TypeVar

from mjcf_model.caching import BoundedCache
from mjcf_model.errors import Advice, MjcfValueError
from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    Node,
    build_node,
    get_attribute,
    to_children,
)
from mjcf_model.schema.namespaces import child_key, guess_context
from mjcf_model.tree.ancestry import Ancestors
from mjcf_model.tree.indexes import NotedOrder, indexed

__all__ = [
    "GUESS",
    "SKIN_KEYS",
    "ElementVisitor",
    "Path",
    "keyed_walk",
    "map_elements",
    "map_tree",
    "refuse_file_skin",
    "refuse_opaque",
    "schema_key",
    "walk",
    "walk_nodes",
    "with_children",
    "with_mapped_children",
]

#: A position in a tree: the index of each step in its parent's ``children``.
Path = tuple[int, ...]

#: ``fn(element, schema key, ancestors root first)``, as :func:`map_elements` calls it.
ElementVisitor = Callable[[AnyElement, str | None, Sequence[AnyElement]], AnyElement]

_E = TypeVar("_E", bound=Element)
_N = TypeVar("_N", bound=Node)
_A = TypeVar("_A", bound=Element)

#: What to do with a model whose ``<include>`` elements were kept as they are.
INCLUDES_NOT_READ = Advice(
    "load it with inline_includes=True",
    "run the command on the main file (the command line reads included files in)",
)


class _Guess:
    def __repr__(self) -> str:
        return "GUESS"


#: Read the root element in the context its tag most likely has (``<geom>`` in a body).
GUESS = _Guess()


def with_children(element: _E, children: Sequence[Node]) -> _E:
    """``element`` with new children, or ``element`` itself when each child is the same object.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> body = Body(children=[Geom()])
        >>> with_children(body, list(body.children)) is body
        True

    """
    old = element.children
    if len(old) == len(children) and all(map(operator.is_, old, children)):
        return element
    return build_node(type(element), {"children": to_children(children)}, element)


def map_tree(fn: Callable[[Node], Node], node: _N) -> Node:
    """Apply ``fn`` to every node, children before their parent, sharing what ``fn`` keeps.

    ``fn`` receives each node (comments too) after its children were mapped, and
    returns it or a replacement.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> from mjcf_model.nodes.base import with_attributes
        >>> body = Body(children=[Geom(name="a"), Geom(name="b")])
        >>> def rename_a(node):
        ...     is_a = getattr(node, "name", None) == "a"
        ...     return with_attributes(node, {"name": "z"}) if is_a else node
        >>> new = map_tree(rename_a, body)
        >>> [g.name for g in new.geoms], new.children[1] is body.children[1]
        (['z', 'b'], True)

    """
    if not (isinstance(node, Element) and node.children):
        return fn(node)
    # An explicit stack, not recursion: trees of any depth are mapped.
    stack: list[tuple[Element, list[Node], Iterator[Node]]] = [(node, [], iter(node.children))]
    while True:
        parent, mapped, pending = stack[-1]
        for child in pending:
            if isinstance(child, Element) and child.children:
                stack.append((child, [], iter(child.children)))
                break
            mapped.append(fn(child))
        else:
            stack.pop()
            result = fn(with_children(parent, mapped))
            if not stack:
                return result
            stack[-1][1].append(result)


def schema_key(element: AnyElement, context: str | _Guess | None = GUESS) -> str | None:
    """The schema key of ``element`` read inside ``context`` (guessed from its tag by default).

    Examples:
        >>> from mjcf_model import Geom, Mujoco
        >>> schema_key(Mujoco()), schema_key(Geom()), schema_key(Geom(), "default")
        ('mujoco', 'body/geom', 'default/geom')

    """
    if isinstance(context, _Guess):
        context = guess_context(element.tag)
    return child_key(context, element.tag)


def map_elements(
    fn: ElementVisitor,
    node: _A,
    context: str | _Guess | None = GUESS,
    *,
    kept: Collection[str] = frozenset(),
) -> _A:
    """Apply ``fn(element, key, ancestors)`` to every element, children first.

    ``key`` is the element's schema key (``None`` for an element the table does
    not know), ``ancestors`` the original elements from the root down to the
    parent. Comments are kept as they are. ``kept`` names the keys of elements
    ``fn`` returns unchanged when they have no children: ``fn`` is not called
    for those (a transform's way of skipping what it has nothing to do with). A result
    of the same shape (each element's result has its tag and the children mapped from
    its own) is indexed for lookups from its first one, as a loaded model is.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> from mjcf_model.nodes.base import with_attributes
        >>> def tag_keys(element, key, ancestors):
        ...     return with_attributes(element, {"key": key})
        >>> map_elements(tag_keys, Body(children=[Geom()])).geoms[0].extra["key"]
        'body/geom'

    """
    if isinstance(context, _Guess):
        context = guess_context(node.tag)
    return _map_elements(fn, node, context, kept)  # type: ignore[return-value]


#: ``child_key`` answers, by ``(context, tag)``: the walks ask it for every element
#: (tags are open-ended in untrusted files, hence the bound).
_KEYS: BoundedCache[tuple[str | None, str], str | None] = BoundedCache(4096)
#: What :data:`_KEYS` gives for a question it has no answer to.
_UNKNOWN = "?"


def _key_of(context: str | None, tag: str) -> str | None:
    """:func:`~mjcf_model.schema.namespaces.child_key`, remembered."""
    try:
        return _KEYS[(context, tag)]
    except KeyError:
        return _KEYS.remember((context, tag), child_key(context, tag))


def with_mapped_children(element: _A, mapped: list[Node]) -> _A:
    """:func:`with_children` for children the walk built (nodes already, not checked again)."""
    old = element.children
    if len(old) == len(mapped) and all(map(operator.is_, old, mapped)):
        return element
    return build_node(type(element), {"children": tuple(mapped)}, element)


#: A frame of :func:`_map_elements`' stack.
_Frame = tuple[
    AnyElement, str | None, str | None, Ancestors, Ancestors, list[Node], Iterator[Node], int
]


def _map_elements(
    fn: ElementVisitor, root: AnyElement, context: str | None, kept: Collection[str]
) -> AnyElement:
    """:func:`map_elements` with an explicit stack, so trees of any depth are mapped.

    A frame is pushed only for an element with children; a leaf is visited
    where it stands. The results are noted in document order as the reader notes what
    it reads: when ``fn`` keeps the shape of the tree (each element's result has its
    tag, and the children mapped from its own), that is the lookup index of the new
    tree (:func:`~mjcf_model.tree.indexes.indexed`), so its first lookup walks nothing.
    """
    key = _key_of(context, root.tag)
    inner = context if key is None or key == "include" else key
    top = Ancestors()
    keys, unknown = _KEYS, _UNKNOWN
    noted = NotedOrder()
    order, reserve = noted.order, noted.reserve
    same_shape = True
    # (element, key, its children's context, its ancestors, theirs, mapped, pending, place)
    stack: list[_Frame] = [(root, key, inner, top, top.extended(root), [], iter(root.children), -1)]
    while True:
        element, key, inner, ancestors, below, mapped, pending, place = stack[-1]
        for child in pending:
            if not isinstance(child, Element):
                mapped.append(child)
                continue
            tag = child.tag
            child_key = keys.get((inner, tag), unknown)
            if child_key is unknown:
                child_key = _key_of(inner, tag)
            child_place = reserve(tag)
            if child.children:
                deeper = inner if child_key is None or child_key == "include" else child_key
                level = below.extended(child)
                stack.append(
                    (child, child_key, deeper, below, level, [], iter(child.children), child_place)
                )
                break
            result = child if child_key in kept else fn(child, child_key, below)
            if result is not child and (result.tag != tag or result.children):
                same_shape = False
            order[child_place] = result
            mapped.append(result)
        else:
            stack.pop()
            built = with_mapped_children(element, mapped)
            result = fn(built, key, ancestors)
            if result is not built and (
                result.tag != element.tag or result.children is not built.children
            ):
                same_shape = False
            if not stack:
                if same_shape and result is not root:
                    indexed(result, noted.index())
                return result
            order[place] = result
            stack[-1][5].append(result)


def refuse_opaque(element: AnyElement, key: str | None, action: str) -> None:
    """Raise when a transform meets an element whose contents are not in the tree.

    An ``<include>`` names another file. A ``<composite>`` (removed in MuJoCo 4.0,
    expanded by older releases) makes bodies, joints and geoms whose names and
    sizes are nowhere in the tree, so prefixing or scaling it would give a model
    MuJoCo rejects or reads differently.

    Examples:
        >>> from mjcf_model.nodes.base import GenericElement
        >>> refuse_opaque(GenericElement(tag="include"), "include", "prefix")
        Traceback (most recent call last):
        ...
        mjcf_model.errors.MjcfValueError: cannot prefix a model with <include> elements: \
their files are not part of the tree; load it with inline_includes=True

    """
    if key == "include":
        raise MjcfValueError(
            f"cannot {action} a model with <include> elements: their files are not part "
            "of the tree",
            advice=INCLUDES_NOT_READ,
        )
    if key is None and element.tag == "composite":
        raise MjcfValueError(
            f"cannot {action} a model with <composite> elements: MuJoCo before 4.0 expands "
            "them into bodies, joints and geoms whose names and sizes are not in the tree "
            "(MuJoCo 4.0 removed them); write them as <replicate> or <flexcomp> instead"
        )


#: The schema keys of skins, which may keep their vertices, bind poses and bodies in a file.
SKIN_KEYS = frozenset({"asset/skin", "deformable/skin"})


def refuse_file_skin(skin: AnyElement, action: str, because: str) -> None:
    """Raise because a transform needs what a skin keeps in its ``.skn`` file.

    A skin read from a file has its vertices, bind poses and the names of its
    bodies there, not in the tree; a model loaded from a file can have it written
    inline (``mjcf_model.serializers.skins.inline_skin_files``).

    Examples:
        >>> from mjcf_model.nodes.base import GenericElement
        >>> skin = GenericElement(tag="skin", attributes={"file": "s.skn"})
        >>> refuse_file_skin(skin, "scale", "holds its vertices")
        Traceback (most recent call last):
        ...
        mjcf_model.errors.MjcfValueError: cannot scale a model where a skin is read from \
's.skn': the file holds its vertices; write the skin inline first with \
mjcf_model.serializers.skins.inline_skin_files(model, model_folder)

    """
    name, file = get_attribute(skin, "name"), get_attribute(skin, "file")
    called = f"skin {name!r}" if name else "a skin"
    raise MjcfValueError(
        f"cannot {action} a model where {called} is read from {file!r}: the file {because}; "
        "write the skin inline first with "
        "mjcf_model.serializers.skins.inline_skin_files(model, model_folder)"
    )


def walk(node: Node) -> Iterator[tuple[Path, AnyElement]]:
    """Yield ``(path, element)`` for ``node`` and every element below it, parents first.

    ``path`` indexes ``children`` from ``node`` down (``()`` is ``node``); comments
    are skipped but keep their index.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><worldbody><geom size="1"/></worldbody></mujoco>')
        >>> [(path, e.tag) for path, e in walk(model)]
        [((), 'mujoco'), ((0,), 'worldbody'), ((0, 0), 'geom')]

    """
    for _, current, path in walk_nodes(node):
        if isinstance(current, Element):
            yield path, current


def walk_nodes(node: Node) -> Iterator[tuple[AnyElement | None, Node, Path]]:
    """Yield ``(parent, node, path)`` for ``node`` and every node below it, comments too.

    Document order; ``path`` indexes ``children`` from ``node`` down, and the parent of
    ``node`` itself is ``None``.

    Examples:
        >>> from mjcf_model import Body, Comment, Geom
        >>> body = Body(children=[Comment(text="c"), Geom()])
        >>> [(path, type(node).__name__) for _, node, path in walk_nodes(body)]
        [((), 'Body'), ((0,), 'Comment'), ((1,), 'Geom')]

    """
    stack: list[tuple[AnyElement | None, Node, Path]] = [(None, node, ())]
    while stack:
        parent, current, path = stack.pop()
        yield parent, current, path
        if isinstance(current, Element):
            stack.extend(
                (current, child, (*path, index))
                for index, child in reversed(list(enumerate(current.children)))
            )


def keyed_walk(
    node: AnyElement, context: str | _Guess | None = GUESS
) -> Iterator[tuple[AnyElement, str | None, Ancestors]]:
    """Yield ``(element, key, ancestors)`` for every element, parents first.

    Examples:
        >>> from mjcf_model import Body, Geom
        >>> [key for _, key, _ in keyed_walk(Body(children=[Geom()]))]
        ['body', 'body/geom']

    """
    if isinstance(context, _Guess):
        context = guess_context(node.tag)
    keys, unknown = _KEYS, _UNKNOWN
    # Each level: the children still to walk, their context and their ancestors.
    stack: list[tuple[Iterator[Node], str | None, Ancestors]] = [
        (iter((node,)), context, Ancestors())
    ]
    while stack:
        pending, parent_context, ancestors = stack[-1]
        for element in pending:
            if not isinstance(element, Element):
                continue
            key = keys.get((parent_context, element.tag), unknown)
            if key is unknown:
                key = _key_of(parent_context, element.tag)
            yield element, key, ancestors
            if element.children:
                inner = parent_context if key is None or key == "include" else key
                stack.append((iter(element.children), inner, ancestors.extended(element)))
                break
        else:
            stack.pop()
