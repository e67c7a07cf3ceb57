"""``mjcf-model diff A B``: what changed in the model, not in the text.

Exit status as ``diff``'s: 0 when the models are the same, 1 when they differ, 2
when a file cannot be read (or, with ``--compiled``, compiled).

Example:
    >>> import pathlib, tempfile
    >>> from mjcf_model.tools.cli import main
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> a, b = folder / "a.xml", folder / "b.xml"
    >>> _ = a.write_text('<mujoco><worldbody><geom size="0.10"/></worldbody></mujoco>')
    >>> _ = b.write_text("<mujoco> <worldbody><geom size='.1'/></worldbody> </mujoco>")
    >>> main(["diff", str(a), str(b)])
    0

"""

from __future__ import annotations

import argparse
import json
import sys
from typing import Any

from mjcf_model.bridge.compare import model_differences, path_fields
from mjcf_model.bridge.compiling import compiled
from mjcf_model.tools.cli.common import Failed, guarded, read_model
from mjcf_model.tools.diff import changes_between

__all__ = ["add_parsers"]


def _diff(arguments: argparse.Namespace) -> int:
    if arguments.first == "-" and arguments.second == "-":
        raise Failed("only one of the two models can come from standard input")
    first, second = read_model(arguments.first), read_model(arguments.second)
    changes = changes_between(first, second)
    fields: list[str] = []
    if arguments.compiled:
        fields = model_differences(compiled(first), compiled(second), ignore=path_fields())
    equal = not changes and not fields
    if arguments.json:
        report: dict[str, Any] = {
            "equal": equal,
            "changes": [change.to_dict() for change in changes],
        }
        if arguments.compiled:
            report["compiled"] = fields
        sys.stdout.write(json.dumps(report, indent=2) + "\n")
    else:
        for change in changes:
            sys.stdout.write(f"{change}\n")
        if fields:
            sys.stdout.write("compiled models differ in: " + ", ".join(fields) + "\n")
    return 0 if equal else 1


def add_parsers(commands: Any) -> None:
    """Add ``diff`` to the command line's verbs."""
    diff = commands.add_parser(
        "diff",
        help="semantic diff of two models (added, removed, moved, changed elements)",
        description=(
            "Compare two MJCF models element by element: elements are matched by namespace "
            "and name (unnamed ones by position under their parent); formatting, comments, "
            "attribute order and number spelling are ignored. Lines start with + (added), "
            "- (removed), > (moved) or ~ (attribute changed). Exit status 0 when equal, "
            "1 when different, 2 on trouble."
        ),
    )
    diff.add_argument("first", metavar="A", help="the first model (or - for stdin)")
    diff.add_argument("second", metavar="B", help="the second model (or - for stdin)")
    diff.add_argument(
        "--compiled",
        action="store_true",
        help="also compile both with MuJoCo and list the MjModel fields that differ",
    )
    diff.add_argument("--json", action="store_true", help="print the changes as JSON")
    diff.set_defaults(run=guarded(_diff))
