"""``mjcf-model lint FILE...``: the mistakes MuJoCo compiles without a word.

Each finding is printed as ``file:line: element path: CODE message``; ``--format json``
prints one list of objects (``file``, ``line``, ``path``, ``rule``, ``severity``,
``message``). The exit status is 1 when anything is found, 2 when a file cannot be
read or MuJoCo rejects it, else 0. ``--select`` and ``--ignore`` take rule codes or
their prefixes (``K``, ``K104``), as ruff's do; ``[tool.mjcf-model.lint]`` in the
nearest ``pyproject.toml`` sets ``select`` and ``ignore`` for the files below it
(``--select`` replaces the file's, ``--ignore`` adds to it).

Example:
    >>> import pathlib, tempfile
    >>> from mjcf_model.tools.cli import main
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "arm.xml"
    >>> _ = path.write_text(
    ...     '<mujoco><worldbody><body><joint name="j" range="1 -1"/><geom size="1"/>'
    ...     '</body></worldbody></mujoco>')
    >>> main(["lint", str(path)])  # doctest: +ELLIPSIS
    /.../arm.xml:1: /mujoco/worldbody/body/joint[@name='j']: R201 joint 'j' has range ...
    1 finding (1 error) in 1 file
    1
    >>> main(["lint", str(path), "--ignore", "R"])
    no findings in 1 file
    0

"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from pathlib import Path
from typing import Any

from mjcf_model.errors import MjcfError, MjcfValueError
from mjcf_model.tools.cli.common import STDIO, guarded, progress, read_model, said
from mjcf_model.tools.lint import RULES, Finding, lint
from mjcf_model.tools.settings import project_settings

__all__ = ["add_parsers", "lint_settings"]

#: The keys ``[tool.mjcf-model.lint]`` may set.
_KEYS = ("select", "ignore")


def lint_settings(start: str | Path) -> dict[str, list[str]]:
    r"""``select`` and ``ignore`` of ``[tool.mjcf-model.lint]`` nearest ``start`` (empty: none).

    Raises:
        MjcfValueError: The table sets another key, or not a list of strings (the
            message names the file).

    Examples:
        >>> import pathlib, tempfile
        >>> folder = pathlib.Path(tempfile.mkdtemp())
        >>> _ = (folder / "pyproject.toml").write_text(
        ...     '[tool.mjcf-model.lint]\nignore = ["A4"]\n')
        >>> lint_settings(folder)
        {'ignore': ['A4']}

    """
    table, path = project_settings(start)
    settings = table.get("lint", {})
    checked: dict[str, list[str]] = {}
    for key, value in settings.items():
        if key not in _KEYS or not (
            isinstance(value, list) and all(isinstance(entry, str) for entry in value)
        ):
            raise MjcfValueError(
                f"[tool.mjcf-model.lint] {key} = {value!r}: the settings are select and "
                "ignore, each a list of rule codes or prefixes",
                file=str(path),
            )
        checked[key] = value
    return checked


def _codes(text: str | None) -> list[str] | None:
    if text is None:
        return None
    return [part.strip() for part in text.split(",") if part.strip()]


def _lint_file(path: str, arguments: argparse.Namespace) -> list[Finding]:
    start = Path.cwd() if path == STDIO else Path(path).parent
    settings = lint_settings(start)
    select = _codes(arguments.select)
    ignore = [*settings.get("ignore", []), *(_codes(arguments.ignore) or [])]
    return lint(
        read_model(path),
        select=select if select is not None else settings.get("select", []),
        ignore=ignore,
    )


def _summary(findings: list[Finding], files: int) -> str:
    plural = "s" if files != 1 else ""
    if not findings:
        return f"no findings in {files} file{plural}"
    severities = Counter(finding.severity for finding in findings)
    parts = ", ".join(
        f"{count} {severity}{'s' if count != 1 else ''}"
        for severity, count in sorted(severities.items())
    )
    noun = "finding" if len(findings) == 1 else "findings"
    return f"{len(findings)} {noun} ({parts}) in {files} file{plural}"


def _rules_text() -> str:
    return "".join(
        f"{rule.code}  {rule.name:<28} {rule.severity:<8} {rule.summary}\n"
        for _, rule in sorted(RULES.items())
    )


def _lint(arguments: argparse.Namespace) -> int:
    if arguments.rules:
        sys.stdout.write(_rules_text())
        return 0
    if not arguments.files:
        sys.stderr.write("mjcf-model lint: no files given\n")
        return 2
    findings: list[Finding] = []
    failed = False
    as_json = arguments.format == "json"
    for path in progress(arguments.files, quiet=as_json):
        try:
            found = _lint_file(path, arguments)
        except (MjcfError, OSError) as error:  # this file: the others are still linted
            failed = True
            sys.stderr.write(f"mjcf-model lint: {said(error)}\n")
            continue
        findings += found
        if not as_json:
            sys.stdout.write("".join(f"{finding}\n" for finding in found))
    if as_json:
        payload: list[dict[str, Any]] = [finding.to_dict() for finding in findings]
        sys.stdout.write(json.dumps(payload, indent=2) + "\n")
    else:
        sys.stdout.write(_summary(findings, len(arguments.files)) + "\n")
    if failed:
        return 2
    return 1 if findings else 0


def add_parsers(commands: Any) -> None:
    """Add ``lint`` to the command line's verbs."""
    verb = commands.add_parser(
        "lint",
        help="find the mistakes MuJoCo compiles without a word",
        description=(
            "Check models for mistakes MuJoCo accepts: keys outside ranges or out of step "
            "with their servos, reversed ranges, geoms that start inside each other, "
            "assets and classes nothing uses. Each finding names the file, line and "
            "element path, a rule code and what to do. Exit status 1 when anything is "
            "found, 2 when a file cannot be read or MuJoCo rejects it."
        ),
    )
    verb.add_argument("files", nargs="*", help="MJCF files (- for stdin)")
    verb.add_argument(
        "--select", metavar="CODES", help="only these rules (codes or prefixes, comma-separated)"
    )
    verb.add_argument(
        "--ignore", metavar="CODES", help="not these rules (codes or prefixes, comma-separated)"
    )
    verb.add_argument("--format", choices=("text", "json"), default="text", help="output format")
    verb.add_argument("--rules", action="store_true", help="list the rules and exit")
    verb.set_defaults(run=guarded(_lint))
