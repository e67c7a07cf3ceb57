"""Reading the bone names out of MuJoCo's binary skin files (``.skn``).

A skin loaded from a file names the bodies it is bound to inside that file, so
renaming those bodies in the XML breaks the model; :func:`skin_bone_names` tells
which names to leave alone (``prefixed(model, p, exclude=skin_bone_names(f))``).

The format: four int32 counts (vertices, texture coordinates, faces, bones),
the vertex, texture coordinate and face arrays, then per bone a 40-byte name,
its bind position (3 float32) and quaternion (4 float32), a vertex count and
that many vertex ids (int32) and weights (float32).
"""

from __future__ import annotations

import os
import struct

from mjcf_model.errors import MjcfSyntaxError

__all__ = ["skin_bone_names"]

_NAME_BYTES = 40
_BIND_BYTES = 7 * 4


def skin_bone_names(path: str | os.PathLike[str]) -> tuple[str, ...]:
    r"""The body names a binary skin file binds its bones to, in file order.

    Example:
        >>> import struct, tempfile, os
        >>> data = struct.pack("<4i", 0, 0, 0, 1) + b"torso".ljust(40, b"\0")
        >>> data += struct.pack("<7f", 0, 0, 0, 1, 0, 0, 0) + struct.pack("<i", 0)
        >>> with tempfile.NamedTemporaryFile(suffix=".skn", delete=False) as f:
        ...     _ = f.write(data)
        >>> skin_bone_names(f.name)
        ('torso',)
        >>> os.unlink(f.name)

    """
    data = open(path, "rb").read()  # noqa: SIM115  (closed on return)
    try:
        nvertex, ntexcoord, nface, nbone = struct.unpack_from("<4i", data, 0)
        offset = 16 + 4 * (3 * nvertex + 2 * ntexcoord + 3 * nface)
        names = []
        for _ in range(nbone):
            raw = data[offset : offset + _NAME_BYTES]
            names.append(raw.split(b"\0", 1)[0].decode())
            offset += _NAME_BYTES + _BIND_BYTES
            (count,) = struct.unpack_from("<i", data, offset)
            offset += 4 + 8 * count
    except (struct.error, UnicodeDecodeError) as error:
        raise MjcfSyntaxError(f"not a MuJoCo skin file: {error}", file=str(path)) from error
    if offset != len(data):
        raise MjcfSyntaxError(
            f"not a MuJoCo skin file: {len(data) - offset} bytes left after the last bone",
            file=str(path),
        )
    return tuple(names)
