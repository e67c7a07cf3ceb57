"""PNG images written without an imaging library: 8-bit RGB or RGBA pixels, unfiltered rows.

>>> import numpy as np
>>> data = png_bytes(np.zeros((2, 3, 3), dtype=np.uint8))
>>> data.startswith(bytes([137]) + b"PNG"), int.from_bytes(data[16:20], "big")  # its width
(True, 3)
"""

from __future__ import annotations

import struct
import zlib
from typing import Any

import numpy as np
import numpy.typing as npt

__all__ = ["png_bytes"]

#: PNG's colour type for each number of channels.
_COLOR_TYPES = {3: 2, 4: 6}


def png_bytes(pixels: npt.NDArray[Any]) -> bytes:
    """The PNG file of ``pixels``: an array of shape (height, width, 3 or 4), 0 to 255.

    Raises:
        ValueError: ``pixels`` is not of that shape.

    """
    image = np.ascontiguousarray(pixels, dtype=np.uint8)
    if image.ndim != 3 or image.shape[2] not in _COLOR_TYPES:
        raise ValueError(f"expected (height, width, 3 or 4) pixels, found shape {pixels.shape}")
    height, width, channels = image.shape
    header = struct.pack(">IIBBBBB", width, height, 8, _COLOR_TYPES[channels], 0, 0, 0)
    rows = b"".join(b"\x00" + row.tobytes() for row in image)  # filter 0: each row as it is
    return (
        b"\x89PNG\r\n\x1a\n"
        + _chunk(b"IHDR", header)
        + _chunk(b"IDAT", zlib.compress(rows))
        + _chunk(b"IEND", b"")
    )


def _chunk(kind: bytes, data: bytes) -> bytes:
    crc = zlib.crc32(kind + data) & 0xFFFFFFFF
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc)
