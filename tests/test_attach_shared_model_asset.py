"""An unnamed asset ``<model>`` two children share is read from the parent's folder.

Two children attached without a prefix that both declare the same unnamed
``<model file="sub.xml"/>`` share it (kept once). Its name is its file's root
``model`` attribute; the composer once read that file from the working folder
instead of the parent's, where the child's paths are rebased, and failed elsewhere.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model import attach_all, compiled
from mjcf_model.tree.queries import find_all
from serializers import load, loads
from tests.conftest import FIXTURES

FOLDER = FIXTURES / "attach_shared_model_asset"


def test_a_shared_unnamed_model_asset_does_not_depend_on_the_working_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Attaching two children sharing an unnamed ``<model>`` asset works from any working folder."""
    monkeypatch.chdir(tmp_path)
    parent = loads("<mujoco/>", base_dir=FOLDER)
    children = [(load(FOLDER / "parts" / "a.xml"), ""), (load(FOLDER / "parts" / "b.xml"), "")]
    scene = attach_all(parent, children)
    assert len(find_all(scene, "model")) == 1
    together = compiled(scene)
    alone = [mujoco.MjModel.from_xml_path(str(FOLDER / "parts" / f)) for f in ("a.xml", "b.xml")]
    assert together.nbody == sum(m.nbody for m in alone) - 1
    assert together.body("a").id > 0 and together.body("b").id > 0
