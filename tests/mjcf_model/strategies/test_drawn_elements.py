"""Tests of ``mjcf_model.strategies.drawn_elements``: strategies for single elements."""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from mjcf_model import Body, Geom, Joint, Material, Mesh, Mujoco, Site, Worldbody
from mjcf_model.nodes.asset import Asset
from mjcf_model.serializers import dumps, loads
from mjcf_model.strategies.drawn_elements import elements, geoms, joints, materials, meshes, sites

#: The profile's examples, without a deadline (a drawn element can be slow to draw).
NO_DEADLINE = settings(deadline=None)

#: How many ``size`` values each primitive geom type reads.
SIZE_COUNT = {"sphere": 1, "capsule": 2, "cylinder": 2, "box": 3, "ellipsoid": 3}


@NO_DEADLINE
@given(
    geoms(name="g", material="m"),
    joints(name="j"),
    sites(name="s"),
    meshes(name="mesh"),
    materials(name="m"),
)
def test_drawn_elements_compile_to_the_values_drawn(
    geom: Geom, joint: Joint, site: Site, mesh: Mesh, material: Material
) -> None:
    """A model of one of each compiles, and MuJoCo holds the sizes and kinds drawn."""
    body = Body(name="b", children=[joint, geom, site, Geom(type="mesh", mesh="mesh")])
    model = Mujoco(children=[Asset(children=[mesh, material]), Worldbody(children=[body])])
    compiled = mujoco.MjModel.from_xml_string(dumps(model))
    count = SIZE_COUNT[geom.type or "sphere"]
    assert np.array_equal(compiled.geom("g").size[:count], (geom.size or (0.005,))[:count])
    assert (
        compiled.joint("j").type[0]
        == {"free": 0, "ball": 1, "slide": 2, "hinge": 3}[joint.type or "hinge"]
    )
    assert compiled.site("s").size[0] == site.size[0]
    assert compiled.mesh("mesh").vertnum[0] * 3 >= len(mesh.vertex or ()) > 0


#: The things a body holds, each drawn by ``elements``.
IN_A_BODY = st.one_of([elements(cls) for cls in (Geom, Joint, Site)])


@NO_DEADLINE
@given(IN_A_BODY)
def test_any_class_draws_instances_that_read_back_from_text(element: Any) -> None:
    """``elements(cls)`` gives instances of ``cls`` whose written text reads back equal."""
    assert type(element) in (Geom, Joint, Site)
    wrapped = Mujoco(children=[Worldbody(children=[Body(children=[element])])])
    assert loads(dumps(wrapped)).worldbody.bodies[0].children[0] == element
