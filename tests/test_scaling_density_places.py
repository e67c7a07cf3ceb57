"""Where ``scaled(mass="keep")`` writes a density, checked against MuJoCo's masses.

Under ``mass="keep"`` a geom weighed by its density gets the density that keeps its
mass; a geom of the world body weighs nothing in MuJoCo and is left alone. MuJoCo
compiling the original is the referee: every array of the scaled model is the
original's scaled, masses unchanged (``scaled_model_problems``).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import mujoco

from mjcf_model import Geom
from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.queries import find
from serializers import dumps, from_etree, loads
from tests.support.scaling_oracle import scaled_model_problems

#: World geoms, directly and in a frame; body geoms, directly, in a frame and by class.
PLACES = """
<mujoco>
  <default><default class="heavy"><geom density="5000"/></default></default>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1" density="300"/>
    <frame pos="0 0 0.5"><geom name="world_box" type="box" size="0.1 0.1 0.1"/></frame>
    <body name="b" pos="0 0 1">
      <freejoint/>
      <geom name="own" type="box" size="0.1 0.2 0.3" density="700"/>
      <frame pos="0.3 0 0"><geom name="framed" type="sphere" size="0.1"/></frame>
      <geom name="classed" class="heavy" type="capsule" size="0.05 0.1" pos="0 0.3 0"/>
    </body>
  </worldbody>
</mujoco>
"""


def _geom(model: AnyElement, name: str) -> AnyElement:
    found = find(model, "geom", name=name)
    assert found is not None
    return found


def test_body_geoms_keep_their_mass_and_world_geoms_write_no_density() -> None:
    """Masses are MuJoCo's original ones; the world's geoms keep the density they wrote."""
    new = scaled(loads(PLACES), 2.0)
    original = mujoco.MjModel.from_xml_string(PLACES)
    assert scaled_model_problems(original, mujoco.MjModel.from_xml_string(dumps(new)), 2.0) == []
    assert get_attribute(_geom(new, "floor"), "density") == 300.0
    assert get_attribute(_geom(new, "world_box"), "density") is None
    assert get_attribute(_geom(new, "framed"), "density") == 1000.0 / 8


def test_a_geom_scaled_alone_keeps_its_mass_where_it_is_placed() -> None:
    """A geom scaled on its own gets the density that keeps its mass once in a body."""
    geom = Geom(type="box", size=[0.1, 0.2, 0.3], density=700.0)
    body = '<mujoco><worldbody><body pos="0 0 1"><freejoint/>{}</body></worldbody></mujoco>'
    before = mujoco.MjModel.from_xml_string(body.format(dumps(geom)))
    after = mujoco.MjModel.from_xml_string(body.format(dumps(scaled(geom, 2.0))))
    assert after.body_mass[1] == before.body_mass[1]


def test_a_shell_geom_of_an_untyped_tree_keeps_its_mass() -> None:
    """``shellinertia="true"`` read as text (robosuite's untyped trees) weighs by area."""
    text = (
        '<mujoco><worldbody><body pos="0 0 1"><freejoint/>'
        '<geom type="box" size="0.1 0.2 0.3" shellinertia="true" density="50"/>'
        "</body></worldbody></mujoco>"
    )
    new = scaled(from_etree(ET.fromstring(text), typed=False), 2.0)
    original = mujoco.MjModel.from_xml_string(text)
    assert scaled_model_problems(original, mujoco.MjModel.from_xml_string(dumps(new)), 2.0) == []


def test_a_mesh_holding_a_comment_is_scaled_through_its_scale() -> None:
    """A comment inside a ``<mesh>`` does not make it a plugin's mesh: its scale is written."""
    text = (
        '<mujoco><asset><mesh name="m" vertex="0 0 0 1 0 0 0 1 0 0 0 1"><!-- a tetrahedron -->'
        '</mesh></asset><worldbody><body><freejoint/><geom type="mesh" mesh="m"/></body>'
        "</worldbody></mujoco>"
    )
    new = scaled(loads(text), 2.0)
    original = mujoco.MjModel.from_xml_string(text)
    assert scaled_model_problems(original, mujoco.MjModel.from_xml_string(dumps(new)), 2.0) == []
