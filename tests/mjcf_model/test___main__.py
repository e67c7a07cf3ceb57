"""Tests of ``mjcf_model.__main__``."""

from __future__ import annotations

import subprocess
import sys

# -- The ``mjcf-model`` command line. ----------------------------------------------------------


def test_module_entry_point() -> None:
    """``python -m mjcf_model`` runs the same command line."""
    done = subprocess.run(
        [sys.executable, "-m", "mjcf_model", "check", "--example"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert "1 identical" in done.stdout
