"""Gathering every file a model uses into one bundle.

:func:`bundled` replaces every file path by a readable name (the file's own
name, made unique), stores identical contents once, and bundles asset
``<model>`` files with their own files. :func:`mjcf_model.serializers.export` writes a
bundle into a folder; :func:`mjcf_model.compiled` hands one to MuJoCo.

>>> from mjcf_model import loads
>>> model = loads('<mujoco><asset><texture name="t" file="a/sky.png"/></asset></mujoco>')
>>> bundle = bundled(model, assets={"a/sky.png": b"PNG"})
>>> bundle.model.asset.elements[0].file, bundle.files
('sky.png', {'sky.png': b'PNG'})
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path, PurePosixPath

import attrs

from mjcf_model.errors import Advice, MjcfAssetError, MjcfIncludeCycleError
from mjcf_model.files.provenance import FileReference, Folders, with_folders, with_paths
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers.dumping import dumps, inlined_includes
from mjcf_model.serializers.loading import loads
from mjcf_model.serializers.locations import located_in, read_from
from mjcf_model.values.encoding import encoded

__all__ = ["Bundle", "bundled", "bundled_on_disk"]


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


def _read(reference: FileReference, assets: Mapping[str, bytes]) -> bytes:
    for key in (reference.lookup, reference.text):
        if key in assets:
            return assets[key]
    try:
        return reference.path.read_bytes()
    except OSError as error:
        name = reference.element.tag
        file, _ = read_from(reference.element)
        problem = MjcfAssetError(
            f"<{name} {reference.attribute}={reference.text!r}>: cannot read "
            f"{str(reference.path)!r}: {error.strerror or error}",
            advice=_FROM_A_FILE if file is not None and not file.startswith("<") else _IN_CODE,
        )
        problem.errno, problem.strerror = error.errno, error.strerror
        problem.filename = str(reference.path)
        raise problem from None


#: What to do about a file that cannot be read, named in a model read from a file.
_FROM_A_FILE = Advice(
    "put the file where the model names it (relative paths resolve from the model's "
    "folder, under its meshdir, texturedir or assetdir), or pass its bytes in assets=",
    "put the file where the model names it (relative paths resolve from the model's "
    "folder, under its meshdir, texturedir or assetdir)",
)
#: The same, named in a model built in code or read from text.
_IN_CODE = Advice(
    "load the model from its file (so it knows its folder), give loads() base_dir=, or "
    "pass the file's bytes in assets=",
    "put the file where the model names it (beside the model, or under its "
    "meshdir/texturedir), or run the command on the model where its files are",
)


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
        >>> from mjcf_model import dumps, loads
        >>> model = loads('<mujoco><compiler meshdir="m"/><asset><mesh file="x/a.obj"/>'
        ...               '</asset></mujoco>')
        >>> bundle = bundled(model, assets={"m/x/a.obj": b"v 0 0 0"}, folder="assets/")
        >>> bundle.model.asset.elements[0].file, sorted(bundle.files)
        ('assets/a.obj', ['a.obj'])

    """
    return _bundled(model, dict(assets or {}), folder, on_disk=False)


def bundled_on_disk(model: Mujoco, assets: Mapping[str, bytes]) -> Bundle:
    """:func:`bundled`, except that files MuJoCo can read itself stay where they are.

    A file not given in ``assets`` that exists on disk is named by its absolute path,
    so MuJoCo reads it (and its cache of decoded meshes and textures serves every
    compile of the same file).
    """
    return _bundled(model, assets, "", on_disk=True)


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
    model = inlined_includes(model)

    def new_path(reference: FileReference) -> str:
        if reference.key == "asset/model":
            data = _submodel_text(reference, assets, names, chain, on_disk)
        elif on_disk and _on_disk(reference, assets):
            return os.path.abspath(reference.path)
        else:
            try:
                data = _read(reference, assets)
            except MjcfAssetError as error:
                raise located_in(error, model, reference.element) from None
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
    if reference.path in chain:
        cycle = " -> ".join(str(p) for p in (*chain, reference.path))
        raise MjcfIncludeCycleError(f"asset <model> files refer to each other: {cycle}")
    sub = loads(
        _read(reference, assets), base_dir=reference.path.parent, filename=str(reference.path)
    )
    bundled_sub = _bundle(sub, {}, "", names, (*chain, reference.path), on_disk)
    return encoded(dumps(bundled_sub))
