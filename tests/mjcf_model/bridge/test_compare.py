"""Tests of ``mjcf_model.bridge.compare``: the referee of every round trip."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from mjcf_model.bridge.compare import (
    compile_text_beside,
    compiled_names,
    model_differences,
    path_fields,
)

#: A body with a named geom and site, and an unnamed geom.
MODEL = """<mujoco>
  <option timestep="{timestep}"/>
  <worldbody>
    <body name="box"><geom name="hull" size="0.1" rgba="{rgba}"/><site name="tip"/></body>
    <geom size="0.2"/>
  </worldbody>
</mujoco>
"""

#: A tetrahedron, as a Wavefront OBJ file.
TETRAHEDRON = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n"


def _model(timestep: str = "0.002", rgba: str = "1 0 0 1") -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(MODEL.format(timestep=timestep, rgba=rgba))


def test_equal_models_have_no_difference_and_a_changed_field_is_named() -> None:
    """Two compiles of one text differ in nothing; a changed colour or timestep is named."""
    assert model_differences(_model(), _model()) == []
    assert model_differences(_model(), _model(rgba="0 1 0 1")) == ["geom_rgba"]
    assert model_differences(_model(), _model(timestep="0.004")) == ["opt.timestep"]
    assert (
        model_differences(_model(), _model(rgba="0 1 0 1"), ignore=frozenset({"geom_rgba"})) == []
    )


def test_compiled_names_are_mujocos_names_by_kind() -> None:
    """Each kind lists the names MuJoCo's own accessors give, unnamed objects as ``""``."""
    model = _model()
    names = compiled_names(model)
    assert names["body"] == [model.body(i).name for i in range(model.nbody)] == ["world", "box"]
    assert names["geom"] == [model.geom(i).name for i in range(model.ngeom)] == ["", "hull"]
    assert names["site"] == ["tip"]


def test_a_copy_of_a_file_elsewhere_differs_only_in_path_fields(tmp_path: Path) -> None:
    """The same mesh read from two folders compiles alike but for the recorded paths."""
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "t.obj").write_text(TETRAHEDRON)
    text = '<mujoco><asset><mesh file="{}/t.obj"/></asset></mujoco>'
    one = compile_text_beside(text.format("a"), tmp_path / "m.xml")
    other = compile_text_beside(text.format("b"), tmp_path / "m.xml")
    assert "paths" in model_differences(one, other)
    assert set(model_differences(one, other)) <= path_fields()
    assert model_differences(one, other, ignore=path_fields()) == []


def test_text_compiled_beside_a_file_finds_its_files_and_leaves_none(tmp_path: Path) -> None:
    """Relative paths resolve from the original's folder; no temporary file is left behind.

    Not even when MuJoCo rejects the text.
    """
    (tmp_path / "t.obj").write_text(TETRAHEDRON)
    model = compile_text_beside(
        '<mujoco><asset><mesh file="t.obj"/></asset></mujoco>', tmp_path / "robot.xml"
    )
    assert model.nmesh == 1 and model.mesh_vertnum.tolist() == [4]
    with pytest.raises(ValueError) as rejected:
        compile_text_beside(
            '<mujoco><asset><mesh file="gone.obj"/></asset></mujoco>', tmp_path / "r.xml"
        )
    assert "gone.obj" in str(rejected.value)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["t.obj"]
