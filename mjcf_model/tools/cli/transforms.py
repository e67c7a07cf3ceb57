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
    >>> main(["compose", scene, str(folder / "cup.xml"), f"{folder / 'cup.xml'}:b_"])
    0
    >>> from serializers import load
    >>> [body.name for body in load(scene).worldbody.bodies]
    ['cup', 'b_cup']

"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path
from typing import Any

from mjcf_model.nodes.base import AnyElement
from mjcf_model.nodes.root import Mujoco
from mjcf_model.tools.cli.common import (
    STDIO,
    Failed,
    add_model_argument,
    guarded,
    read_model,
    write_model,
)

__all__ = ["add_parsers", "split_part"]


def split_part(argument: str) -> tuple[str, str, str | None]:
    """``FILE[:PREFIX][@NAME]`` as ``(file, prefix, name)``.

    The file is the longest start of ``argument`` that names an existing file (so
    prefixes and names may hold ``/`` and file names ``:`` or ``@``); when none
    does, the first mark after the file name's ``.xml`` ends it.

    Example:
        >>> split_part("robots/arm.xml:left/@left_mount"), split_part("arm.xml")
        (('robots/arm.xml', 'left/', 'left_mount'), ('arm.xml', '', None))

    """
    if argument == STDIO or os.path.exists(argument):
        return argument, "", None
    cuts = [i for i, char in enumerate(argument) if char in ":@"]
    found = [i for i in cuts if os.path.isfile(argument[:i])]
    if not found:  # no such file: cut after the file name's ".xml", else at the first mark
        after = argument.rfind(".xml") + 4 if ".xml" in argument else 0
        found = [min((i for i in cuts if i >= after), default=len(argument))]
    path, rest = argument[: found[-1]], argument[found[-1] :]
    if rest.startswith(":"):
        prefix, _, name = rest[1:].partition("@")
    else:
        prefix, name = "", rest[1:]
    return path, prefix, name or None


def _model(node: AnyElement) -> Mujoco:
    """``node``, which a transform of a whole model gives: a whole model."""
    assert isinstance(node, Mujoco)
    return node


def _checked(model: AnyElement) -> Mujoco:
    """``model``, once MuJoCo has compiled it (else :class:`Failed` with MuJoCo's reason)."""
    from mjcf_model.errors import MjcfCompileError
    from mjcf_model.files.compiling import compiled

    try:
        compiled(_model(model))
    except MjcfCompileError as error:
        raise Failed(f"{error}; the result is not written") from None
    return _model(model)


def _compose(arguments: argparse.Namespace) -> int:
    from mjcf_model.transforms.composition.attach import attach_all
    from mjcf_model.transforms.naming.renaming import prefixed

    if (
        arguments.export
        and Path(arguments.export).exists()
        and any(Path(arguments.export).iterdir())
    ):
        raise Failed(f"{arguments.export} exists and is not empty; nothing was written")
    path, prefix, _ = split_part(arguments.base)
    scene = read_model(path)
    if prefix:
        scene = _model(prefixed(scene, prefix))
    runs: list[tuple[str | None, list[tuple[Mujoco, str]]]] = []  # parts in a row, one place
    for argument in arguments.parts:
        path, prefix, at = split_part(argument)
        at = at if at is not None else arguments.at
        if not runs or runs[-1][0] != at:
            runs.append((at, []))
        runs[-1][1].append((read_model(path), prefix))
    for at, children in runs:
        scene = attach_all(scene, children, at=at)
    write_model(_checked(scene), arguments.output)
    if arguments.export:
        _export(scene, arguments.export)
    return 0


def _prefix(arguments: argparse.Namespace) -> int:
    from mjcf_model.transforms.naming.renaming import prefixed

    write_model(_checked(prefixed(read_model(arguments.file), arguments.prefix)), arguments.output)
    return 0


def _scale(arguments: argparse.Namespace) -> int:
    from mjcf_model.transforms.scaling.scaled import scaled

    factor = arguments.factor[0] if len(arguments.factor) == 1 else arguments.factor
    model = scaled(read_model(arguments.file), factor, mass=arguments.mass)
    write_model(_checked(model), arguments.output)
    return 0


def _export(model: Mujoco, directory: str) -> None:
    from serializers import export

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
        description=(
            "Read BASE, attach each PART to it (at the world, or at the body, frame or site "
            "its @NAME or --at names), each with its names prefixed by PREFIX, check that "
            "MuJoCo compiles the scene, and write it to OUT (- for stdout). Each model keeps "
            "its own <compiler> settings and files, wherever its folder is."
        ),
    )
    compose.add_argument("output", metavar="OUT", help="where to write the scene (- for stdout)")
    compose.add_argument("base", metavar="BASE[:PREFIX]", help="the base model")
    compose.add_argument(
        "parts", nargs="+", metavar="PART[:PREFIX][@NAME]", help="models to attach (at NAME)"
    )
    compose.add_argument(
        "--at", metavar="NAME", help="the body, frame or site to attach parts without @NAME at"
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
