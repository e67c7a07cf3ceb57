"""Reading MJCF: text and files into nodes, and ElementTree into nodes.

The text reader drives expat directly and builds nodes as elements close, so
it knows the line of every element for error messages, keeps comments, and
never sees a DTD or an entity: both are refused.

>>> model = loads('<mujoco model="m"><worldbody><geom size="0.1"/></worldbody></mujoco>')
>>> model.model, model.worldbody.geoms[0].size
('m', (0.1,))
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import IO, Any, NoReturn
from xml.parsers import expat

import attrs

from mjcf_model.base import AnyElement, Comment, Node
from mjcf_model.errors import (
    MjcfError,
    MjcfIncludeError,
    MjcfSecurityError,
    MjcfSyntaxError,
)
from mjcf_model.namespaces import child_key, children_context, guess_context
from mjcf_model.nodes.root import Include, Mujoco
from serializers.building import build_element, element_step, element_text

__all__ = ["from_etree", "load", "loads"]

_STRING = "<string>"


@attrs.define
class _Open:
    """An element whose start tag was read and whose end tag was not yet."""

    tag: str
    attributes: list[tuple[str, str]]
    key: str | None
    context: str | None
    line: int
    #: 1-based position among the parent's children with the same tag.
    index: int
    children: list[Node] = attrs.field(factory=list)
    text: list[str] = attrs.field(factory=list)
    counts: dict[str, int] = attrs.field(factory=dict)


@attrs.define
class _Session:
    """What one ``load`` call shares across the files it reads."""

    inline_includes: bool
    main_dir: Path | None
    include_chain: tuple[Path, ...] = ()


class _Reader:
    """Builds nodes from expat events for one document."""

    def __init__(self, filename: str, session: _Session, include_context: str | None) -> None:
        self.filename = filename
        self.session = session
        #: For an included file, the context its root's children are read in.
        self.include_context = include_context
        self.stack: list[_Open] = []
        self.top: list[Node] = []  # comments around the root, and the root itself
        self.parser = expat.ParserCreate()
        self.parser.ordered_attributes = True
        self.parser.buffer_text = True
        self.parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
        self.parser.StartElementHandler = self.start
        self.parser.EndElementHandler = self.end
        self.parser.CommentHandler = self.comment
        self.parser.CharacterDataHandler = self.characters
        self.parser.StartDoctypeDeclHandler = self.refuse_doctype
        self.parser.EntityDeclHandler = self.refuse_entity
        self.parser.ExternalEntityRefHandler = self.refuse_external

    # -- security -----------------------------------------------------------------

    def refuse_doctype(self, name: str, *_args: Any) -> NoReturn:
        raise MjcfSecurityError(
            f"DTD <!DOCTYPE {name}> refused: MJCF needs no DTD and entities are never expanded",
            file=self.filename,
            line=self.parser.CurrentLineNumber,
        )

    def refuse_entity(self, name: str, *_args: Any) -> NoReturn:
        raise MjcfSecurityError(
            f"entity declaration {name!r} refused: entities are never expanded",
            file=self.filename,
            line=self.parser.CurrentLineNumber,
        )

    def refuse_external(self, *_args: Any) -> NoReturn:
        raise MjcfSecurityError(
            "external entity reference refused: nothing is fetched",
            file=self.filename,
            line=self.parser.CurrentLineNumber,
        )

    def path_to(self, item: _Open | None) -> str:
        """The element path of ``item`` (or of the innermost open element), for errors.

        Built only when an error is raised: ``item`` has been closed, so the open
        elements on the stack are its ancestors.
        """
        chain = self.stack if item is None else [*self.stack, item]
        return "".join(f"/{element_step(o.tag, o.attributes, o.index)}" for o in chain)

    # -- events -------------------------------------------------------------------

    def start(self, tag: str, flat: list[str]) -> None:
        attributes = list(zip(flat[::2], flat[1::2], strict=True))
        if self.stack:
            parent = self.stack[-1]
            context = parent.context
            index = parent.counts[tag] = parent.counts.get(tag, 0) + 1
        else:
            context, index = None, 1
        key = child_key(context, tag)
        inner = children_context(key, context)
        if not self.stack and key == "mujoco" and self.include_context is not None:
            inner = self.include_context
        self.stack.append(
            _Open(
                tag=tag,
                attributes=attributes,
                key=key,
                context=inner,
                line=self.parser.CurrentLineNumber,
                index=index,
            )
        )

    def end(self, _tag: str) -> None:
        item = self.stack.pop()
        text = element_text(item.text, bool(item.children))
        try:
            node = build_element(item.key, item.tag, item.attributes, item.children, text)
        except MjcfError as error:
            raise error.located(
                file=self.filename, line=item.line, path=self.path_to(item)
            ) from None
        siblings = self.stack[-1].children if self.stack else self.top
        if self.session.inline_includes and isinstance(node, Include):
            siblings.extend(self.included(node, item))
        else:
            siblings.append(node)

    def comment(self, text: str) -> None:
        (self.stack[-1].children if self.stack else self.top).append(Comment(text=text))

    def characters(self, data: str) -> None:
        if self.stack:
            self.stack[-1].text.append(data)

    # -- includes -----------------------------------------------------------------

    def included(self, node: Include, item: _Open) -> list[Node]:
        """The nodes an ``<include>`` stands for, read in the including element's context."""
        if not node.file:
            raise MjcfIncludeError(
                "<include> needs a 'file' attribute",
                file=self.filename,
                line=item.line,
                path=self.path_to(item),
            )
        path = self.resolve_include(node.file, item)
        chain = self.session.include_chain
        if path in chain:
            cycle = " -> ".join(str(p) for p in (*chain[chain.index(path) :], path))
            raise MjcfIncludeError(
                f"include cycle: {cycle}",
                file=self.filename,
                line=item.line,
                path=self.path_to(item),
            )
        session = attrs.evolve(self.session, include_chain=(*chain, path))
        try:
            data = path.read_bytes()
        except OSError as error:
            raise MjcfIncludeError(
                f"cannot read included file {str(path)!r}: {error.strerror}",
                file=self.filename,
                line=item.line,
                path=self.path_to(item),
            ) from None
        parent_context = self.stack[-1].context if self.stack else None
        root = _read(data, str(path), session, parent_context or "mujoco")
        return list(root.children)

    def resolve_include(self, file: str, item: _Open) -> Path:
        """Find an included file as MuJoCo does.

        MuJoCo looks beside the main model first, then beside the including file.
        """
        candidates: list[Path] = []
        if self.session.main_dir is not None:
            candidates.append(self.session.main_dir / file)
        if self.filename != _STRING:
            here = Path(self.filename).parent / file
            if here not in candidates:
                candidates.append(here)
        for candidate in candidates:
            if candidate.is_file():
                return candidate.resolve()
        looked = ", ".join(repr(str(c)) for c in candidates) or "nowhere (no base directory)"
        raise MjcfIncludeError(
            f"included file {file!r} not found; looked in {looked}",
            file=self.filename,
            line=item.line,
            path=self.path_to(item),
        )

    # -- driver -------------------------------------------------------------------

    def parse(self, data: str | bytes) -> list[Node]:
        try:
            self.parser.Parse(data, True)
        except expat.ExpatError as error:
            path = self.path_to(None) if self.stack else None
            message = expat.errors.messages[error.code] if error.code else str(error)
            raise MjcfSyntaxError(
                f"malformed XML: {message} (column {error.offset + 1})",
                file=self.filename,
                line=error.lineno,
                path=path,
            ) from None
        return self.top


def _read(
    data: str | bytes, filename: str, session: _Session, include_context: str | None = None
) -> Mujoco:
    """Parse one document whose root must be ``<mujoco>``.

    Comments before and after the root become its first and last children. An
    included file's root children are read in ``include_context``, the context of
    the element that includes it.
    """
    top = _Reader(filename, session, include_context).parse(data)
    roots = [n for n in top if not isinstance(n, Comment)]
    if len(roots) != 1 or not isinstance(roots[0], Mujoco):
        found = roots[0].tag if roots and isinstance(roots[0], AnyElement) else "nothing"
        raise MjcfSyntaxError(f"expected a <mujoco> root element, found <{found}>", file=filename)
    root = roots[0]
    index = top.index(root)
    before = top[:index]
    after = top[index + 1 :]
    if before or after:
        root = attrs.evolve(root, children=(*before, *root.children, *after))
    return root


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

    Example:
        >>> loads("<mujoco><!-- hi --></mujoco>").children
        (Comment(text=' hi '),)

    """
    session = _Session(
        inline_includes=inline_includes, main_dir=Path(base_dir) if base_dir is not None else None
    )
    return _read(text, filename or _STRING, session)


def load(
    source: str | os.PathLike[str] | IO[bytes] | IO[str], *, inline_includes: bool = False
) -> Mujoco:
    """Read an MJCF model from a file path or an open file.

    Args:
        source: A path, or a file object opened for reading.
        inline_includes: Replace each ``<include>`` by the elements of the file it
            names, looked up beside the main file first and then beside the
            including file, as MuJoCo does. Include cycles raise.

    Example:
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
            raise MjcfIncludeError(f"cannot read {str(path)!r}: {error.strerror}") from None
        resolved = path.resolve()
        session = _Session(
            inline_includes=inline_includes,
            main_dir=resolved.parent,
            include_chain=(resolved,),
        )
        return _read(data, str(path), session)
    name = getattr(source, "name", None)
    filename = name if isinstance(name, str) else _STRING
    base = Path(filename).parent if filename != _STRING else None
    return loads(source.read(), inline_includes=inline_includes, base_dir=base, filename=filename)


def from_etree(element: ET.Element, *, context: str | None = None, typed: bool = True) -> Node:
    """Convert an ElementTree element (and its subtree) to nodes.

    Args:
        element: The element; ``<mujoco>`` gives a :class:`~mjcf_model.Mujoco`, any
            other element the node of that element.
        context: The schema key of the element's parent (``"body"``, ``"asset"``, ...).
            By default it is guessed from the tag, which is right except for tags
            that mean different things in different sections (``<joint>`` inside
            ``<equality>``): pass the context for those.
        typed: With ``False`` every element becomes a
            :class:`~mjcf_model.GenericElement` holding its attribute text exactly
            as given, so text MuJoCo would reject (``group="1.0"``) still converts.

    Example:
        >>> import xml.etree.ElementTree as ET
        >>> from_etree(ET.fromstring('<geom size="0.1"/>')).size
        (0.1,)
        >>> from_etree(ET.fromstring('<geom group="1.0"/>'), typed=False).attributes["group"]
        '1.0'

    """
    if element.tag is ET.Comment:  # type: ignore[comparison-overlap]
        return Comment(text=element.text or "")
    if context is None:
        context = guess_context(element.tag)
    try:
        return _from_etree(element, context, typed)
    except MjcfError as error:
        raise _within(error, element, 1) from None


def _from_etree(element: ET.Element, context: str | None, typed: bool = True) -> AnyElement:
    """Convert one element; an error names no path yet: each caller adds its step."""
    key = child_key(context, element.tag)
    inner = children_context(key, context)
    children: list[Node] = []
    chunks = [element.text]
    counts: dict[str, int] = {}
    for child in element:
        if child.tag is ET.Comment:  # type: ignore[comparison-overlap]
            children.append(Comment(text=child.text or ""))
        elif isinstance(child.tag, str):
            index = counts[child.tag] = counts.get(child.tag, 0) + 1
            try:
                children.append(_from_etree(child, inner, typed))
            except MjcfError as error:
                raise _within(error, child, index) from None
        chunks.append(child.tail)
    return build_element(
        key if typed else None,
        element.tag,
        list(element.attrib.items()),
        children,
        element_text(chunks, bool(children)),
    )


def _within(error: MjcfError, element: ET.Element, index: int) -> MjcfError:
    """The error with ``element``'s step put in front of its path."""
    step = element_step(element.tag, list(element.attrib.items()), index)
    return type(error)(
        error.detail, file=error.file, line=error.line, path=f"/{step}{error.path or ''}"
    )
