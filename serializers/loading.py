"""Reading MJCF: text and files into nodes.

:func:`load` and :func:`loads` read the main document with the expat reader
(:mod:`mjcf_model.serializers.parsing`) and, with ``inline_includes``, every file it
includes (:mod:`mjcf_model.serializers.includes`). :func:`from_etree` lives in
:mod:`mjcf_model.serializers.etree` and is importable from here too.

>>> model = loads('<mujoco model="m"><worldbody><geom size="0.1"/></worldbody></mujoco>')
>>> model.model, model.worldbody.geoms[0].size
('m', (0.1,))
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import IO

from mjcf_model.errors import (
    MjcfIncludeCycleError,
    MjcfSyntaxError,
    unreadable_file,
)
from mjcf_model.files.provenance import with_included_paths
from mjcf_model.nodes.base import AnyElement, Comment, Element
from mjcf_model.nodes.building import build_node
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers.etree import from_etree
from mjcf_model.serializers.includes import (
    STRING_FILENAME,
    Document,
    Session,
    include_error,
    record_origins,
    resolve_include,
    splice,
)
from mjcf_model.serializers.parsing import Reader
from mjcf_model.tree.indexes import indexed
from mjcf_model.tree.traversal import with_children

__all__ = ["from_etree", "load", "loads"]


def _parse(
    data: str | bytes, filename: str, session: Session, include_context: str | None = None
) -> Document:
    """Parse one document; the main file's root must be ``<mujoco>``.

    Comments before and after the root become its first and last children. An
    included file's root children are read in ``include_context``, the context of
    the element that includes it; MuJoCo takes them whatever the root's tag is.
    """
    reader = Reader(filename, session, include_context)
    top = reader.parse(data)
    roots = [n for n in top if not isinstance(n, Comment)]
    root = roots[0] if roots else None
    if root is None or (include_context is None and not isinstance(root, Mujoco)):
        found = root.tag if isinstance(root, Element) else "nothing"
        raise MjcfSyntaxError(f"expected a <mujoco> root element, found <{found}>", file=filename)
    assert isinstance(root, Element)
    index = top.index(root)
    before = top[:index]
    after = [n for n in top[index + 1 :] if isinstance(n, Comment)]
    if before or after:
        root = with_children(root, [*before, *root.children, *after])
    return Document(root, reader.includes, filename, index=reader.index())


def _read(data: str | bytes, filename: str, session: Session) -> Mujoco:
    """Read the main document, and with ``inline_includes`` every file it includes.

    Included files are read one after another from an explicit stack, not by
    recursion, so an include chain as long as MuJoCo follows (it has no limit)
    is read too. The garbage collector is left alone: a caller who reads big models
    while holding others can pause it (:func:`mjcf_model.serializers.collector_paused`).
    """
    stack = [_parse(data, filename, session)]
    reading = {path: 0 for path in session.include_chain} if stack[0].includes else {}
    origins: dict[int, tuple[AnyElement, Path]] = {}
    while True:
        document = stack[-1]
        if len(document.found) < len(document.includes):
            pending = document.includes[len(document.found)]
            path = resolve_include(pending, session)
            if path in reading:
                chain = [*session.include_chain, *(Path(d.filename) for d in stack[1:]), path]
                cycle = " -> ".join(str(p) for p in chain[chain.index(path) :])
                raise MjcfIncludeCycleError(
                    f"include cycle: {cycle}",
                    file=pending.filename,
                    line=pending.line,
                    path=pending.path,
                )
            try:
                data = path.read_bytes()
            except OSError as error:
                raise include_error(
                    pending, f"cannot read included file {str(path)!r}", error
                ) from None
            reading[path] = len(stack)
            stack.append(_parse(data, str(path), session, pending.context))
            continue
        stack.pop()
        root = splice(document)
        if not stack:
            assert isinstance(root, Mujoco)
            if session.main_dir is not None:
                root = build_node(Mujoco, {"base_dir": session.main_dir}, root)
                root = with_included_paths(root, origins)
            if not document.found and document.index is not None:
                indexed(root, document.index)  # the elements below it are the ones read
            return root
        reading.pop(Path(document.filename), None)
        parent = stack[-1]
        parent.found[id(parent.includes[len(parent.found)].node)] = root.children
        record_origins(root.children, Path(document.filename).parent, origins)


def loads(
    text: str | bytes,
    *,
    inline_includes: bool = False,
    base_dir: str | os.PathLike[str] | None = None,
    filename: str | None = None,
) -> Mujoco:
    """Read an MJCF model from text.

    Args:
        text: The XML.
        inline_includes: Replace each ``<include>`` by the elements of the file it
            names (found relative to ``base_dir``). By default includes are kept as
            :class:`~mjcf_model.Include` nodes and written back as includes.
        base_dir: Where included files are looked for; the main model's directory.
        filename: The name errors should report (default ``"<string>"``).

    Raises:
        MjcfSyntaxError: The text is not well-formed XML or its root is not ``<mujoco>``.
        MjcfValueError: An attribute value has the wrong form.
        MjcfIncludeError: An included file is missing or files include each other.
        MjcfSecurityError: The text declares a DTD or entities.

    Examples:
        >>> loads("<mujoco><!-- hi --></mujoco>").children
        (Comment(text=' hi '),)

    """
    session = Session(
        inline_includes=inline_includes, main_dir=Path(base_dir) if base_dir is not None else None
    )
    return _read(text, filename or STRING_FILENAME, session)


def load(
    source: str | os.PathLike[str] | IO[bytes] | IO[str],
    *,
    inline_includes: bool = False,
) -> Mujoco:
    """Read an MJCF model from a file path or an open file.

    Reading never compiles: ``<attach>`` elements are kept as they are. To have
    what MuJoCo attaches there instead, compose the steps:
    ``mjcf_model.inlined_attachments(load(path))``.

    Args:
        source: A path, or a file object opened for reading.
        inline_includes: Replace each ``<include>`` by the elements of the file it
            names, looked up beside the main file first and then beside the
            including file, as MuJoCo does. Include cycles raise.

    Examples:
        >>> import tempfile, pathlib
        >>> path = pathlib.Path(tempfile.mkdtemp()) / "m.xml"
        >>> _ = path.write_text('<mujoco model="m"/>')
        >>> load(path).model
        'm'

    """
    if isinstance(source, (str, os.PathLike)):
        path = Path(source)
        try:
            data = path.read_bytes()
        except OSError as error:
            raise unreadable_file(source, error) from None
        session = Session(
            inline_includes=inline_includes,
            # the folder MuJoCo resolves from: the link's own, when the path is a link
            main_dir=Path(os.path.abspath(path)).parent,
            main_file=path,
        )
        return _read(data, str(path), session)
    name = getattr(source, "name", None)
    filename = name if isinstance(name, str) else STRING_FILENAME
    base = Path(filename).parent if filename != STRING_FILENAME else None
    return loads(
        source.read(),
        inline_includes=inline_includes,
        base_dir=base,
        filename=filename,
    )
