"""Tests of ``mjcf_model.transforms.composition.shared_assets``: repeats kept once.

MuJoCo is the referee: a shared scene compiles to the unshared one but for the assets'
own arrays and counts; each geom's mesh and material hold the same values as before.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from mjcf_model import attach_all, compiled, dumps, load, loads
from mjcf_model.bridge.compare import model_differences
from mjcf_model.transforms.composition.shared_assets import shared_assets
from tests.conftest import corpus_files

#: The compiled arrays sharing may change: the assets' own, their counts and ids, names.
_ASSET_ARRAYS = ("mesh_", "mat_", "tex_", "bvh_", "name", "paths", "nmesh", "nmat", "ntex")
_ASSET_ARRAYS += ("nbvh", "nbuffer", "nnames", "npaths", "geom_dataid", "geom_matid")


def _panda() -> Path:
    return next(p for p in corpus_files() if str(p).endswith("robots/panda/robot.xml"))


def _mesh_rows(model: object, mesh: int) -> np.ndarray:
    start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]  # type: ignore[attr-defined]
    return np.asarray(model.mesh_vert[start : start + count])  # type: ignore[attr-defined]


@pytest.mark.parametrize("copies", [1, 2, 3])
def test_copies_of_a_robot_share_their_assets_and_compile_to_the_same_scene(copies: int) -> None:
    """Robosuite's Panda attached 1 to 3 times: each mesh file once, everything else equal."""
    panda = load(_panda(), inline_includes=True)
    parts = [(panda, f"p{i}_") for i in range(copies)]
    apart = compiled(attach_all(loads("<mujoco/>"), parts))
    together = compiled(attach_all(loads("<mujoco/>"), parts, share_assets=True))
    differing = model_differences(apart, together)
    assert all(name.startswith(_ASSET_ARRAYS) for name in differing), differing
    alone = compiled(shared_assets(panda))
    assert together.nmesh == alone.nmesh and apart.nmesh == copies * compiled(panda).nmesh
    assert together.nmat == alone.nmat
    for geom in range(apart.ngeom):
        mesh_apart, mesh_together = apart.geom_dataid[geom], together.geom_dataid[geom]
        if mesh_apart >= 0:
            assert np.array_equal(
                _mesh_rows(apart, mesh_apart), _mesh_rows(together, mesh_together)
            )
        mat_apart, mat_together = apart.geom_matid[geom], together.geom_matid[geom]
        assert (mat_apart < 0) == (mat_together < 0)
        if mat_apart >= 0:
            assert np.array_equal(apart.mat_rgba[mat_apart], together.mat_rgba[mat_together])


def test_only_assets_the_same_but_for_their_name_are_shared(tmp_path: Path) -> None:
    """Another file, another scale or no name: kept apart.

    A material made the same by a shared texture is shared in turn.
    """
    for name in ("tet.obj", "other.obj"):
        (tmp_path / name).write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n")
    text = """<mujoco><asset>
      <mesh name="a" file="tet.obj"/><mesh name="b" file="./tet.obj"/>
      <mesh name="c" file="other.obj"/><mesh name="d" file="tet.obj" scale="2 2 2"/>
      <mesh file="tet.obj"/>
      <texture name="t1" type="2d" builtin="checker" width="8" height="8"/>
      <texture name="t2" type="2d" builtin="checker" width="8" height="8"/>
      <material name="m1" texture="t1"/><material name="m2" texture="t2"/></asset>
      <worldbody><geom type="mesh" mesh="a" material="m1"/>
      <geom type="mesh" mesh="b" material="m2"/>
      <geom type="mesh" mesh="c"/><geom type="mesh" mesh="d"/><geom type="mesh" mesh="tet"/>
      </worldbody></mujoco>"""
    (tmp_path / "m.xml").write_text(text)
    model = load(tmp_path / "m.xml")
    shared = shared_assets(model)
    assert [g.mesh for g in shared.worldbody.geoms] == ["a", "a", "c", "d", "tet"]
    assert [g.material for g in shared.worldbody.geoms][:2] == ["m1", "m1"]
    assert "t2" not in dumps(shared) and 'name="m2"' not in dumps(shared)
    assert model_differences(compiled(model), compiled(shared))  # fewer assets
    assert shared_assets(shared) is shared  # nothing repeats any more


def test_the_compose_verb_shares_assets_when_asked(tmp_path: Path) -> None:
    """``compose --share-assets``: the scene of two Pandas loads each mesh once."""
    from mjcf_model.tools.cli import main

    out = tmp_path / "scene.xml"
    empty = tmp_path / "empty.xml"
    empty.write_text("<mujoco/>")
    panda = str(_panda())
    assert main(["compose", str(out), str(empty), f"{panda}:a_", f"{panda}:b_"]) == 0
    apart = compiled(load(out))
    assert (
        main(["compose", str(out), str(empty), f"{panda}:a_", f"{panda}:b_", "--share-assets"]) == 0
    )
    together = compiled(load(out))
    assert together.nmesh * 2 == apart.nmesh and together.nbody == apart.nbody
