r"""MuJoCo's binary skin files (``.skn``): reading them, and inlining them into a model.

A skin loaded from a file names the bodies it is bound to inside that file, so
renaming those bodies (prefixing, attaching two copies) breaks the model unless
the skin is written inline first: :func:`inline_skin_files` does that, and
:func:`skin_bone_names` tells which names a skin file uses.

The format: four int32 counts (vertices, texture coordinates, faces, bones),
the vertex (3 float32 each), texture coordinate (2 float32) and face (3 int32)
arrays, then per bone a 40-byte name, its bind position (3 float32) and
quaternion (4 float32), a vertex count and that many vertex ids (int32) and
weights (float32).

>>> import struct, tempfile, os
>>> data = struct.pack("<4i", 1, 0, 0, 1) + struct.pack("<3f", 0.5, 0, 0)
>>> data += b"torso".ljust(40, b"\0") + struct.pack("<7f", 0, 0, 0, 1, 0, 0, 0)
>>> data += struct.pack("<i", 1) + struct.pack("<i", 0) + struct.pack("<f", 1)
>>> with tempfile.NamedTemporaryFile(suffix=".skn", delete=False) as f:
...     _ = f.write(data)
>>> skin = read_skin(f.name)
>>> skin.vertex, skin.children[0].body, skin.children[0].vertweight
((0.5, 0.0, 0.0), 'torso', (1.0,))
>>> os.unlink(f.name)
"""

from __future__ import annotations

import decimal
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any, TypeVar, cast

import numpy as np
from numpy.typing import NDArray

from mjcf_model.caching import BoundedCache
from mjcf_model.errors import MjcfAssetError, MjcfSyntaxError
from mjcf_model.files.provenance import Folders, element_file_references, file_stem
from mjcf_model.nodes.asset import Bone, Skin
from mjcf_model.nodes.base import (
    AnyElement,
    Comment,
    Element,
    Node,
    attribute_items,
    get_attribute,
    with_attributes,
)
from mjcf_model.nodes.building import build_node
from mjcf_model.nodes.root import Mujoco
from mjcf_model.tree.traversal import SKIN_KEYS, with_children
from mjcf_model.values import format_float
from mjcf_model.values.writing import LONG_LIST, remember_text

__all__ = [
    "inline_skin_files",
    "read_skin",
    "skin_bone_names",
    "skin_file_bytes",
]

_N = TypeVar("_N", bound=Node)

_NAME_BYTES = 40


class _Reader:
    def __init__(self, data: bytes, path: str) -> None:
        self.data, self.offset, self.path = data, 0, path

    def take(self, dtype: str, count: int) -> NDArray[Any]:
        size = np.dtype(dtype).itemsize * count
        if self.offset + size > len(self.data):
            raise MjcfSyntaxError("not a MuJoCo skin file: it ends too early", file=self.path)
        values = np.frombuffer(self.data, dtype=dtype, count=count, offset=self.offset)
        self.offset += size
        return values

    def name(self) -> str:
        raw = self.data[self.offset : self.offset + _NAME_BYTES]
        self.offset += _NAME_BYTES
        try:
            return raw.split(b"\0", 1)[0].decode()
        except UnicodeDecodeError as error:
            raise MjcfSyntaxError(f"not a MuJoCo skin file: {error}", file=self.path) from None


def _floats(values: NDArray[Any]) -> tuple[float, ...] | None:
    return tuple(values.astype(float).tolist()) if len(values) else None


def _ints(values: NDArray[Any]) -> tuple[int, ...]:
    return tuple(values.astype(int).tolist())


def read_skin(path: str | os.PathLike[str]) -> Skin:
    """A binary skin file as an inline ``<skin>`` node (vertices, faces, bones).

    The float32 values of the file are kept exactly, so MuJoCo compiles the same skin.
    A file read before and unchanged since (same size and modification time) is
    not read again (same file, size and times): renaming a model's bodies reads its
    skins each time.
    """
    found = Path(path).stat()
    key = (
        os.path.abspath(path),
        found.st_ino,
        found.st_size,
        found.st_mtime_ns,
        found.st_ctime_ns,
    )
    skin = _READ.get(key)
    if skin is None:
        skin = _READ.remember(key, _read_skin(path))
    return skin


#: Skins read, by path, size and modification time (a few: scenes hold few skin files).
_READ: BoundedCache[tuple[str, int, int, int, int], Skin] = BoundedCache(16)


def _read_skin(path: str | os.PathLike[str]) -> Skin:
    reader = _Reader(Path(path).read_bytes(), str(path))
    nvertex, ntexcoord, nface, nbone = (int(n) for n in reader.take("<i4", 4))
    if min(nvertex, ntexcoord, nface, nbone) < 0:
        raise MjcfSyntaxError("not a MuJoCo skin file: negative counts", file=str(path))
    vertex = reader.take("<f4", 3 * nvertex)
    texcoord = reader.take("<f4", 2 * ntexcoord)
    face = reader.take("<i4", 3 * nface)
    bones = []
    for _ in range(nbone):
        body = reader.name()
        bind = reader.take("<f4", 7)
        (count,) = reader.take("<i4", 1)
        ids = reader.take("<i4", int(count))
        weights = reader.take("<f4", int(count))
        bones.append(
            Bone(
                body=body,
                bindpos=_floats(bind[:3]),
                bindquat=_floats(bind[3:]),
                vertid=_ints(ids),
                vertweight=_floats(weights),
            )
        )
    if reader.offset != len(reader.data):
        left = len(reader.data) - reader.offset
        raise MjcfSyntaxError(
            f"not a MuJoCo skin file: {left} bytes after the last bone", file=str(path)
        )
    skin = Skin(
        vertex=_floats(vertex),
        texcoord=_floats(texcoord),
        face=_ints(face) or None,
        children=bones,
    )
    return _with_remembered_texts(skin)


def _with_remembered_texts(skin: Skin) -> Skin:
    """``skin``, its long number lists formatted once and remembered (:func:`remember_text`).

    A skin file holds tens of thousands of numbers; written inline they are most of a
    model's text. The file is read once (see :data:`_READ`), and every model that writes
    the skin inline (prefixing renames its bones' bodies) copies the numbers' text
    instead of formatting them again.
    """
    for node in (skin, *skin.children):
        for _, value in attribute_items(cast(AnyElement, node)):
            if isinstance(value, tuple) and len(value) >= LONG_LIST:
                remember_text(value)
    return skin


def float32_as_written(values: Sequence[float]) -> NDArray[np.float32]:
    """``values`` in float32 as MuJoCo reads their written text: the decimal rounded once.

    Rounding a double to float32 rounds twice (text to double, double to float32);
    MuJoCo rounds the text itself. The two differ where the double lies exactly
    halfway between two float32 values and its shortest text does not: that text
    is on one side of the midpoint, and decides.

    Examples:
        >>> halfway = 0.31089024245738983  # between two float32 values, exactly
        >>> float(np.float32(halfway)), float(float32_as_written([halfway])[0])
        (0.310890257358551, 0.31089022755622864)

    """
    doubles = np.asarray(values, dtype=float)
    rounded = doubles.astype(np.float32)
    back = rounded.astype(float)
    toward = np.where(doubles > back, np.float32(np.inf), np.float32(-np.inf))
    other = np.nextafter(rounded, toward)
    halfway = np.nonzero((doubles != back) & (doubles == (back + other.astype(float)) / 2))[0]
    for index in halfway.tolist():
        exact = decimal.Decimal(float(doubles[index]))
        text = decimal.Decimal(format_float(float(doubles[index])))
        if text != exact:  # the text's side of the midpoint, not the even neighbour
            below, above = sorted((rounded[index], other[index]))
            rounded[index] = above if text > exact else below
    return rounded


def skin_file_bytes(skin: Skin) -> bytes | None:
    """An inline skin's vertices, faces and bones as a binary skin file (mirrors :func:`read_skin`).

    ``None`` when the file cannot hold the skin exactly: a bone name of 40 bytes or
    more, a bone without its four arrays, children other than bones and comments,
    or counts that do not fit the format.

    Examples:
        >>> from mjcf_model.nodes.asset import Asset, Bone, Skin
        >>> bone = Bone(body="torso", bindpos=[0, 0, 0], bindquat=[1, 0, 0, 0],
        ...             vertid=[0], vertweight=[1])
        >>> data = skin_file_bytes(Skin(vertex=[0.5, 0, 0], children=[bone]))
        >>> len(data), skin_file_bytes(Skin(vertex=[0.5, 0], children=[bone]))
        (108, None)

    """
    vertex, texcoord, face = skin.vertex or (), skin.texcoord or (), skin.face or ()
    if len(vertex) % 3 or len(face) % 3 or len(texcoord) not in (0, 2 * len(vertex) // 3):
        return None
    bones = [child for child in skin.children if not isinstance(child, Comment)]
    header = np.array([len(vertex) // 3, len(texcoord) // 2, len(face) // 3, len(bones)], "<i4")
    parts = [header.tobytes()]
    parts += (_written(vertex), _written(texcoord))
    parts.append(np.asarray(face, "<i4").tobytes())
    for bone in bones:
        if not isinstance(bone, Bone) or bone.extra or bone.children or bone.text:
            return None
        bindpos, bindquat = bone.bindpos or (), bone.bindquat or ()
        vertid, vertweight = bone.vertid or (), bone.vertweight or ()
        name = (bone.body or "").encode()
        if len(name) >= _NAME_BYTES or b"\0" in name or len(bindpos) != 3 or len(bindquat) != 4:
            return None
        if not vertid or len(vertid) != len(vertweight):
            return None
        parts += (name.ljust(_NAME_BYTES, b"\0"), _written((*bindpos, *bindquat)))
        parts += (np.array([len(vertid)], "<i4").tobytes(), np.asarray(vertid, "<i4").tobytes())
        parts.append(_written(vertweight))
    return b"".join(parts)


def _written(values: Sequence[float]) -> bytes:
    return float32_as_written(values).astype("<f4").tobytes()


def skin_bone_names(path: str | os.PathLike[str]) -> tuple[str, ...]:
    """The body names a binary skin file binds its bones to, in file order."""
    return tuple(str(bone.body) for bone in read_skin(path).children if isinstance(bone, Bone))


def inline_skin_files(node: _N, directory: str | os.PathLike[str] | None = None) -> _N:
    """``node`` with every skin read from a file written inline instead.

    Skin files are found as MuJoCo finds them (:mod:`mjcf_model.files.provenance`):
    under the compiler's ``meshdir`` (or ``assetdir``), from ``directory``, the
    folder of the model file (by default the model's own ``base_dir``). Returned as
    it is: a node that is not a whole model, a model that reads no skin from a file,
    and a model that does not know its folder (built in code, or read from text
    without ``base_dir``) when ``directory`` is not given. The transforms call it on
    every model they rename or scale (a skin file names bodies, and holds lengths).

    Examples:
        >>> from mjcf_model import loads
        >>> m = loads('<mujoco><worldbody/></mujoco>')
        >>> inline_skin_files(m, ".") is m
        True

    """
    if not isinstance(node, Mujoco) or (directory is None and node.base_dir is None):
        return node
    # Skins stand only in the top-level sections: no need to walk the bodies, and only
    # the skins' paths are resolved.
    sections = [
        (index, section)
        for index, section in enumerate(node.children)
        if isinstance(section, Element)
        and section.tag in _SKIN_SECTIONS
        and any(get_attribute(e, "file") for e in section.elements if e.tag == "skin")
    ]
    if not sections:
        return node
    base_dir = Path(directory) if directory is not None else node.base_dir
    folders = Folders.of(node)
    children = list(node.children)
    for index, section in sections:
        key = f"{section.tag}/skin"
        children[index] = with_children(
            section,
            [
                _inlined_skin(child, key, folders, base_dir)
                if isinstance(child, Element) and child.tag == "skin"
                else child
                for child in section.children
            ],
        )
    return cast(_N, with_children(node, children))


#: The sections whose ``<skin>`` elements may read a file (the first part of their keys).
_SKIN_SECTIONS = frozenset(key.partition("/")[0] for key in SKIN_KEYS)


def _inlined_skin(
    element: AnyElement, key: str, folders: Folders, base_dir: Path | None
) -> AnyElement:
    """``element`` with the skin its file holds written inline (itself, when it names none)."""
    reference = next(element_file_references(element, key, folders, base_dir), None)
    if reference is None:
        return element
    try:
        data = read_skin(reference.path)
    except OSError as error:
        raise MjcfAssetError(
            f"cannot read skin file {str(reference.path)!r}: {error.strerror or error}"
        ) from None
    name = get_attribute(element, "name") or file_stem(reference.text)
    inline = with_attributes(
        element,
        {
            "file": None,
            "name": name,
            "vertex": data.vertex,
            "texcoord": data.texcoord,
            "face": data.face,
        },
    )
    return build_node(type(inline), {"children": (*inline.children, *data.children)}, inline)
