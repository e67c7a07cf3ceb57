"""Exporting a model as a self-contained folder: the XML and every file it uses.

>>> import pathlib, tempfile
>>> from mjcf_model import loads
>>> model = loads('<mujoco model="cube"><worldbody><geom size="0.1"/></worldbody></mujoco>')
>>> written = export(model, pathlib.Path(tempfile.mkdtemp()) / "cube")
>>> written.name, sorted(p.name for p in written.parent.iterdir())
('cube.xml', ['cube.xml'])
"""

from __future__ import annotations

import os
import re
import secrets
import shutil
from collections.abc import Mapping
from pathlib import Path

from mjcf_model.errors import MjcfAssetError, MjcfValueError
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers.bundling import bundled
from mjcf_model.serializers.dumping import dumps
from mjcf_model.values.encoding import encoded

__all__ = ["ASSET_FOLDER", "export"]

#: The subfolder of an exported folder that holds the model's files.
ASSET_FOLDER = "assets"
#: Characters kept in the XML file's name; others become ``_``.
_UNSAFE = re.compile(r"[^A-Za-z0-9._-]")


def _xml_name(model: Mujoco) -> str:
    name = _UNSAFE.sub("_", model.model or "").strip("._")
    return f"{name or 'model'}.xml"


def export(
    model: Mujoco,
    directory: str | os.PathLike[str],
    *,
    assets: Mapping[str, bytes] | None = None,
) -> Path:
    """Write ``model`` and every file it uses into ``directory``; return the XML's path.

    The XML is named after the model (``<mujoco model=...>``, else
    ``model.xml``); meshes, textures, height fields, skins and asset
    ``<model>`` files go to ``assets/`` under their own names. Files with the
    same content are stored once; different files with the same name are told
    apart by ``_2``, ``_3``... in the order the model names them. Included files
    are inlined. The folder can be moved anywhere: every path in it is relative.

    The folder is written beside its final place and then renamed, so it either
    appears complete or not at all.

    Args:
        model: The model; its files are found through its provenance
            (:mod:`mjcf_model.files.provenance`) or in ``assets``.
        directory: A folder that does not exist yet, or is empty.
        assets: File contents by the path the model writes, for models built in code.

    Raises:
        MjcfValueError: ``directory`` exists and is not an empty folder.
        MjcfAssetError: A file the model names cannot be read, or the folder
            cannot be written.

    Examples:
        >>> import pathlib, tempfile
        >>> from mjcf_model import load, loads
        >>> model = loads('<mujoco><asset><texture name="t" type="2d" file="../img/wood.png"/>'
        ...               '</asset></mujoco>')
        >>> folder = pathlib.Path(tempfile.mkdtemp()) / "scene"
        >>> path = export(model, folder, assets={"../img/wood.png": b"not really a png"})
        >>> sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))
        ['assets', 'assets/wood.png', 'model.xml']
        >>> load(path).asset.elements[0].file
        'assets/wood.png'

    """
    target = Path(directory)
    if target.exists() and (not target.is_dir() or any(target.iterdir())):
        raise MjcfValueError(
            f"cannot export into {str(target)!r}: it exists and is not an empty folder; "
            "choose a new folder"
        )
    bundle = bundled(model, assets=assets, folder=f"{ASSET_FOLDER}/")
    xml_name = _xml_name(model)
    try:
        _write_folder(target, xml_name, encoded(dumps(bundle.model)), bundle.files)
    except OSError as error:
        raise MjcfAssetError(
            f"cannot write {str(target)!r}: {error.strerror or error}; nothing was written"
        ) from None
    return target / xml_name


def _write_folder(target: Path, xml_name: str, xml: bytes, files: Mapping[str, bytes]) -> None:
    """Write the folder beside ``target``, flush it to disk, then rename it into place."""
    target.parent.mkdir(parents=True, exist_ok=True)
    staging = target.parent / f".{target.name}.{secrets.token_hex(6)}.tmp"
    staging.mkdir()  # not mkdtemp: the folder gets the usual permissions, not 0700
    try:
        _write_file(staging / xml_name, xml)
        if files:
            (staging / ASSET_FOLDER).mkdir()
        for name, data in files.items():
            _write_file(staging / ASSET_FOLDER / name, data)
        if target.exists():
            target.rmdir()
        os.replace(staging, target)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise


def _write_file(path: Path, data: bytes) -> None:
    with open(path, "wb") as stream:
        stream.write(data)
        stream.flush()
        os.fsync(stream.fileno())
