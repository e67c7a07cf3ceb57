"""What every verb of the command line shares: reading and writing models, errors, progress.

A file argument may be ``-``: the model is read from standard input, or written to
standard output. Files are written atomically (:func:`mjcf_model.serializers.dump`): a
failed command leaves them as they were.

>>> list(progress([1, 2], quiet=False))  # two files: no bar
[1, 2]
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import TextIO, TypeVar

from mjcf_model import serializers
from mjcf_model.errors import MjcfError
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers.dumping import relocated_for, write_atomically
from mjcf_model.values.encoding import encoded

__all__ = [
    "STDIO",
    "Failed",
    "add_model_argument",
    "guarded",
    "progress",
    "read_model",
    "read_stdin",
    "said",
    "to_stdout",
    "write_model",
    "write_text",
]

_T = TypeVar("_T")

#: The file argument that stands for standard input or output.
STDIO = "-"
#: Draw a progress bar when a verb works on at least this many files.
_PROGRESS_FROM = 5


class Failed(Exception):
    """A verb cannot go on: the message is printed and the command exits with ``status``."""

    def __init__(self, message: str, status: int = 2) -> None:
        super().__init__(message)
        #: The exit status.
        self.status = status


def add_model_argument(parser: argparse.ArgumentParser) -> None:
    """The ``FILE`` argument of a verb that reads one model (``-`` for standard input)."""
    parser.add_argument("file", metavar="FILE", help="the model (- for stdin)")


@contextmanager
def stages(
    name: str, quiet: bool, stream: TextIO | None = None
) -> Iterator[Callable[[str], object]]:
    r"""A callback that shows the step a long task on ``name`` is at, and the time it took.

    On a terminal (standard error, unless ``quiet``) each step replaces the last on one
    status line, cleared when the block ends; elsewhere nothing is written.

    Examples:
        >>> import io
        >>> class Terminal(io.StringIO):
        ...     def isatty(self): return True
        >>> terminal = Terminal()
        >>> with stages("big.xml", quiet=False, stream=terminal) as stage:
        ...     stage("compiling")
        >>> terminal.getvalue().startswith("\r\033[Kbig.xml: compiling (0 s in)")
        True

    """
    out = sys.stderr if stream is None else stream
    if quiet or not out.isatty():
        yield lambda _: None
        return
    start = time.monotonic()

    def show(step: str) -> None:
        out.write(f"\r\033[K{name}: {step} ({time.monotonic() - start:.0f} s in)")
        out.flush()

    try:
        yield show
    finally:
        out.write("\r\033[K")
        out.flush()


def progress(items: Sequence[_T], quiet: bool, stream: TextIO | None = None) -> Iterator[_T]:
    r"""Yield ``items``, with a one-line progress bar on ``stream`` (standard error).

    The bar is drawn for many items, unless ``quiet`` or ``stream`` is no terminal;
    it is cleared before each item, so what a verb prints for the item stands on a
    line of its own.

    Examples:
        >>> import io
        >>> class Terminal(io.StringIO):
        ...     def isatty(self): return True
        >>> terminal = Terminal()
        >>> list(progress(range(5), quiet=False, stream=terminal))
        [0, 1, 2, 3, 4]
        >>> terminal.getvalue().rsplit("\r", 1)[-1]
        '[##############################] 5/5\n'

    """
    out = sys.stderr if stream is None else stream
    total = len(items)
    drawn = total >= _PROGRESS_FROM and not quiet and out.isatty()
    for done, item in enumerate(items, start=1):
        if drawn and done > 1:
            out.write("\r\033[K")
        yield item
        if drawn:
            width = 30
            filled = width * done // total
            bar = "#" * filled + "-" * (width - filled)
            out.write(f"\r[{bar}] {done}/{total}")
            out.flush()
    if drawn:
        out.write("\n")


def read_model(source: str, *, inline_includes: bool = True) -> Mujoco:
    """The model in the file ``source`` (``-``: standard input, paths read from here).

    Included files are read in by default: the verbs that inspect or transform a
    model work on what MuJoCo reads.

    Raises:
        MjcfError: The file cannot be read or is not MJCF (the message names file and line).

    """
    if source == STDIO:
        return serializers.loads(read_stdin(), inline_includes=inline_includes, filename="<stdin>")
    return serializers.load(source, inline_includes=inline_includes)


def read_stdin() -> bytes:
    """Standard input as bytes: the reader decodes it as MuJoCo does (UTF-8)."""
    return sys.stdin.buffer.read()


def write_model(model: Mujoco, target: str, *, canonical: bool = False) -> None:
    """Write ``model`` to the file ``target`` atomically (``-``: standard output).

    Relative file paths are written to resolve from ``target``'s folder (from the
    working folder for standard output).
    """
    if target == STDIO:
        to_stdout(serializers.dumps(relocated_for(model, Path.cwd()), canonical=canonical))
    else:
        serializers.dump(model, target, canonical=canonical)


def write_text(text: str, target: str) -> None:
    """Write ``text`` to ``target`` atomically (``-``: standard output)."""
    if target == STDIO:
        to_stdout(text)
        return

    write_atomically(text, target)


def to_stdout(text: str) -> None:
    """Write MJCF text to standard output as a file holds it (escaped bytes as they were)."""
    sys.stdout.flush()
    sys.stdout.buffer.write(encoded(text))
    sys.stdout.buffer.flush()


def guarded(run: Callable[[argparse.Namespace], int]) -> Callable[[argparse.Namespace], int]:
    """``run``, with library errors and :class:`Failed` printed as ``mjcf-model <verb>: ...``.

    An :class:`~mjcf_model.errors.MjcfError` (its message names the file, line and
    element path) or an ``OSError`` exits with status 2.
    """

    def verb(arguments: argparse.Namespace) -> int:
        try:
            return run(arguments)
        except Failed as failure:
            return _report(arguments, str(failure), failure.status)
        except BrokenPipeError:  # the reader went away: main() ends quietly
            raise
        except (MjcfError, OSError) as error:
            return _report(arguments, said(error), 2)

    return verb


def said(error: Exception) -> str:
    """``error`` as the command line says it: advice in terms of files and options.

    Examples:
        >>> said(PermissionError(13, "Permission denied", "out/m.xml"))
        "'out/m.xml': Permission denied"

    """
    if isinstance(error, MjcfError):
        return error.for_command_line()
    if isinstance(error, OSError) and error.strerror:  # reading or writing: the system's words
        if error.filename is None:
            return error.strerror
        return f"{str(error.filename)!r}: {error.strerror}"
    return str(error)


def _report(arguments: argparse.Namespace, message: str, status: int) -> int:
    sys.stderr.write(f"mjcf-model {arguments.command}: {message}\n")
    return status
