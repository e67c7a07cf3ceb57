"""``mjcf-model render``: a real picture, drawn offscreen (EGL, see .ci/run), read by Pillow."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from mjcf_model.files.png import png_bytes
from tests.support.rendering import _pixels, _scene, render


def test_a_rendered_model_is_a_picture_of_it(tmp_path: Path) -> None:
    """A 320 x 240 PNG, not blank; a red ball and a blue ball render differently."""
    red, blue = _scene(tmp_path, "red", "1 0 0 1"), _scene(tmp_path, "blue", "0 0 1 1")
    for path in (red, blue):
        done = render(
            str(path), "-o", str(path.with_suffix(".png")), "--width", "320", "--height", "240"
        )
        assert done.returncode == 0, done.stderr.decode()
    red_pixels = _pixels(red.with_suffix(".png").read_bytes())
    blue_pixels = _pixels(blue.with_suffix(".png").read_bytes())
    assert red_pixels.shape == (240, 320, 3)
    assert red_pixels.std() > 10  # not one colour
    assert not np.array_equal(red_pixels, blue_pixels)
    centre = (slice(100, 140), slice(140, 180))
    assert red_pixels[centre][..., 0].mean() > red_pixels[centre][..., 2].mean()
    assert blue_pixels[centre][..., 2].mean() > blue_pixels[centre][..., 0].mean()


def test_named_camera_and_stdout(tmp_path: Path) -> None:
    """--camera draws from the model's camera; - writes the PNG to standard output."""
    path = _scene(tmp_path, "red", "1 0 0 1")
    done = render(str(path), "-o", "-", "--camera", "top", "--width", "160", "--height", "120")
    assert done.returncode == 0, done.stderr.decode()
    pixels = _pixels(done.stdout)
    assert pixels.shape == (120, 160, 3)
    assert pixels[50:70, 70:90, 0].mean() > 100  # looking down at the red ball
    missing = render(str(path), "-o", str(tmp_path / "x.png"), "--camera", "side")
    assert missing.returncode == 2 and b"no camera named 'side'" in missing.stderr
    assert not (tmp_path / "x.png").exists()


def test_without_opengl_it_says_what_to_install(tmp_path: Path) -> None:
    """With a backend that cannot start here (GLFW, no display) the message names the fix."""
    path = _scene(tmp_path, "red", "1 0 0 1")
    done = render(
        str(path), "-o", str(tmp_path / "x.png"), env={"MUJOCO_GL": "glfw", "DISPLAY": ""}
    )
    assert done.returncode == 2
    assert b"apt install libegl1" in done.stderr and b"MUJOCO_GL=osmesa" in done.stderr
    assert not (tmp_path / "x.png").exists()


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
