"""The scene the render tests draw, and ``mjcf-model render`` run in a fresh process."""

from __future__ import annotations

import io
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
from PIL import Image

SCENE = """<mujoco model="scene">
  <worldbody>
    <light pos="0 0 3" dir="0 0 -1"/>
    <camera name="top" pos="0 0 2" xyaxes="1 0 0 0 1 0"/>
    <geom name="floor" type="plane" size="1 1 0.1" rgba="0.9 0.9 0.9 1"/>
    <body name="ball" pos="0 0 0.2"><geom type="sphere" size="0.2" rgba="{color}"/></body>
  </worldbody>
</mujoco>
"""


def render(
    *arguments: str, env: dict[str, str] | None = None
) -> subprocess.CompletedProcess[bytes]:
    """``mjcf-model render ARGUMENTS`` in a fresh process (no MUJOCO_GL: the verb chooses)."""
    base = {k: v for k, v in os.environ.items() if k not in ("MUJOCO_GL", "PYOPENGL_PLATFORM")}
    return subprocess.run(
        [sys.executable, "-m", "mjcf_model", "render", *arguments],
        capture_output=True,
        check=False,
        env={**base, **(env or {})},
    )


def _scene(folder: Path, name: str, color: str) -> Path:
    path = folder / f"{name}.xml"
    path.write_text(SCENE.format(color=color))
    return path


def _pixels(data: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(data)).convert("RGB"))
