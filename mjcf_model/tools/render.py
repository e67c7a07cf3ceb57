"""A picture of a model, drawn offscreen by MuJoCo's renderer.

MuJoCo draws with OpenGL. On a machine without a display, an offscreen backend is
needed: EGL (Debian: ``libegl1`` with Mesa's ``libgl1-mesa-dri``) or OSMesa
(``libosmesa6``), chosen with ``MUJOCO_GL=egl`` or ``MUJOCO_GL=osmesa`` *before*
MuJoCo is first imported. :func:`choose_backend` makes that choice for a fresh
process (the command line calls it first); without any OpenGL, :func:`render`
raises :class:`~mjcf_model.errors.MjcfRenderError` saying what to install.
"""

from __future__ import annotations

import os
import sys
from typing import Any

import numpy as np
import numpy.typing as npt

from mjcf_model.bridge.compiling import compiled
from mjcf_model.errors import MjcfLookupError, MjcfRenderError
from mjcf_model.nodes.root import Mujoco

__all__ = ["choose_backend", "render"]

#: What to install when no OpenGL backend works.
_INSTALL = (
    "MuJoCo found no OpenGL to draw with. On a machine without a display install an "
    "offscreen backend and name it before running: EGL (Debian: apt install libegl1 "
    "libgl1-mesa-dri; MUJOCO_GL=egl) or OSMesa (apt install libosmesa6; MUJOCO_GL=osmesa)"
)


def choose_backend() -> None:
    """Pick MuJoCo's OpenGL backend for this process, unless ``MUJOCO_GL`` names one.

    On Linux without a display this is EGL. It only takes effect before MuJoCo is
    first imported.
    """
    if sys.platform.startswith("linux") and not os.environ.get("DISPLAY"):
        if not os.environ.get("MUJOCO_GL"):  # unset or empty
            os.environ["MUJOCO_GL"] = "egl"


def render(
    model: Mujoco,
    *,
    camera: str | None = None,
    width: int = 640,
    height: int = 480,
    key: str | None = None,
) -> npt.NDArray[np.uint8]:
    """The model drawn in its initial state: an array of (height, width, 3) RGB pixels.

    Args:
        model: The model (compiled in memory, its files read from its provenance).
        camera: The name of a camera of the model; by default a free camera that
            looks at the whole model, as MuJoCo's viewer starts.
        width: The picture's width in pixels.
        height: Its height.
        key: The name of a keyframe to draw the model in (``mj_resetDataKeyframe``)
            instead of its initial state.

    Raises:
        MjcfCompileError: MuJoCo rejects the model.
        MjcfLookupError: The model has no camera or keyframe by that name (the
            message lists those it has).
        MjcfRenderError: No OpenGL backend works (the message says what to install).

    """
    try:
        import mujoco  # a MUJOCO_GL that cannot work fails here
    except Exception as error:  # RuntimeError, ImportError, AttributeError from PyOpenGL...
        raise MjcfRenderError(f"{_INSTALL} ({type(error).__name__}: {error})") from None

    compiled_model = compiled(model)
    if camera is not None:
        _named(compiled_model, mujoco.mjtObj.mjOBJ_CAMERA, "camera", camera)
    visual = compiled_model.vis.global_
    visual.offwidth, visual.offheight = max(width, visual.offwidth), max(height, visual.offheight)
    data = mujoco.MjData(compiled_model)
    if key is not None:
        index = _named(compiled_model, mujoco.mjtObj.mjOBJ_KEY, "keyframe", key)
        mujoco.mj_resetDataKeyframe(compiled_model, data, index)
    mujoco.mj_forward(compiled_model, data)
    try:
        renderer = mujoco.Renderer(compiled_model, height=height, width=width)
    except Exception as error:  # each backend fails its own way (ImportError, RuntimeError...)
        raise MjcfRenderError(f"{_INSTALL} ({type(error).__name__}: {error})") from None
    try:
        view: Any = camera
        if camera is None:
            view = mujoco.MjvCamera()
            mujoco.mjv_defaultFreeCamera(compiled_model, view)
        renderer.update_scene(data, camera=view)
        pixels: npt.NDArray[np.uint8] = renderer.render().copy()
    finally:
        renderer.close()
    return pixels


def _named(compiled_model: Any, kind: Any, what: str, name: str) -> int:
    """The id of the ``what`` called ``name``; else :class:`MjcfLookupError` listing names."""
    import mujoco

    index = int(mujoco.mj_name2id(compiled_model, kind, name))
    if index >= 0:
        return index
    count = {"camera": compiled_model.ncam, "keyframe": compiled_model.nkey}[what]
    names = [mujoco.mj_id2name(compiled_model, kind, i) for i in range(count)]
    named = [repr(n) for n in names if n]
    have = f"its {what}s: {', '.join(named)}" if named else f"it has no named {what}"
    raise MjcfLookupError(f"the model has no {what} named {name!r}; {have}")
