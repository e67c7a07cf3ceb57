"""``mjcf-model examples DIR``: copy the bundled example models somewhere to try the verbs on.

The examples are ``arm.xml`` (a two-link arm, angles in radians) and
``workcell/workcell.xml`` (a table with a mesh, two mount sites, angles in degrees,
its meshes in its own folder): two models from different folders with their own
``<compiler>``, ready to compose.

Example:
    >>> import pathlib, tempfile
    >>> from mjcf_model.tools.cli import main
    >>> folder = pathlib.Path(tempfile.mkdtemp()) / "demo"
    >>> main(["examples", str(folder)])
    0
    >>> sorted(str(p.relative_to(folder)) for p in folder.rglob("*.*"))
    ['arm.xml', 'workcell/meshes/wedge.obj', 'workcell/workcell.xml']

"""

from __future__ import annotations

import argparse
import shutil
import sys
from importlib import resources
from pathlib import Path
from typing import Any

from mjcf_model.tools.cli.common import Failed, guarded

__all__ = ["add_parsers", "example_path", "examples_folder"]


def examples_folder() -> Path:
    """The folder of the example models shipped with the package."""
    return Path(str(resources.files("mjcf_model") / "examples"))


def example_path() -> str:
    """The path of the example arm shipped with the package (what ``check --example`` checks).

    Examples:
        >>> example_path().endswith("arm.xml")
        True

    """
    return str(examples_folder() / "arm.xml")


def _examples(arguments: argparse.Namespace) -> int:
    target = Path(arguments.directory).resolve()
    if target.exists() and any(target.iterdir()):
        raise Failed(f"{target} exists and is not empty; name a new folder")
    staging = target.with_name(f".{target.name}.tmp")
    shutil.rmtree(staging, ignore_errors=True)
    shutil.copytree(examples_folder(), staging, ignore=shutil.ignore_patterns("__pycache__"))
    if target.exists():
        target.rmdir()
    staging.replace(target)
    sys.stderr.write(f"examples copied to {target}\n")
    return 0


def add_parsers(commands: Any) -> None:
    """Add ``examples`` to the command line's verbs."""
    examples = commands.add_parser(
        "examples",
        help="copy the bundled example models into a new folder",
        description=(
            "Copy the bundled examples into DIR (new or empty): arm.xml, a two-link arm, and "
            "workcell/workcell.xml, a table with a mesh and two mount sites, each with its "
            "own <compiler>. Try: mjcf-model compose DIR/scene.xml DIR/workcell/workcell.xml "
            "DIR/arm.xml:left_@left_mount DIR/arm.xml:right_@right_mount"
        ),
    )
    examples.add_argument("directory", metavar="DIR", help="the folder to create")
    examples.set_defaults(run=guarded(_examples))
