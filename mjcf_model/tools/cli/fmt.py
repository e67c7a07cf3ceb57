"""``mjcf-model fmt``: lay MJCF files out tidily, as ``ruff format`` does for code.

Indentation, one element a line and long start tags wrapped; comments, blank lines
between elements and the spelling of numbers kept (:mod:`mjcf_model.serializers.tidy`). The
width and indentation come from ``[tool.mjcf-model]`` in the nearest
``pyproject.toml`` (``width``, ``indent``, ``normalize-numbers``), or the options.
A file is rewritten only with proof that MuJoCo compiles the rewrite to the same
model (:mod:`mjcf_model.tools.formatting`); otherwise it is left alone and the
command fails. ``--check`` and ``--diff`` write nothing.

Exit status: 0 when all is well, 1 when ``--check`` or ``--diff`` finds a file to
reformat, 2 when a file cannot be read or could not be rewritten safely.

Example:
    >>> import pathlib, tempfile
    >>> from mjcf_model.tools.cli import main
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "m.xml"
    >>> _ = path.write_text("<mujoco><worldbody><geom size='.1'/></worldbody></mujoco>")
    >>> main(["fmt", "--check", "--quiet", str(path)]), main(["fmt", "--quiet", str(path)])
    (1, 0)
    >>> main(["fmt", "--check", "--quiet", str(path)])
    0

"""

from __future__ import annotations

import argparse
import difflib
import os
import sys
from pathlib import Path
from typing import Any

import attrs

from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.tools.cli.common import STDIO, progress, read_stdin, said, write_text
from mjcf_model.tools.formatting import (
    FormatOptions,
    Formatted,
    format_file,
    format_text,
    options_from_pyproject,
)

__all__ = ["add_parsers"]


def _formatted(path: str, options: FormatOptions) -> Formatted:
    if path == STDIO:
        return format_text(read_stdin(), filename="<stdin>", options=options)
    return format_file(path, options=options)


def _options(arguments: argparse.Namespace) -> FormatOptions:
    """The settings of the nearest ``pyproject.toml``, with the command line's over them."""
    files = [Path(f).resolve().parent for f in arguments.files if f != STDIO]
    start = Path(os.path.commonpath(files)) if files else Path.cwd()
    options, _ = options_from_pyproject(start)
    given = {
        "width": arguments.width,
        "indent": arguments.indent,
        "normalize_numbers": arguments.normalize_numbers or None,
    }
    try:
        return attrs.evolve(options, **{k: v for k, v in given.items() if v is not None})
    except ValueError as error:
        raise MjcfValueError(f"--width or --indent: {error}") from None


def _unified(result: Formatted) -> str:
    return "".join(
        difflib.unified_diff(
            result.original.splitlines(keepends=True),
            result.text.splitlines(keepends=True),
            fromfile=result.path,
            tofile=result.path,
        )
    )


def _fmt(arguments: argparse.Namespace) -> int:
    files: list[str] = arguments.files
    writing = not (arguments.check or arguments.diff)
    counts = {"reformatted": 0, "unchanged": 0, "failed": 0}
    try:
        options = _options(arguments)
    except MjcfError as error:
        _say(arguments, f"error: {said(error)}")
        return 2
    for path in progress(files, arguments.quiet):
        try:
            result = _formatted(path, options)
        except MjcfError as error:
            _say(arguments, f"error: {said(error)}")
            counts["failed"] += 1
            continue
        if not result.safe:
            why = "; ".join(result.differences[:5])
            _say(arguments, f"error: {path}: not rewritten, it changes the model: {why}")
            counts["failed"] += 1
            continue
        if path == STDIO and writing:
            write_text(result.text, STDIO)
        if not result.changed:
            counts["unchanged"] += 1
            continue
        if arguments.diff:
            sys.stdout.write(_unified(result))
        elif arguments.check:
            _say(arguments, f"would reformat {path}")
        elif path != STDIO:
            try:
                write_text(result.text, path)
            except OSError as error:
                _say(arguments, f"error: {path}: cannot write: {error.strerror or error}")
                counts["failed"] += 1
                continue
        counts["reformatted"] += 1
    if not arguments.quiet:
        done = "would be reformatted" if not writing else "reformatted"
        summary = f"{_files(counts['reformatted'])} {done}, {_files(counts['unchanged'])} unchanged"
        failed = f", {_files(counts['failed'])} failed" if counts["failed"] else ""
        sys.stderr.write(summary + failed + "\n")
    if counts["failed"]:
        return 2
    return 1 if counts["reformatted"] and not writing else 0


def _files(count: int) -> str:
    return f"{count} file" + ("" if count == 1 else "s")


def _say(arguments: argparse.Namespace, line: str) -> None:
    if not arguments.quiet or line.startswith("error"):
        sys.stderr.write(line + "\n")


def add_parsers(commands: Any) -> None:
    """Add ``fmt`` to the command line's verbs."""
    fmt = commands.add_parser(
        "fmt",
        help="lay MJCF files out tidily (the compiled model unchanged)",
        description=(
            "Lay each file out tidily: one element a line, indented by depth, a start tag "
            "longer than the width wrapped one attribute a line; comments, attribute order, "
            "one blank line where the file had blank lines, and every number's spelling "
            "kept (--normalize-numbers: the shortest form). Settings come from "
            "[tool.mjcf-model] in the nearest pyproject.toml (width, indent, "
            "normalize-numbers), then these options. A file is rewritten only when "
            "MuJoCo compiles the rewrite to the identical model (for a file MuJoCo rejects "
            "on its own, when the elements read back the same). '-' reads standard input "
            "and writes standard output. Exit status 1 when --check or --diff finds a file "
            "to reformat, 2 when a file fails."
        ),
    )
    fmt.add_argument("files", nargs="+", metavar="FILE", help="MJCF files, or - for stdin")
    fmt.add_argument(
        "--check", action="store_true", help="write nothing; exit 1 if a file would change"
    )
    fmt.add_argument(
        "--diff", action="store_true", help="write nothing; print a unified diff of the changes"
    )
    fmt.add_argument(
        "--width", type=int, metavar="N", help="wrap start tags longer than N (default 100)"
    )
    fmt.add_argument("--indent", type=int, metavar="N", help="spaces per level (default 2)")
    fmt.add_argument(
        "--normalize-numbers",
        action="store_true",
        help="write every number in its shortest form instead of as written",
    )
    fmt.add_argument("-q", "--quiet", action="store_true", help="print errors only")
    fmt.set_defaults(run=_fmt)
