"""Includes: finding an included file as MuJoCo does and splicing its elements in.

By default the reader keeps an ``<include>`` as a node. With ``inline_includes``
each one read becomes a :class:`PendingInclude`, its file is found as MuJoCo
finds it (:func:`resolve_include`), and its elements replace it (:func:`splice`),
each remembering the folder its paths resolve from (:func:`record_origins`).

>>> import pathlib, tempfile
>>> from mjcf_model import Include
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> _ = (folder / "parts.xml").write_text("<mujoco/>")
>>> pending = PendingInclude(Include(file="parts.xml"), STRING_FILENAME, 1, "/include", "mujoco")
>>> found = resolve_include(pending, Session(inline_includes=True, main_dir=folder))
>>> found == (folder / "parts.xml").resolve()
True
"""

from __future__ import annotations

from pathlib import Path

import attrs

from mjcf_model.errors import MjcfIncludeError
from mjcf_model.files.provenance import FILE_TAGS
from mjcf_model.nodes.base import AnyElement, Element, Node
from mjcf_model.nodes.root import Include, Mujoco
from mjcf_model.tree.indexes import TagIndex
from mjcf_model.tree.traversal import map_tree, with_children

__all__ = [
    "STRING_FILENAME",
    "Document",
    "PendingInclude",
    "Session",
    "include_error",
    "record_origins",
    "resolve_include",
    "splice",
]

#: The file name errors report for text that was not read from a file.
STRING_FILENAME = "<string>"


@attrs.define
class Session:
    """What one ``load`` call shares across the files it reads."""

    #: Whether each ``<include>`` is replaced by the elements of its file.
    inline_includes: bool
    #: The main model's folder, where included files are looked for first.
    main_dir: Path | None
    #: The file being read when the call began (the main file), if any.
    main_file: Path | None = None

    @property
    def include_chain(self) -> tuple[Path, ...]:
        """The files being read when the call began, resolved: for include cycles only."""
        return () if self.main_file is None else (self.main_file.resolve(),)


@attrs.define
class PendingInclude:
    """An ``<include>`` met while reading a file, to be replaced by its file's elements."""

    node: Include
    #: The file the ``<include>`` stands in, and where, for errors.
    filename: str
    line: int
    path: str
    #: The schema context of the including element: the included elements are read in it.
    context: str


@attrs.define
class Document:
    """One file being read, and the ``<include>`` elements in it not yet replaced."""

    root: Mujoco | AnyElement
    includes: list[PendingInclude]
    filename: str
    #: The included elements found so far, by the ``<include>`` node they replace.
    found: dict[int, tuple[Node, ...]] = attrs.field(factory=dict)
    #: The lookup index the reader noted for the root's tree, as read.
    index: TagIndex | None = None


def record_origins(
    nodes: tuple[Node, ...], folder: Path, origins: dict[int, tuple[AnyElement, Path]]
) -> None:
    """Note ``folder`` as the origin of each element in ``nodes`` that may name a file.

    Elements of a file included deeper keep the folder noted first, their own:
    MuJoCo looks beside the innermost included file.
    """
    stack = list(nodes)
    while stack:
        node = stack.pop()
        if isinstance(node, Element):
            if node.tag in FILE_TAGS and id(node) not in origins:
                origins[id(node)] = (node, folder)
            stack.extend(node.children)


def splice(document: Document) -> Mujoco | AnyElement:
    """The document's root with each ``<include>`` replaced by the elements it stands for."""
    if not document.found:
        return document.root
    found = document.found

    def expand(node: Node) -> Node:
        if isinstance(node, Element) and any(id(c) in found for c in node.children):
            children: list[Node] = []
            for child in node.children:
                children.extend(found.get(id(child), (child,)))
            return with_children(node, children)
        return node

    return map_tree(expand, document.root)  # type: ignore[return-value]


def include_error(pending: PendingInclude, what: str, error: OSError) -> MjcfIncludeError:
    """The error saying ``what`` failed for ``pending``, and the system's reason."""
    return MjcfIncludeError(
        f"{what}: {error.strerror or error}",
        file=pending.filename,
        line=pending.line,
        path=pending.path,
    )


def resolve_include(pending: PendingInclude, session: Session) -> Path:
    """Find an included file as MuJoCo does.

    MuJoCo looks beside the main model first, then beside the including file.
    """
    file = pending.node.file
    assert file
    candidates: list[Path] = []
    if session.main_dir is not None:
        candidates.append(session.main_dir / file)
    if pending.filename != STRING_FILENAME:
        here = Path(pending.filename).parent / file
        if here not in candidates:
            candidates.append(here)
    for candidate in candidates:
        try:
            if candidate.is_file():
                return candidate.resolve()
        except OSError as error:  # a name too long, a loop of links
            raise include_error(pending, f"cannot look for included file {file!r}", error) from None
    looked = ", ".join(repr(str(c)) for c in candidates) or "nowhere (no base directory)"
    raise MjcfIncludeError(
        f"included file {file!r} not found; looked in {looked}",
        file=pending.filename,
        line=pending.line,
        path=pending.path,
    )
