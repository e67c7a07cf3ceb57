"""Tests of ``mjcf_model.files.png``."""

from __future__ import annotations

import io

import numpy as np
import pytest
from PIL import Image

from mjcf_model.files.png import png_bytes

# -- ``mjcf-model render``: a real picture, drawn offscreen (EGL, see .ci/run), read by Pillow.


@pytest.mark.parametrize("shape", [(2, 3, 3), (5, 1, 4), (1, 1, 3)])
def test_png_writer_is_read_back_by_pillow(shape: tuple[int, int, int]) -> None:
    """The PNG writer's files are read by an independent decoder to the same pixels."""
    pixels = np.arange(np.prod(shape), dtype=np.uint8).reshape(shape)
    mode = "RGB" if shape[2] == 3 else "RGBA"
    assert np.array_equal(
        np.asarray(Image.open(io.BytesIO(png_bytes(pixels))).convert(mode)), pixels
    )
    with pytest.raises(ValueError, match="height, width, 3 or 4"):
        png_bytes(np.zeros((2, 2)))
