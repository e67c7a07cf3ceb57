"""Tests of ``mjcf_model.nodes.geom``: geoms, sites, cameras and lights."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Camera, Geom, Light, Site
from mjcf_model.serializers import loads
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

#: One of each thing a body carries, with values MuJoCo's defaults do not have.
CARRIED = """<mujoco>
  <worldbody>
    <light name="lamp" pos="0 0 3" dir="0 0 -1" diffuse="0.5 0.4 0.3"/>
    <body name="b" pos="0 0 1">
      <geom name="g" type="capsule" size="0.05 0.2" rgba="0.1 0.2 0.3 1" friction="0.7 0.01 0.001"/>
      <site name="s" pos="0 0 0.1" size="0.02"/>
      <camera name="c" pos="0 -1 0" fovy="60" resolution="64 48"/>
    </body>
  </worldbody>
</mujoco>
"""
MODULE = "mjcf_model.nodes.geom"


def test_carried_things_load_typed_and_hold_what_mujoco_compiles() -> None:
    """Each element's typed values are the arrays MuJoCo compiles for it."""
    model = loads(CARRIED)
    assert loaded_from(model, MODULE) == declared_in(MODULE) == {"Geom", "Site", "Camera", "Light"}
    compiled = mujoco.MjModel.from_xml_string(CARRIED)
    light = model.worldbody.children[0]
    body = model.worldbody.bodies[0]
    geom, site, camera = body.geoms[0], body.sites[0], body.children[2]
    assert isinstance(light, Light) and isinstance(geom, Geom)
    assert isinstance(site, Site) and isinstance(camera, Camera)
    assert np.array_equal(np.float32(light.diffuse), compiled.light("lamp").diffuse)  # float32
    assert np.array_equal(geom.size, compiled.geom("g").size[:2])
    assert np.array_equal(geom.friction, compiled.geom("g").friction)
    assert np.array_equal(np.float32(geom.rgba), compiled.geom("g").rgba)
    assert np.array_equal(site.pos, compiled.site("s").pos)
    assert camera.fovy == compiled.camera("c").fovy[0]
    assert np.array_equal(camera.resolution, compiled.cam_resolution[0])
    assert text_round_trip_differences(CARRIED) == []
