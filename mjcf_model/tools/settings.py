r"""The ``[tool.mjcf-model]`` table of the ``pyproject.toml`` nearest a file.

Looked for in the file's folder and each folder above it, as ruff and black look. The
formatter reads the table's own keys (``width``...), the linter its ``lint`` table
(``select``, ``ignore``).

Examples:
    >>> import pathlib, tempfile
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> text = '[tool.mjcf-model]\nwidth = 120\n[tool.mjcf-model.lint]\nignore = ["A401"]\n'
    >>> _ = (folder / "pyproject.toml").write_text(text)
    >>> table, path = project_settings(folder)
    >>> table, path.name
    ({'width': 120, 'lint': {'ignore': ['A401']}}, 'pyproject.toml')

"""

from __future__ import annotations

import os
import tomllib
from pathlib import Path
from typing import Any

from mjcf_model.errors import MjcfValueError

__all__ = ["project_settings"]


def project_settings(start: str | os.PathLike[str]) -> tuple[dict[str, Any], Path | None]:
    """``[tool.mjcf-model]`` of the ``pyproject.toml`` nearest ``start``, and that file.

    An empty table and ``None`` when no ``pyproject.toml`` up the folders has one.

    Raises:
        MjcfValueError: The nearest file with the table cannot be read (the message
            names it).

    """
    here = Path(start).resolve()
    for folder in [here, *here.parents]:
        candidate = folder / "pyproject.toml"
        if not candidate.is_file():
            continue
        try:
            table = tomllib.loads(candidate.read_text("utf-8")).get("tool", {}).get("mjcf-model")
        except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
            raise MjcfValueError(
                f"cannot read the settings: {error}", file=str(candidate)
            ) from None
        if table is not None:
            return dict(table), candidate
    return {}, None
