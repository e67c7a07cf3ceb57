"""Tests of the asset and class rules: what nothing uses, and files loaded twice."""

from __future__ import annotations

from pathlib import Path

import mujoco

from mjcf_model import load, loads
from mjcf_model.bridge.compare import model_differences
from mjcf_model.tools.lint import lint
from mjcf_model.tools.lint.assets import used_assets
from mjcf_model.tools.lint.subject import Subject

USES = """
<mujoco>
  <asset>
    <texture name="sky" type="skybox" builtin="gradient" width="8" height="8"/>
    <texture name="grid" type="2d" builtin="checker" width="8" height="8"/>
    <texture name="spare" type="2d" builtin="flat" width="8" height="8"/>
    <material name="floor" texture="grid"/>
    <material name="paint" rgba="1 0 0 1"/>
    <material name="old" rgba="0 1 0 1"/>
    <mesh name="tet" vertex="0 0 0 1 0 0 0 1 0 0 0 1"/>
    <mesh name="spare_tet" vertex="0 0 0 1 0 0 0 1 0 0 0 1"/>
  </asset>
  <default>
    <default class="painted"><geom material="paint"/>
      <default class="shiny"><geom rgba="1 1 1 1"/></default>
    </default>
    <default class="unused"><geom rgba="0 0 1 1"/></default>
  </default>
  <worldbody>
    <geom type="plane" size="1 1 0.1" material="floor"/>
    <body childclass="shiny"><geom type="mesh" mesh="tet"/></body>
  </worldbody>
</mujoco>
"""


def test_assets_nothing_uses_are_found_and_their_removal_changes_nothing_else() -> None:
    """A401: a texture, a material and a mesh; what defaults, materials and skyboxes use is not.

    MuJoCo referee: the model compiled without them differs only in those assets' arrays.
    """
    findings = lint(loads(USES), select=["A401"])
    assert [f.path for f in findings] == [
        "/mujoco/asset/mesh[@name='spare_tet']",
        "/mujoco/asset/material[@name='old']",
        "/mujoco/asset/texture[@name='spare']",
    ]
    lean = USES
    for line in ('<mesh name="spare_tet"', '<material name="old"', '<texture name="spare"'):
        lean = "\n".join(row for row in lean.splitlines() if line not in row)
    before = mujoco.MjModel.from_xml_string(USES)
    after = mujoco.MjModel.from_xml_string(lean)
    differing = model_differences(before, after)
    kept = ("mesh_", "mat_", "tex_", "bvh_", "name", "nnames", "nmesh", "nmat", "ntex", "nbvh")
    kept = (*kept, "nbuffer")
    assert differing and all(name.startswith(kept) for name in differing), differing
    assert "geom_dataid" not in differing and "geom_matid" not in differing
    subject = Subject(loads(lean))
    assert lint(loads(lean), select=["A401"]) == []
    assert used_assets(subject)["texture"] == {0, 1}


def test_a_class_nothing_names_is_found_and_one_a_used_class_nests_in_is_not() -> None:
    """A402: ``shiny`` is named, so ``painted`` (its parent) is used; ``unused`` is not."""
    findings = lint(loads(USES), select=["A402"])
    assert [(f.path, f.message.split(":")[0]) for f in findings] == [
        ("/mujoco/default/default[2]", "default class 'unused' is used by nothing")
    ]


def test_one_file_loaded_twice_with_the_same_settings_is_found(tmp_path: Path) -> None:
    """A403: the second mesh of one file is found; a scaled copy is a different mesh."""
    (tmp_path / "tet.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n")
    text = """<mujoco><asset>
      <mesh name="a" file="tet.obj"/><mesh name="b" file="tet.obj"/>
      <mesh name="big" file="tet.obj" scale="2 2 2"/></asset>
      <worldbody><geom type="mesh" mesh="a"/><geom type="mesh" mesh="b"/>
      <geom type="mesh" mesh="big"/></worldbody></mujoco>"""
    (tmp_path / "m.xml").write_text(text)
    findings = lint(load(tmp_path / "m.xml"), select=["A"])
    assert [(f.rule, f.path, f.line) for f in findings] == [
        ("A403", "/mujoco/asset/mesh[@name='b']", 2)
    ]
