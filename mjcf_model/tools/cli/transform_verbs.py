"""The transforms from the shell: ``compose``, ``prefix``, ``scale`` and ``export``.

Every result is compiled with MuJoCo before it is written: a model MuJoCo rejects
is not written, and the command says why (exit status 2).

Example:
    >>> import pathlib, tempfile
    >>> from mjcf_model.tools.cli import main
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (folder / "cup.xml").write_text(
    ...     '<mujoco><worldbody><body name="cup"><geom size="0.1"/></body></worldbody></mujoco>')
    >>> scene = str(folder / "scene.xml")
    >>> cup = str(folder / "cup.xml")
    >>> import contextlib, io
    >>> with contextlib.redirect_stdout(io.StringIO()) as said:  # b_cup half a metre to -y
    ...     status = main(["compose", scene, cup, f"{cup}:b_", "pos=0,-0.5,0"])
    >>> status, said.getvalue().split(": ", 2)[1] == f"1 part attached to {cup}; MuJoCo compiles it"
    (0, True)
    >>> from mjcf_model import load
    >>> world = load(scene).worldbody
    >>> [body.name for body in world.bodies], [body.name for body in world.frames[-1].bodies]
    (['cup'], ['b_cup'])

"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from mjcf_model.bridge.compiling import compiled
from mjcf_model.errors import MjcfCompileError
from mjcf_model.nodes.base import AnyElement
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers import export
from mjcf_model.tools.cli.common import (
    STDIO,
    Failed,
    add_model_argument,
    guarded,
    read_model,
    write_model,
)
from mjcf_model.tools.cli.parts import PLACEMENT_FORM, parts_of, split_part
from mjcf_model.transforms.composition.attaching import attach_all
from mjcf_model.transforms.composition.shared_assets import shared_assets
from mjcf_model.transforms.naming.renaming import prefixed
from mjcf_model.transforms.scaling.transform import scaled

__all__ = ["add_parsers", "split_part"]


_COMPOSE_DESCRIPTION = """\
Read BASE, attach each PART to it (at the world, or at the body, frame or site its
@NAME or --at names), each with its names prefixed by PREFIX, check that MuJoCo
compiles the scene, and write it to OUT (- for stdout). Each model keeps its own
<compiler> settings and files, wherever its folder is.

The words after a PART place it, relative to its attach point (default: at it):
  pos=X,Y,Z        its world's position
  quat=W,X,Y,Z     its world's orientation, as a quaternion
  euler=A,B,C      or as Euler angles, read in BASE's <compiler> angle units
                   (degrees unless it says angle="radian") and eulerseq, as
                   mjcf_model.attach reads them
Numbers are separated by commas (or spaces, quoted); a model file whose name
starts with pos=, quat= or euler= is written ./pos=... . A placement text that
is not of this form exits 2 and writes nothing.

example:
  mjcf-model compose scene.xml table.xml arm.xml:left_ pos=-0.5,0,0 \\
      arm.xml:right_ pos=0.5,0,0 euler=0,0,180
"""


def _model(node: AnyElement) -> Mujoco:
    """``node``, which a transform of a whole model gives: a whole model."""
    assert isinstance(node, Mujoco)
    return node


def _checked(model: AnyElement) -> Mujoco:
    """``model``, once MuJoCo has compiled it (else :class:`Failed` with MuJoCo's reason)."""
    _compiled_sizes(model)
    return _model(model)


def _compiled_sizes(model: AnyElement) -> str:
    """What MuJoCo compiles ``model`` to, in words (else :class:`Failed` with its reason)."""
    try:
        compiled_model = compiled(_model(model))
    except MjcfCompileError as error:
        raise Failed(f"{error.for_command_line()}; the result is not written") from None
    counts = (
        (compiled_model.nbody - 1, "bodies"),
        (compiled_model.njnt, "joints"),
        (compiled_model.ngeom, "geoms"),
        (compiled_model.nu, "actuators"),
        (compiled_model.nkey, "keyframes"),
    )
    return ", ".join(f"{count} {what}" for count, what in counts)


def _say_written(target: str, what: str) -> None:
    """Tell the user what was written, unless the model itself went to standard output."""
    if target != STDIO:
        sys.stdout.write(f"wrote {target}: {what}\n")


def _compose(arguments: argparse.Namespace) -> int:

    if (
        arguments.export
        and Path(arguments.export).exists()
        and any(Path(arguments.export).iterdir())
    ):
        raise Failed(f"{arguments.export} exists and is not empty; nothing was written")
    parts = parts_of(arguments.parts)  # placement errors before any file is read
    path, prefix, _ = split_part(arguments.base)
    scene = read_model(path)
    if prefix:
        scene = _model(prefixed(scene, prefix))
    # Parts in a row with one attach point and one placement are attached in one pass.
    runs: list[tuple[str | None, dict[str, tuple[float, ...]], list[tuple[Mujoco, str]]]] = []
    for part in parts:
        at = part.at if part.at is not None else arguments.at
        if not runs or runs[-1][:2] != (at, part.placement()):
            runs.append((at, part.placement(), []))
        runs[-1][2].append((read_model(part.path), part.prefix))
    for at, placement, children in runs:
        pos, quat, euler = (placement.get(key) for key in ("pos", "quat", "euler"))
        scene = attach_all(
            scene,
            children,
            at=at,
            pos=pos,
            quat=quat,
            euler=euler,
            keyframes=arguments.keyframes,
        )
    if arguments.share_assets:
        scene = shared_assets(scene)
    sizes = _compiled_sizes(scene)
    write_model(scene, arguments.output)
    attached = sum(len(children) for _, _, children in runs)
    _say_written(
        arguments.output,
        f"{attached} part{'s' if attached != 1 else ''} attached to {path}; "
        f"MuJoCo compiles it: {sizes}",
    )
    if arguments.export:
        _export(scene, arguments.export)
    return 0


def _prefix(arguments: argparse.Namespace) -> int:

    model = prefixed(read_model(arguments.file), arguments.prefix)
    sizes = _compiled_sizes(model)
    write_model(_model(model), arguments.output)
    _say_written(arguments.output, f"{arguments.file} prefixed {arguments.prefix!r}: {sizes}")
    return 0


def _scale(arguments: argparse.Namespace) -> int:

    factor = arguments.factor[0] if len(arguments.factor) == 1 else arguments.factor
    model = scaled(read_model(arguments.file), factor, mass=arguments.mass)
    sizes = _compiled_sizes(model)
    write_model(_model(model), arguments.output)
    _say_written(arguments.output, f"{arguments.file} scaled by {factor}: {sizes}")
    return 0


def _export(model: Mujoco, directory: str) -> None:

    written = export(model, directory)
    sys.stderr.write(f"exported to {written}\n")


def _export_verb(arguments: argparse.Namespace) -> int:
    _export(_checked(read_model(arguments.file)), arguments.directory)
    return 0


def add_parsers(commands: Any) -> None:
    """Add ``compose``, ``prefix``, ``scale`` and ``export`` to the command line's verbs."""
    compose = commands.add_parser(
        "compose",
        help="attach models to a base model and write the scene",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description=_COMPOSE_DESCRIPTION,
    )
    compose.add_argument("output", metavar="OUT", help="where to write the scene (- for stdout)")
    compose.add_argument("base", metavar="BASE[:PREFIX]", help="the base model")
    compose.add_argument(
        "parts",
        nargs="+",
        metavar="PART[:PREFIX][@NAME]",
        help=f"a model to attach (at NAME), each followed by its placement {PLACEMENT_FORM}",
    )
    compose.add_argument(
        "--at", metavar="NAME", help="the body, frame or site to attach parts without @NAME at"
    )
    compose.add_argument(
        "--keyframes",
        choices=("separate", "merged"),
        default="separate",
        help=(
            "separate (default): each part's keys are kept under their prefixed names; "
            "merged: keys of the same name in the parts become one key that sets every "
            "part (e.g. one home for two robots)"
        ),
    )
    compose.add_argument(
        "--share-assets",
        action="store_true",
        help="keep once each mesh, texture, material, height field or skin the parts "
        "repeat (the same file and settings under another name); every use follows it",
    )
    compose.add_argument(
        "--export", metavar="DIR", help="also export the scene with all its files into DIR"
    )
    compose.set_defaults(run=guarded(_compose))

    prefix = commands.add_parser(
        "prefix",
        help="prefix every name a model declares, and every reference to it",
        description="Write FILE with PREFIX before every name it declares and every reference.",
    )
    add_model_argument(prefix)
    prefix.add_argument("prefix", metavar="PREFIX", help="the text put before each name")
    _output_option(prefix)
    prefix.set_defaults(run=guarded(_prefix))

    scale = commands.add_parser(
        "scale",
        help="scale every length of a model",
        description=(
            "Write FILE with every length multiplied by the factor (one number, or three for "
            "x, y and z); --mass keep keeps each body's mass, --mass volume scales it with "
            "the volume."
        ),
    )
    add_model_argument(scale)
    scale.add_argument(
        "--factor", type=float, nargs="+", required=True, metavar="F", help="1 or 3 factors"
    )
    scale.add_argument("--mass", choices=("keep", "volume"), default="keep", help="mass policy")
    _output_option(scale)
    scale.set_defaults(run=guarded(_scale))

    export = commands.add_parser(
        "export",
        help="write a model and every file it uses into one movable folder",
        description=(
            "Write FILE and every mesh, texture and included file it uses into DIR (which "
            "must not exist or be empty); every path in DIR is relative."
        ),
    )
    add_model_argument(export)
    export.add_argument("directory", metavar="DIR", help="the folder to create")
    export.set_defaults(run=guarded(_export_verb))


def _output_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "-o", "--output", default=STDIO, metavar="OUT", help="where to write (default: stdout)"
    )
