"""``mjcf-model render FILE -o OUT.png``: a picture of the model, for people who would rather look.

On a machine without a display it draws through EGL (``MUJOCO_GL=egl``, chosen for
you) or OSMesa (``MUJOCO_GL=osmesa``); without any OpenGL it says what to install
and exits with status 2 (:mod:`mjcf_model.tools.render`).
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from mjcf_model.files.png import png_bytes
from mjcf_model.serializers.dumping import write_atomically
from mjcf_model.tools.cli.common import STDIO, Failed, add_model_argument, guarded, read_model
from mjcf_model.tools.render import choose_backend, render

__all__ = ["add_parsers"]


def _render(arguments: argparse.Namespace) -> int:

    if arguments.width <= 0 or arguments.height <= 0:
        raise Failed(f"the size must be positive, not {arguments.width} x {arguments.height}")
    choose_backend()  # before MuJoCo is imported

    model = read_model(arguments.file)
    pixels = render(
        model,
        camera=arguments.camera,
        width=arguments.width,
        height=arguments.height,
        key=arguments.key,
    )
    data = png_bytes(pixels)
    if arguments.output == STDIO:
        sys.stdout.buffer.write(data)
    else:
        write_atomically(data, arguments.output)
        seen = f"camera {arguments.camera!r}" if arguments.camera else "a free camera"
        state = f"keyframe {arguments.key!r}" if arguments.key else "its initial state"
        sys.stdout.write(
            f"wrote {arguments.output} ({arguments.width} x {arguments.height}, "
            f"from {seen}, in {state})\n"
        )
    return 0


def add_parsers(commands: Any) -> None:
    """Add ``render`` to the command line's verbs."""
    render = commands.add_parser(
        "render",
        help="draw a model offscreen into a PNG picture",
        description=(
            "Compile FILE, put it in its initial state (or a keyframe: --key) and draw it "
            "with MuJoCo's renderer "
            "into a PNG: from the named camera, or from a free camera that sees the whole "
            "model. Headless machines draw through EGL or OSMesa (set MUJOCO_GL to choose)."
        ),
    )
    add_model_argument(render)
    render.add_argument(
        "-o", "--output", required=True, metavar="OUT.png", help="the picture (- for stdout)"
    )
    render.add_argument("--camera", metavar="NAME", help="a camera of the model")
    render.add_argument(
        "--key", metavar="NAME", help="draw the model in this keyframe, not its initial state"
    )
    render.add_argument("--width", type=int, default=640, help="width in pixels (640)")
    render.add_argument("--height", type=int, default=480, help="height in pixels (480)")
    render.set_defaults(run=guarded(_render))
