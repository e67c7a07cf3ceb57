"""Import time: each library imported by a fresh interpreter, as a script starts."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

from benchmarks.harness import OURS, Case, Contender

__all__ = ["import_cases"]

#: The note of every import row: what the time includes.
_NOTE = "a fresh `python -c 'import ...'`; start-up included, not subtracted (own row: -c pass)"


def _source_root() -> Path:
    """The folder holding the ``mjcf_model`` this process runs (its children import the same)."""
    import mjcf_model

    return Path(mjcf_model.__file__).resolve().parent.parent


def _fresh_process(statement: str) -> Callable[[], object]:
    """Run ``statement`` in a new interpreter of this environment (raising if it fails).

    Example:
        >>> _fresh_process("pass")().returncode
        0

    """
    path = os.pathsep.join(filter(None, [str(_source_root()), os.environ.get("PYTHONPATH")]))
    environment = {**os.environ, "PYTHONPATH": path}

    def run() -> subprocess.CompletedProcess[bytes]:
        return subprocess.run(
            [sys.executable, "-c", statement], env=environment, capture_output=True, check=True
        )

    return run


def _installed(module: str) -> bool:
    return importlib.util.find_spec(module.split(".")[0]) is not None


def import_cases() -> list[Case]:
    """One case: the import of mjcf-model beside robosuite's, dm_control's and the floor."""
    contenders = [Contender(OURS, _fresh_process("import mjcf_model"), note=_NOTE)]
    for name, module in (
        ("robosuite", "robosuite.utils.mjcf_utils"),
        ("dm_control", "dm_control.mjcf"),
    ):
        contenders.append(
            Contender(
                f"{name} (import {module})",
                _fresh_process(f"import {module}") if _installed(module) else None,
                f"{name} is not installed",
                note=_NOTE,
            )
        )
    contenders += [
        Contender(
            "xml.etree.ElementTree (floor)",
            _fresh_process("import xml.etree.ElementTree"),
            note=_NOTE,
        ),
        Contender("python -c pass (interpreter start-up)", _fresh_process("pass"), note=_NOTE),
    ]
    return [Case("import time", contenders, "a fresh interpreter")]
