"""The ``mjcf-model`` command line: one module per verb, each adding its own parser.

Every verb reads files or ``-`` (standard input), writes files atomically or ``-``
(standard output), and exits non-zero with the library's error message (file, line
and element path) when it fails. ``mjcf-model VERB --help`` describes each.

Example:
    >>> main(["check", "--example", "--quiet"])
    0

"""

from __future__ import annotations

import argparse
import io
import os
import sys
from collections.abc import Sequence
from importlib.metadata import PackageNotFoundError, version

from mjcf_model.tools.cli import check as check
from mjcf_model.tools.cli import diff as diff
from mjcf_model.tools.cli import examples as examples
from mjcf_model.tools.cli import fmt as fmt
from mjcf_model.tools.cli import info as info
from mjcf_model.tools.cli import lint as lint
from mjcf_model.tools.cli import render as render
from mjcf_model.tools.cli import transform_verbs as transform_verbs
from mjcf_model.tools.cli.examples import example_path

__all__ = ["example_path", "main"]

#: The verbs, in the order ``--help`` lists them.
_VERBS = (check, fmt, lint, diff, transform_verbs, info, render, examples)


def parser() -> argparse.ArgumentParser:
    """The parser of the whole command line."""
    top = argparse.ArgumentParser(
        prog="mjcf-model",
        description="MuJoCo MJCF files: check, format, lint, diff, compose, inspect and render.",
    )
    top.add_argument("--version", action="version", version=version_line())
    commands = top.add_subparsers(dest="command", required=True, metavar="VERB")
    for verb in _VERBS:
        verb.add_parsers(commands)
    return top


def version_line() -> str:
    """The version of mjcf-model and of the MuJoCo it runs with (MuJoCo is not imported).

    Examples:
        >>> version_line().startswith("mjcf-model ")
        True

    """

    def installed(name: str) -> str:
        try:
            return version(name)
        except PackageNotFoundError:
            return "not installed"

    return f"mjcf-model {installed('mjcf-model')} (MuJoCo {installed('mujoco')})"


def _bytes_as_read() -> None:
    """Print the bytes of a name or comment that are not UTF-8 as the file holds them.

    The reader escapes them (:mod:`mjcf_model.values.encoding`); a strict stream
    would refuse them.
    """
    for stream in (sys.stdout, sys.stderr):
        if isinstance(stream, io.TextIOWrapper):
            stream.reconfigure(errors="surrogateescape")


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit status.

    Examples:
        >>> main(["check", "--example", "--quiet"])
        0

    """
    arguments = parser().parse_args(argv)
    _bytes_as_read()
    try:
        status: int = arguments.run(arguments)
        sys.stdout.flush()
    except BrokenPipeError:
        return _reader_gone()
    return status


#: The exit status of a command whose reader went away, as a shell reports a
#: program ended by SIGPIPE (``git log | head`` ends so).
BROKEN_PIPE_STATUS = 128 + 13


def _reader_gone() -> int:
    """End quietly when standard output's reader has gone (``mjcf-model diff a b | head``).

    What is still buffered for it goes nowhere, so that Python's own flush at exit
    does not report the broken pipe again.
    """
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())
    os.close(devnull)
    return BROKEN_PIPE_STATUS
