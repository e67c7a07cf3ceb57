"""``mjcf-model check``: whether each file survives a round trip, as MuJoCo compiles it.

``mjcf-model check FILE...`` loads each file, writes it back, compiles the
original and the written model with MuJoCo and reports whether the two are
identical field by field. It exits with status 1 when any file differs, fails
or is rejected by MuJoCo, 0 otherwise; a part for ``<include>`` is checked as
such (see :func:`mjcf_model.tools.check.check_file`). ``mjcf-model check
--example`` runs it on the example model that ships with the package.

Example:
    >>> from mjcf_model.tools.cli import main
    >>> main(["check", "--example", "--quiet"])
    0

"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterable
from typing import Any, TextIO

from mjcf_model.tools.check import CheckResult, check_file, check_text
from mjcf_model.tools.cli.common import STDIO, progress, read_stdin, stages
from mjcf_model.tools.cli.examples import example_path

__all__ = ["add_parsers"]


def _check_stdin() -> CheckResult:
    # bytes that are not UTF-8 are escaped, and written back as they were
    return check_text(read_stdin().decode("utf-8", "surrogateescape"))


def _report(result: CheckResult, out: TextIO, verbose: bool) -> None:
    _report_status(result, out, verbose)
    for warning in result.warnings:
        out.write(f"              warning: {warning}\n")


def _report_status(result: CheckResult, out: TextIO, verbose: bool) -> None:
    if result.status == "identical":
        if verbose:
            out.write(f"identical     {result.path}\n")
    elif result.status == "different":
        fields = ", ".join(result.differences)
        out.write(f"DIFFERENT     {result.path}\n              fields: {fields}\n")
    elif result.status == "part":
        if verbose:
            out.write(f"part          {result.path}\n              {result.message}\n")
    elif result.status == "not-compiled":
        out.write(f"not compiled  {result.path}\n              {result.message}\n")
    else:
        out.write(f"ERROR         {result.path}\n              {result.message}\n")


def _summary(results: Iterable[CheckResult]) -> dict[str, int]:
    counts = {"identical": 0, "part": 0, "different": 0, "not-compiled": 0, "error": 0}
    for result in results:
        counts[result.status] += 1
    return counts


def _check(arguments: argparse.Namespace) -> int:
    files: list[str] = list(arguments.files)
    if arguments.example:
        files.append(example_path())
    if not files:
        sys.stderr.write("mjcf-model check: no files given (try --example)\n")
        return 2
    results = []
    for path in progress(files, arguments.quiet):
        if path == STDIO:
            result = _check_stdin()
        else:
            with stages(path, arguments.quiet) as stage:
                result = check_file(
                    path,
                    inline_includes=arguments.inline_includes,
                    part=arguments.part,
                    stage=stage,
                )
        results.append(result)
        if not arguments.quiet:
            _report(result, sys.stdout, verbose=True)
    counts = _summary(results)
    if not arguments.quiet:
        parts = ", ".join(f"{n} {status}" for status, n in counts.items() if n)
        noun = "file" if len(results) == 1 else "files"
        sys.stdout.write(f"{len(results)} {noun}: {parts}\n")
    failed = counts["different"] + counts["error"] + counts["not-compiled"]
    return 1 if failed else 0


def add_parsers(commands: Any) -> None:
    """Add ``check`` to the command line's verbs."""
    check = commands.add_parser(
        "check",
        help="round-trip MJCF files and compare the compiled models",
        description=(
            "Load each file, write it back, compile the original and the written "
            "model with MuJoCo and compare every field. A file MuJoCo rejects that "
            "another file in its folder (or up to two above) includes is checked as a "
            "part: it must read back the same, and the files including it must compile. "
            "Exit status 1 if any file differs, fails or is rejected by MuJoCo (the "
            "message names the file, line and element)."
        ),
    )
    check.add_argument("files", nargs="*", help="MJCF files to check (- for stdin)")
    check.add_argument("--example", action="store_true", help="also check the bundled example")
    check.add_argument(
        "--inline-includes", action="store_true", help="inline <include> files before writing"
    )
    check.add_argument(
        "--part",
        action="store_true",
        help="the files are parts for <include>: check that they read back the same, "
        "and that the files found including them compile",
    )
    # Rejected files fail by default now; --strict stays accepted for old CI jobs.
    check.add_argument("--strict", action="store_true", help=argparse.SUPPRESS)
    check.add_argument("-q", "--quiet", action="store_true", help="print nothing; exit status only")
    check.set_defaults(run=_check)
