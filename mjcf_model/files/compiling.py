"""Compiling a model in memory, and gathering every file it uses into one bundle.

:func:`compiled` hands MuJoCo the model's text and the bytes of every file it
names (MuJoCo's asset dictionary), so nothing is written and the model may
combine files from many folders. :func:`bundled` is the step both it and
:func:`serializers.export` take: every file path is replaced by a readable
name (the file's own name, made unique), identical contents are stored once,
and asset ``<model>`` files are bundled with their own files.

>>> from serializers import loads
>>> model = loads('<mujoco><worldbody><geom size="0.1"/></worldbody></mujoco>')
>>> compiled(model).ngeom
1
"""

from __future__ import annotations

import itertools
import os
from collections.abc import Mapping
from pathlib import Path, PurePosixPath
from typing import TYPE_CHECKING

import attrs

from mjcf_model.errors import Advice, MjcfAssetError, MjcfIncludeCycleError
from mjcf_model.files.compile_errors import compile_error
from mjcf_model.files.provenance import FileReference, Folders, with_folders, with_paths
from mjcf_model.nodes.asset import Skin
from mjcf_model.nodes.base import Element, Node
from mjcf_model.nodes.building import build_node
from mjcf_model.nodes.root import Mujoco
from mjcf_model.tree.traversal import keyed_walk, with_children

if TYPE_CHECKING:
    import mujoco

__all__ = ["Bundle", "bundled", "compiled", "inlined"]


@attrs.frozen
class Bundle:
    """A model whose file paths name entries of ``files``, and those entries."""

    #: The model, every path replaced by ``folder`` and a name of ``files``.
    model: Mujoco
    #: The contents of every file the model uses, by name (asset ``<model>`` files
    #: are stored as their bundled text, naming their files by bare name).
    files: dict[str, bytes]


class _Names:
    """Readable, unique file names: the file's own name, ``_2``, ``_3``... on a clash.

    Names that differ only in case clash too: a folder on macOS or Windows could
    not hold both.
    """

    def __init__(self) -> None:
        self.by_content: dict[bytes, str] = {}
        self.files: dict[str, bytes] = {}
        self.taken: set[str] = set()

    def name(self, wanted: str, data: bytes) -> str:
        known = self.by_content.get(data)
        if known is not None and PurePosixPath(known).suffix == PurePosixPath(wanted).suffix:
            return known
        path = PurePosixPath(wanted.replace("\\", "/")).name or "file"
        stem, suffix = PurePosixPath(path).stem, PurePosixPath(path).suffix
        name, count = path, 1
        while name.casefold() in self.taken:
            count += 1
            name = f"{stem}_{count}{suffix}"
        self.taken.add(name.casefold())
        self.files[name] = data
        self.by_content.setdefault(data, name)
        return name


def inlined(model: Mujoco) -> Mujoco:
    """``model`` with kept ``<include>`` elements replaced by their files' elements.

    The files are found from the model's ``base_dir`` (a model built in code:
    the working folder), as :func:`serializers.load` with ``inline_includes``
    finds them.

    Examples:
        >>> from serializers import loads
        >>> model = loads("<mujoco><worldbody/></mujoco>")
        >>> inlined(model) is model
        True

    """
    if not any(key == "include" for _, key, _ in keyed_walk(model)):
        return model
    from serializers import dumps, loads

    base = model.base_dir if model.base_dir is not None else Path(os.getcwd())
    return loads(dumps(model), inline_includes=True, base_dir=base)


def _read(reference: FileReference, assets: Mapping[str, bytes]) -> bytes:
    for key in (reference.lookup, reference.text):
        if key in assets:
            return assets[key]
    try:
        return reference.path.read_bytes()
    except OSError as error:
        name = reference.element.tag
        raise MjcfAssetError(
            f"<{name} {reference.attribute}={reference.text!r}>: cannot read "
            f"{str(reference.path)!r}: {error.strerror or error}",
            advice=Advice(
                "load the model from its file (so it knows its folder) or pass the file's "
                "bytes in assets=",
                "put the file where the model names it (beside the model, or under its "
                "meshdir/texturedir), or run the command on the model where its files are",
            ),
        ) from None


def bundled(
    model: Mujoco, *, assets: Mapping[str, bytes] | None = None, folder: str = ""
) -> Bundle:
    """``model`` with every file it names gathered under readable names.

    Args:
        model: The model; its files are found through its ``base_dir`` and
            compiler folders (:mod:`mjcf_model.files.provenance`), or in ``assets``.
        assets: File contents by the name the model uses (with or without the
            compiler folder), for models built in code.
        folder: Written before every name in the model (``"assets/"``).

    Raises:
        MjcfAssetError: A file cannot be read and is not in ``assets``.
        MjcfIncludeError: Asset ``<model>`` files refer to each other in a cycle.

    Examples:
        >>> from serializers import dumps, loads
        >>> model = loads('<mujoco><compiler meshdir="m"/><asset><mesh file="x/a.obj"/>'
        ...               '</asset></mujoco>')
        >>> bundle = bundled(model, assets={"m/x/a.obj": b"v 0 0 0"}, folder="assets/")
        >>> bundle.model.asset.elements[0].file, sorted(bundle.files)
        ('assets/a.obj', ['a.obj'])

    """
    return _bundled(model, dict(assets or {}), folder, on_disk=False)


def _bundled(model: Mujoco, assets: Mapping[str, bytes], folder: str, *, on_disk: bool) -> Bundle:
    """:func:`bundled`; with ``on_disk``, files that exist stay where they are, by absolute path."""
    names = _Names()
    result = _bundle(model, assets, folder, names, (), on_disk)
    return Bundle(model=result, files=names.files)


def _bundle(
    model: Mujoco,
    assets: Mapping[str, bytes],
    folder: str,
    names: _Names,
    chain: tuple[Path, ...],
    on_disk: bool,
) -> Mujoco:
    model = inlined(model)

    def new_path(reference: FileReference) -> str:
        if reference.key == "asset/model":
            data = _submodel_text(reference, assets, names, chain, on_disk)
        elif on_disk and _on_disk(reference, assets):
            return os.path.abspath(reference.path)
        else:
            data = _read(reference, assets)
        return folder + names.name(reference.text, data)

    return with_folders(with_paths(model, new_path), Folders())


def _on_disk(reference: FileReference, assets: Mapping[str, bytes]) -> bool:
    """Whether MuJoCo can read the file itself: not given in ``assets``, and a file on disk."""
    return (
        reference.lookup not in assets and reference.text not in assets and reference.path.is_file()
    )


def _submodel_text(
    reference: FileReference,
    assets: Mapping[str, bytes],
    names: _Names,
    chain: tuple[Path, ...],
    on_disk: bool,
) -> bytes:
    """The bundled text of an asset ``<model>`` file (its own paths resolve from its folder)."""
    from serializers import dumps, loads

    if reference.path in chain:
        cycle = " -> ".join(str(p) for p in (*chain, reference.path))
        raise MjcfIncludeCycleError(f"asset <model> files refer to each other: {cycle}")
    sub = loads(
        _read(reference, assets), base_dir=reference.path.parent, filename=str(reference.path)
    )
    bundled_sub = _bundle(sub, {}, "", names, (*chain, reference.path), on_disk)
    return dumps(bundled_sub).encode()


#: The fewest numbers an inline skin holds for :func:`compiled` to hand it over as a file.
_SKIN_FILE_NUMBERS = 3000


def _skins_as_files(model: Mujoco, files: dict[str, bytes]) -> tuple[Mujoco, dict[str, bytes]]:
    """``model`` with each big named inline skin given as a binary skin file in ``files``.

    MuJoCo reads a skin's float32 arrays from a file in a fraction of the time it
    parses them as text (a scaled copy of dm_control's dog writes 4.6 MB of skin
    numbers), and compiles the same model: the file holds the values MuJoCo would
    have rounded the text to (only ``paths`` records the file's name,
    ``mjcf-model-skin-0.skn``). An unnamed skin stays inline (MuJoCo would name it
    after the file), and so does one the format cannot hold (see
    :func:`serializers.skins.skin_file_bytes`).
    """
    from serializers.skins import skin_file_bytes

    added = dict(files)
    made = iter(f"mjcf-model-skin-{n}.skn" for n in itertools.count())

    def as_file(element: Node) -> Node:
        if not isinstance(element, Skin) or element.name is None or element.file is not None:
            return element
        data = None if len(element.vertex or ()) < _SKIN_FILE_NUMBERS else skin_file_bytes(element)
        if data is None:
            return element
        name = next(name for name in made if name not in added)
        added[name] = data
        changes = {"file": name, "vertex": None, "texcoord": None, "face": None}
        return build_node(Skin, {**changes, "children": ()}, element)

    sections = [  # skins stand only in these top-level sections
        with_children(section, [as_file(child) for child in section.children])
        if isinstance(section, Element) and getattr(section, "tag", "") in ("asset", "deformable")
        else section
        for section in model.children
    ]
    changed = with_children(model, sections)
    return (model, files) if changed is model else (changed, added)


def compiled(model: Mujoco, *, assets: Mapping[str, bytes] | None = None) -> mujoco.MjModel:
    r"""Compile ``model`` with MuJoCo in memory: nothing is written.

    Every file the model names is found where its provenance says it is
    (see :mod:`mjcf_model.files.provenance`): a loaded model's files resolve from its
    folder, the files of models attached from other folders from theirs. A
    model built in code resolves relative paths from the working folder, or
    takes the files from ``assets``. MuJoCo reads a file that exists on disk
    itself, by its absolute path (so its cache of decoded meshes and textures
    serves every compile of the same file); the text of asset ``<model>`` files
    and whatever ``assets`` gives go through MuJoCo's asset dictionary. The
    compiler's ``meshdir``, ``texturedir``, ``assetdir`` and ``strippath`` are
    resolved before MuJoCo sees the model.

    Args:
        model: The model.
        assets: File contents by the path the model writes (``"box.stl"``, or
            with the compiler folder, ``"meshes/box.stl"``).

    Raises:
        MjcfCompileError: MuJoCo rejects the model; the message is MuJoCo's, after the
            file, line and element path of the element it rejects
            (:mod:`mjcf_model.files.compile_errors`).
        MjcfAssetError: A file cannot be read and is not in ``assets``.

    Examples:
        >>> from serializers import loads
        >>> model = loads('<mujoco><asset><mesh name="m" file="tet.obj"/></asset>'
        ...               '<worldbody><geom type="mesh" mesh="m"/></worldbody></mujoco>')
        >>> points = "v 0 0 0 \n v 1 0 0 \n v 0 1 0 \n v 0 0 1 \n"
        >>> faces = "f 1 2 3 \n f 1 2 4 \n f 1 3 4 \n f 2 3 4"
        >>> tetrahedron = (points + faces).encode()
        >>> compiled(model, assets={"tet.obj": tetrahedron}).mesh_vertnum.tolist()
        [4]

    """
    import mujoco

    from serializers import dumps

    bundle = _bundled(model, dict(assets or {}), "", on_disk=True)
    given, files = _skins_as_files(bundle.model, bundle.files)
    text = dumps(given)
    try:
        return mujoco.MjModel.from_xml_string(text, files)
    except ValueError as error:
        raise compile_error(str(error), model, bundle, text) from None
