"""Where a model's files are: asset, include and sub-model paths, resolved as MuJoCo does.

A loaded :class:`~mjcf_model.Mujoco` records the folder it was read from in
``base_dir``. A relative file path in it resolves the way MuJoCo resolves it:

* meshes, height fields, skins and ``<flexcomp file>`` under ``<compiler meshdir>``;
* textures under ``<compiler texturedir>``;
* ``assetdir`` stands for whichever of the two is not set;
* ``<include>`` and asset ``<model>`` files under the model's folder itself;
* a relative folder is itself relative to the model's folder, an absolute path
  is used as it is, and ``strippath="true"`` drops the directory part of every
  file name first.

A model built in code has no ``base_dir``: its paths resolve from wherever it is
compiled or written (the working folder, when compiled).
:func:`relocated` rewrites the relative paths of a model so that they resolve
to the same files from another folder (and under other compiler folders): what
:func:`mjcf_model.serializers.dump` does when it writes a model somewhere else and what
:func:`mjcf_model.attach` does when a child comes from another folder.

>>> from mjcf_model import loads
>>> model = loads('<mujoco><compiler meshdir="meshes"/><asset><mesh file="arm.stl"/></asset>'
...               '</mujoco>', base_dir="/robots/panda")
>>> [str(reference.path) for reference in file_references(model)]
['/robots/panda/meshes/arm.stl']
>>> moved = relocated(model, "/scenes")
>>> moved.asset.elements[0].file, moved.base_dir
('../../robots/panda/meshes/arm.stl', PosixPath('/scenes'))
"""

from __future__ import annotations

import os
import posixpath
from collections.abc import Callable, Iterator, Mapping, Sequence
from pathlib import Path, PurePosixPath
from typing import Literal, TypeGuard

import attrs

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    Node,
    attribute_items,
    get_attribute,
    with_attributes,
)
from mjcf_model.nodes.building import build_node
from mjcf_model.nodes.compiler import Compiler
from mjcf_model.nodes.root import Mujoco, to_base_dir
from mjcf_model.schema.namespaces import SCHEMA, child_key
from mjcf_model.tree.indexes import held_index
from mjcf_model.tree.traversal import keyed_walk, map_elements, with_children

__all__ = [
    "FILE_ATTRIBUTES",
    "FILE_TAGS",
    "FileReference",
    "Folders",
    "element_file_references",
    "file_references",
    "file_stem",
    "relocated",
    "with_included_paths",
    "with_folders",
    "with_paths",
]

#: Which compiler folder a file path resolves under (``model``: the model's own folder).
Kind = Literal["mesh", "texture", "model"]

_TEXTURE_FILES = ("file", "fileright", "fileleft", "fileup", "filedown", "filefront", "fileback")

#: The attributes that name files, by schema key, with the folder each resolves under.
FILE_ATTRIBUTES: Mapping[str, tuple[Kind, tuple[str, ...]]] = {
    "asset/mesh": ("mesh", ("file",)),
    "asset/hfield": ("mesh", ("file",)),
    "asset/skin": ("mesh", ("file",)),
    "deformable/skin": ("mesh", ("file",)),
    "body/flexcomp": ("mesh", ("file",)),
    "asset/texture": ("texture", _TEXTURE_FILES),
    "asset/model": ("model", ("file",)),
    "include": ("model", ("file",)),
}


def _true(value: object) -> bool:
    return str(value).strip().lower() == "true"


@attrs.frozen
class Folders:
    """The ``<compiler>`` settings that say where files are.

    Examples:
        >>> from mjcf_model import loads
        >>> Folders.of(loads('<mujoco><compiler assetdir="a" texturedir="t"/></mujoco>'))
        Folders(mesh='a', texture='t', strip=False)

    """

    #: ``meshdir`` (or ``assetdir``); empty when neither is set.
    mesh: str = ""
    #: ``texturedir`` (or ``assetdir``); empty when neither is set.
    texture: str = ""
    #: ``strippath``: file names lose their directory part.
    strip: bool = False

    @classmethod
    def of(cls, model: Mujoco) -> Folders:
        """The settings of ``model``'s top-level ``<compiler>`` sections, in order.

        ``assetdir`` sets both folders, and a ``meshdir`` or ``texturedir`` in the
        same or a later section overrides it, as MuJoCo reads them.

        Examples:
            >>> from mjcf_model import loads
            >>> Folders.of(loads('<mujoco><compiler meshdir="m"/><compiler assetdir="a"/>'
            ...                  '</mujoco>'))
            Folders(mesh='a', texture='a', strip=False)

        """
        mesh = texture = ""
        strip = False
        for section in model.elements:
            if section.tag != "compiler":
                continue
            asset = get_attribute(section, "assetdir")
            if asset is not None:
                mesh = texture = str(asset)
            mesh = str(get_attribute(section, "meshdir") or mesh)
            texture = str(get_attribute(section, "texturedir") or texture)
            strip = _true(get_attribute(section, "strippath") or strip)
        return cls(mesh=mesh, texture=texture, strip=strip)

    def folder(self, kind: Kind) -> str:
        """The folder setting that paths of ``kind`` resolve under."""
        return {"mesh": self.mesh, "texture": self.texture, "model": ""}[kind]

    def location(self, kind: Kind, base_dir: Path | None) -> Path:
        """The folder a relative path of ``kind`` resolves in (no base: the working folder)."""
        folder = self.folder(kind)
        root = base_dir if base_dir is not None else Path(os.getcwd())
        return Path(os.path.normpath(root / folder)) if folder else root

    def resolve(self, text: str, kind: Kind, base_dir: Path | None) -> Path:
        """Where MuJoCo looks for the file a path of ``kind`` names, read from ``base_dir``.

        Examples:
            >>> from pathlib import Path
            >>> Folders(mesh="meshes").resolve("arm.stl", "mesh", Path("/robots"))
            PosixPath('/robots/meshes/arm.stl')

        """
        return Path(os.path.normpath(self.location(kind, base_dir) / _effective(text, self, kind)))


@attrs.frozen
class FileReference:
    """One file path written in a model."""

    #: The element that names the file.
    element: AnyElement
    #: The element's schema key (``"asset/mesh"``, ``"include"``, ...).
    key: str
    #: The attribute holding the path.
    attribute: str
    #: The path as written.
    text: str
    #: Which folder the path resolves under.
    kind: Kind
    #: Where the file is (the path MuJoCo opens, when no asset dictionary provides it).
    path: Path
    #: The path MuJoCo looks up in an asset dictionary: folder and file name joined.
    lookup: str


def _effective(text: str, folders: Folders, kind: Kind) -> str:
    """The path MuJoCo uses: with ``strippath`` only the file name (includes keep theirs)."""
    if folders.strip and kind != "model":
        return PurePosixPath(text.replace("\\", "/")).name
    return text


def _lookup(text: str, folders: Folders, kind: Kind) -> str:
    folder = folders.folder(kind)
    return posixpath.normpath(posixpath.join(folder, text)) if folder else text


def element_file_references(
    element: AnyElement, key: str | None, folders: Folders, base_dir: Path | None
) -> Iterator[FileReference]:
    """The file paths ``element`` itself writes (its schema key ``key``), as MuJoCo reads them.

    Resolved under ``folders`` from ``base_dir``: :func:`file_references` for one element.

    Examples:
        >>> from mjcf_model import Mesh
        >>> [r.lookup for r in element_file_references(
        ...     Mesh(file="arm.stl"), "asset/mesh", Folders(mesh="meshes"), None)]
        ['meshes/arm.stl']

    """
    found = FILE_ATTRIBUTES.get(key or "")
    if found is None:
        return
    kind, attributes = found
    for attribute in attributes:
        value = get_attribute(element, attribute)
        if not isinstance(value, str) or not value:
            continue
        yield FileReference(
            element=element,
            key=str(key),
            attribute=attribute,
            text=value,
            kind=kind,
            path=folders.resolve(value, kind, base_dir),
            lookup=_lookup(_effective(value, folders, kind), folders, kind),
        )


def file_references(model: Mujoco) -> Iterator[FileReference]:
    """Every file path written in ``model`` (kept ``<include>`` elements, not their contents).

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><asset><texture type="2d" file="wood.png"/></asset></mujoco>')
        >>> [(r.key, r.attribute, r.text, r.kind) for r in file_references(model)]
        [('asset/texture', 'file', 'wood.png', 'texture')]

    """
    folders = Folders.of(model)
    for element, key, _ in keyed_walk(model):
        yield from element_file_references(element, key, folders, model.base_dir)


#: The schema keys of elements that write no file path (:func:`with_paths` skips them).
_WITHOUT_FILES = frozenset(SCHEMA) - FILE_ATTRIBUTES.keys()
#: The tags of the elements that may write one.
_FILE_TAGS = frozenset(key.rpartition("/")[2] for key in FILE_ATTRIBUTES)
#: The attributes that may hold a file path, by tag.
_FILE_ATTRIBUTE_NAMES = {
    tag: frozenset(
        name
        for key, (_, names) in FILE_ATTRIBUTES.items()
        if key.rpartition("/")[2] == tag
        for name in names
    )
    for tag in _FILE_TAGS
}
#: The top-level sections whose children write file paths (a section's key is its tag).
_FILE_SECTIONS = frozenset({"asset", "deformable"})


def _writes_file(node: Node) -> TypeGuard[AnyElement]:
    """Whether ``node`` is an element of a file-writing tag that writes a file path."""
    names = _FILE_ATTRIBUTE_NAMES.get(getattr(node, "tag", ""))
    if names is None or not isinstance(node, Element):
        return False
    return any(
        isinstance(get_attribute(node, name), str) and get_attribute(node, name) for name in names
    )


def with_paths(
    model: Mujoco, new_path: Callable[[FileReference], str], folders: Folders | None = None
) -> Mujoco:
    """``model`` with each file path replaced by ``new_path(reference)``; the rest is shared.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><asset><mesh file="a.stl"/></asset></mujoco>')
        >>> with_paths(model, lambda r: r.text.upper()).asset.elements[0].file
        'A.STL'

    """
    folders = folders if folders is not None else Folders.of(model)

    def visit(element: AnyElement, key: str | None, _: Sequence[AnyElement]) -> AnyElement:
        changes = {}
        for reference in element_file_references(element, key, folders, model.base_dir):
            text = new_path(reference)
            if text != reference.text:
                changes[reference.attribute] = text
        return with_attributes(element, changes)

    # A tree with an index (a loaded one): where every element of a file-writing tag
    # stands in a top-level section (``<asset>`` holds the meshes), only those sections
    # are rebuilt. Any other tree is walked once, leaves that write no file skipped.
    index = held_index(model)
    if index is None:
        return map_elements(visit, model, kept=_WITHOUT_FILES)
    found = sum(1 for tag in _FILE_TAGS for element in index.tagged(tag) if _writes_file(element))
    visited = 0
    sections: list[Node] = []
    for section in model.children:
        if isinstance(section, Element) and section.tag in _FILE_SECTIONS:
            inner: list[Node] = []
            for child in section.children:
                if _writes_file(child):
                    visited += 1
                    child = visit(child, child_key(section.tag, child.tag), ())
                inner.append(child)
            section = with_children(section, inner)
        elif _writes_file(section):
            visited += 1
            section = visit(section, child_key("mujoco", section.tag), ())
        sections.append(section)
    if visited == found:
        return with_children(model, sections)
    return map_elements(visit, model, kept=_WITHOUT_FILES)  # some stand deeper: walk them all


def relocated(
    model: Mujoco,
    base_dir: str | os.PathLike[str] | None,
    folders: Folders | None = None,
    *,
    source: Folders | None = None,
) -> Mujoco:
    """``model`` with its relative file paths rewritten to resolve from ``base_dir``.

    Each relative path is rewritten so that, read from ``base_dir`` under the
    compiler ``folders`` (by default the model's own), it names the file it
    names now. A path whose folder does not change is kept exactly as written,
    and absolute paths are kept. A model without a ``base_dir`` has paths that
    resolve from wherever it is used: they are taken as relative to the new
    place too, so only a change of compiler folder rewrites them. When the new
    ``base_dir`` is ``None`` (a model built in code), paths that resolved from
    a known folder become absolute. The result's ``<compiler>`` names ``folders``.

    Args:
        model: The model whose paths are rewritten.
        base_dir: The folder the result's paths should resolve from.
        folders: The compiler folders they should resolve under.
        source: The compiler folders they resolve under now (by default read
            from the model's top-level ``<compiler>`` sections).

    Raises:
        MjcfValueError: ``folders`` strips paths (``strippath``), and a file is
            not directly in its folder.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><include file="parts/arm.xml"/></mujoco>', base_dir="/robots")
        >>> relocated(model, "/robots/scenes").elements[0].file
        '../parts/arm.xml'

    """
    target_base = to_base_dir(base_dir)
    source = source if source is not None else Folders.of(model)
    target = folders if folders is not None else source
    source_base = model.base_dir if model.base_dir is not None else target_base
    if source_base == target_base and source == target:  # nothing can move: no walk
        return build_node(Mujoco, {"base_dir": target_base}, model)

    def new_path(reference: FileReference) -> str:
        text = _effective(reference.text, source, reference.kind)
        old = source.location(reference.kind, source_base)
        new = target.location(reference.kind, target_base)
        if os.path.isabs(text) or (old == new and source.strip == target.strip):
            return reference.text
        path = os.path.normpath(old / text)
        if target_base is None and source_base is not None:
            return path
        written = os.path.relpath(path, new)
        if target.strip and reference.kind != "model" and os.path.dirname(written):
            raise MjcfValueError(
                f'cannot refer to {path!r} from {str(new)!r}: the compiler\'s strippath="true" '
                "drops folder names; set strippath to false or move the file beside the model"
            )
        return written.replace(os.sep, "/")

    moved = with_paths(model, new_path, source)
    if folders is not None and target != source:
        moved = with_folders(moved, target)
    return build_node(Mujoco, {"base_dir": target_base}, moved)


def file_stem(text: str) -> str:
    r"""The name MuJoCo gives an asset named by its file: the file name without extension.

    Examples:
        >>> file_stem("meshes\\arm.link.stl")
        'arm.link'

    """
    return PurePosixPath(text.replace("\\", "/")).stem


#: The tags of elements that may name a file (see :data:`FILE_ATTRIBUTES`).
FILE_TAGS = frozenset(key.rpartition("/")[2] for key in FILE_ATTRIBUTES)


def with_included_paths(model: Mujoco, origins: Mapping[int, tuple[AnyElement, Path]]) -> Mujoco:
    """``model`` (its includes inlined) with paths written in included files made explicit.

    MuJoCo looks for a file named in an included file under the main model's
    folder first and then beside the included file. Once the include is
    inlined the second place is gone, so a path found only there is rewritten
    to name it from the main model's folder.

    Args:
        model: The model, with ``base_dir`` set to the main model's folder.
        origins: For each element that came from an included file, by ``id``:
            the element and that file's folder.

    Examples:
        >>> import pathlib, tempfile
        >>> from mjcf_model import loads
        >>> folder = pathlib.Path(tempfile.mkdtemp())
        >>> (folder / "parts").mkdir()
        >>> _ = (folder / "parts" / "arm.obj").write_text("v 0 0 0")
        >>> model = loads('<mujoco><asset><mesh file="arm.obj"/></asset></mujoco>', base_dir=folder)
        >>> mesh = model.asset.elements[0]
        >>> with_included_paths(model, {id(mesh): (mesh, folder / "parts")}).asset.elements[0].file
        'parts/arm.obj'

    """
    if not origins:
        return model
    folders = Folders.of(model)

    def new_path(reference: FileReference) -> str:
        origin = origins.get(id(reference.element))
        if origin is None or origin[0] is not reference.element or reference.path.exists():
            return reference.text
        text = _effective(reference.text, folders, reference.kind)
        beside = Path(os.path.normpath(origin[1] / text))
        if os.path.isabs(text) or not beside.exists():
            return reference.text
        written = os.path.relpath(beside, folders.location(reference.kind, model.base_dir))
        return written.replace(os.sep, "/")

    return with_paths(model, new_path)


def with_folders(model: Mujoco, folders: Folders) -> Mujoco:
    r"""``model`` whose ``<compiler>`` sections name ``folders`` and no other folder setting.

    ``Folders()`` removes them all: every path then names its file directly.

    Examples:
        >>> from mjcf_model import dumps, loads
        >>> model = loads('<mujoco><compiler meshdir="m" angle="radian"/></mujoco>')
        >>> dumps(with_folders(model, Folders()), canonical=True)
        '<mujoco>\n  <compiler angle="radian"/>\n</mujoco>\n'
        >>> dumps(with_folders(model, Folders(texture="t")), canonical=True)
        '<mujoco>\n  <compiler angle="radian" texturedir="t"/>\n</mujoco>\n'
        >>> empty = with_folders(loads('<mujoco><compiler meshdir="m"/></mujoco>'), Folders())
        >>> dumps(empty, canonical=True), dumps(empty)
        ('<mujoco/>\n', '<mujoco></mujoco>')

    """
    written = {
        "meshdir": folders.mesh or None,
        "texturedir": folders.texture or None,
        "assetdir": None,
        "strippath": "true" if folders.strip else None,
    }
    sections = [c for c in model.elements if c.tag == "compiler"]
    if not sections and not any(written.values()):
        return model
    children: list[Node] = []
    for child in model.children:
        if isinstance(child, Element) and child.tag == "compiler":
            changes = written if child is sections[-1] else dict.fromkeys(written)
            child = with_attributes(child, changes)
            if not attribute_items(child) and not child.children:
                continue  # nothing left to say: an empty <compiler/> is dropped
        children.append(child)
    if not sections and any(written.values()):
        children.insert(0, with_attributes(Compiler(), written))
    return with_children(model, children)
