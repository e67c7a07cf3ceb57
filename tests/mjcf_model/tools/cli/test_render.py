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


def test_a_keyframe_is_drawn_and_the_picture_written_is_named(tmp_path: Path) -> None:
    """--key draws the model in that keyframe; a picture written to a file is reported.

    In the keyframe the ball slid out of the top camera's view; an unknown key lists the
    keys there are.
    """
    path = tmp_path / "slide.xml"
    path.write_text(
        _scene(tmp_path, "red", "1 0 0 1")
        .read_text()
        .replace(
            '<body name="ball" pos="0 0 0.2">',
            '<body name="ball" pos="0 0 0.2"><joint name="x" type="slide" axis="1 0 0"/>',
        )
        .replace("</worldbody>", '</worldbody><keyframe><key name="away" qpos="5"/></keyframe>')
    )
    size = ("--camera", "top", "--width", "160", "--height", "120")
    home, away = tmp_path / "home.png", tmp_path / "away.png"
    first = render(str(path), "-o", str(home), *size)
    second = render(str(path), "-o", str(away), *size, "--key", "away")
    assert first.returncode == second.returncode == 0, second.stderr.decode()
    assert second.stdout.decode() == (
        f"wrote {away} (160 x 120, from camera 'top', in keyframe 'away')\n"
    )
    assert first.stdout.decode().endswith("in its initial state)\n")
    centre = (slice(50, 70), slice(70, 90), 1)  # green: none in the red ball, much in the floor
    assert _pixels(home.read_bytes())[centre].mean() < 100  # the ball below the camera
    assert _pixels(away.read_bytes())[centre].mean() > 150  # moved away: the floor shows
    missing = render(str(path), "-o", str(tmp_path / "x.png"), "--key", "nope")
    assert missing.returncode == 2
    assert b"no keyframe named 'nope'; its keyframes: 'away'" in missing.stderr
