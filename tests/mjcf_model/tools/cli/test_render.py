"""Tests of ``mjcf_model.tools.cli.render``."""

from __future__ import annotations

from pathlib import Path

from tests.support.rendering import _pixels, _scene, render

# -- ``mjcf-model render``: a real picture, drawn offscreen (EGL, see .ci/run), read by Pillow.


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
