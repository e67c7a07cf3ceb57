"""``mjcf-model info FILE``: what a model holds, and one element's attributes after defaults.

The summary ends with whether MuJoCo compiles the model, and if not, the file,
line and element path of what it rejects, and MuJoCo's reason.

Example:
    >>> import pathlib, tempfile
    >>> from mjcf_model.tools.cli import main
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "m.xml"
    >>> _ = path.write_text('<mujoco model="m"><default><geom rgba="1 0 0 1"/></default>'
    ...                     '<worldbody><geom name="g" size="1"/></worldbody></mujoco>')
    >>> main(["info", str(path), "--element", "geom:g"])
    name = g (written)
    size = 1 (written)
    rgba = 1 0 0 1 (class main)
    0

"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Mapping
from typing import Any

from mjcf_model.bridge.compiling import compiled
from mjcf_model.errors import MjcfAssetError, MjcfCompileError
from mjcf_model.nodes.root import Mujoco
from mjcf_model.tools.cli.common import Failed, add_model_argument, guarded, read_model
from mjcf_model.tools.info import ModelSummary, effective_attributes, model_summary

__all__ = ["add_parsers"]

#: How many names of one namespace are printed before ``...``.
_NAMES_SHOWN = 8


def _info(arguments: argparse.Namespace) -> int:
    model = read_model(arguments.file)
    if arguments.element:
        kind, colon, name = arguments.element.partition(":")
        if not colon or not kind or not name:
            raise Failed(f"--element takes KIND:NAME (geom:finger), not {arguments.element!r}")
        for attribute in effective_attributes(model, kind, name):
            sys.stdout.write(f"{attribute}\n")
        return 0
    summary = model_summary(model)
    sys.stdout.write(_summary_text(summary, arguments.defaults))
    sys.stdout.write(f"compiles: {_compiles(model)}\n")
    return 0


def _compiles(model: Mujoco) -> str:
    """``yes``, or ``no:`` and where and why MuJoCo rejects ``model``."""
    try:
        compiled(model)
    except (MjcfCompileError, MjcfAssetError) as error:
        return f"no: {error.for_command_line()}"
    return "yes"


def _summary_text(summary: ModelSummary, defaults: bool) -> str:
    lines = [f"model: {summary.name or '(no name)'}"]
    counts = sorted(summary.counts.items(), key=lambda item: (-item[1], item[0]))
    lines.append("elements: " + ", ".join(f"{tag} {count}" for tag, count in counts))
    lines.append("names:")
    for namespace, names in summary.names.items():
        shown = ", ".join(names[:_NAMES_SHOWN]) + (", ..." if len(names) > _NAMES_SHOWN else "")
        lines.append(f"  {namespace} ({len(names)}): {shown}")
    settings = " ".join(f"{key}={value}" for key, value in summary.compiler.items())
    lines.append(f"compiler: {settings}")
    lines.append(f"default classes: {len(summary.classes)}")
    if defaults:
        lines.extend(_class_tree(summary.classes, summary.class_settings))
    return "\n".join(lines) + "\n"


def _class_tree(
    parents: Mapping[str, str | None], settings: Mapping[str, tuple[str, ...]]
) -> list[str]:
    """The classes indented under their parents, each with the tags it sets."""
    children: dict[str | None, list[str]] = {}
    for name, parent in parents.items():
        children.setdefault(parent, []).append(name)
    lines: list[str] = []
    stack = [(name, 1) for name in reversed(children.get(None, []))]
    while stack:
        name, depth = stack.pop()
        tags = ", ".join(settings.get(name, ())) or "nothing"
        lines.append(f"{'  ' * depth}{name}: sets {tags}")
        stack.extend((child, depth + 1) for child in reversed(children.get(name, [])))
    return lines


def add_parsers(commands: Any) -> None:
    """Add ``info`` to the command line's verbs."""
    info = commands.add_parser(
        "info",
        help="summarise a model, or show one element's attributes after default classes",
        description=(
            "Print the element counts per tag, the names declared per namespace, the "
            "<compiler> settings and the number of default classes (--defaults: their tree "
            "and what each sets). With --element KIND:NAME (geom:finger, actuator:elbow), "
            "print that element's attributes as MuJoCo reads them after default classes and "
            "childclass, each with the class that supplied it."
        ),
    )
    add_model_argument(info)
    info.add_argument("--defaults", action="store_true", help="show the default-class tree")
    info.add_argument("--element", metavar="KIND:NAME", help="one element's effective attributes")
    info.set_defaults(run=guarded(_info))
