"""Tests of ``mjcf_model.nodes.asset``: the ``<asset>`` section and its typed views."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Asset
from mjcf_model.bridge.compare import compiled_names
from mjcf_model.serializers import loads
from tests.support.node_classes import loaded_from, text_round_trip_differences

#: Assets of every kind a model can hold without files, interleaved.
ASSETS = """<mujoco>
  <asset>
    <texture name="grid" type="2d" builtin="checker" width="8" height="8"/>
    <mesh name="small" vertex="0 0 0 1 0 0 0 1 0 0 0 1"/>
    <material name="red" rgba="1 0 0 1" texture="grid"/>
    <hfield name="ground" nrow="2" ncol="3" size="1 1 0.1 0.1"/>
    <mesh name="large" vertex="0 0 0 2 0 0 0 2 0 0 0 2"/>
    <texture name="sky" type="skybox" builtin="gradient" width="8" height="8"/>
    <material name="blue" rgba="0 0 1 1"/>
  </asset>
  <worldbody><geom type="mesh" mesh="small" material="red"/></worldbody>
</mujoco>
"""


def test_typed_views_follow_document_order_as_mujoco_numbers_assets() -> None:
    """``meshes``/``textures``/``materials``/``hfields`` list MuJoCo's objects in its order."""
    asset = loads(ASSETS).asset
    assert isinstance(asset, Asset)
    compiled = mujoco.MjModel.from_xml_string(ASSETS)
    names = compiled_names(compiled)
    assert [m.name for m in asset.meshes] == names["mesh"] == ["small", "large"]
    assert [t.name for t in asset.textures] == names["tex"] == ["grid", "sky"]
    assert [m.name for m in asset.materials] == names["mat"] == ["red", "blue"]
    assert [h.name for h in asset.hfields] == names["hfield"] == ["ground"]
    assert asset.skins == () and asset.models == ()
    assert np.array_equal(asset.materials[1].rgba, compiled.mat_rgba[1])
    assert (asset.hfields[0].nrow, asset.hfields[0].ncol) == (
        compiled.hfield_nrow[0],
        compiled.hfield_ncol[0],
    )
    found = loaded_from(loads(ASSETS), "mjcf_model.nodes.asset")
    assert found == {"Asset", "Texture", "Mesh", "Material", "Hfield"}
    assert text_round_trip_differences(ASSETS) == []
