"""Tests of ``mjcf_model.tools.render``."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from tests.support.rendering import _pixels, _scene, render

# -- ``mjcf-model render``: a real picture, drawn offscreen (EGL, see .ci/run), read by Pillow.


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


def test_without_opengl_it_says_what_to_install(tmp_path: Path) -> None:
    """With a backend that cannot start here (GLFW, no display) the message names the fix."""
    path = _scene(tmp_path, "red", "1 0 0 1")
    done = render(
        str(path), "-o", str(tmp_path / "x.png"), env={"MUJOCO_GL": "glfw", "DISPLAY": ""}
    )
    assert done.returncode == 2
    assert b"apt install libegl1" in done.stderr and b"MUJOCO_GL=osmesa" in done.stderr
    assert not (tmp_path / "x.png").exists()
