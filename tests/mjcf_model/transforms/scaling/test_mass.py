"""Tests of ``mjcf_model.transforms.scaling.mass``."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import mujoco
import numpy as np
import pytest

from mjcf_model import Geom
from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.serializers import dumps, from_etree, loads
from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.mass import is_shell
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.queries import find
from mjcf_model.tree.traversal import keyed_walk
from tests.support.scaling_oracle import (
    SCALING_FIXTURES,
    _scaled_copy,
    scaled_model_problems,
)

# -- Scaling on constructs real models use: masses, shells, flexcomps, SDFs, includes, skin
#    files.
#
# The fixtures live in ``tests/fixtures/scaling``; MuJoCo compiles each original and
# each scaled copy, and the oracle compares the compiled arrays.


def test_keep_policy_keeps_the_centre_of_mass_of_mixed_bodies() -> None:
    """A body mixing written masses and densities keeps its mass; its centre of mass doubles."""
    path = SCALING_FIXTURES / "mass.xml"
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = _scaled_copy(path, 2.0)
    for name in ("mixed", "mixed_shells"):
        before, after = original.body(name), changed.body(name)
        assert np.isclose(after.mass[0], before.mass[0], rtol=1e-12, atol=0)
        assert np.allclose(after.ipos, 2 * before.ipos, rtol=1e-9, atol=0)


def test_volume_policy_scales_shells_with_area_and_solids_with_volume() -> None:
    """Density masses grow by s**2 on shells and s**3 on solids; written masses by s**3."""
    path = SCALING_FIXTURES / "mass.xml"
    original = mujoco.MjModel.from_xml_path(str(path))
    changed = _scaled_copy(path, 2.0, mass="volume")
    expected = {"shells_only": 4.0, "solids_only": 8.0, "weighed_only": 8.0, "with_inertial": 8.0}
    for name, factor in expected.items():
        before, after = original.body(name), changed.body(name)
        assert np.isclose(after.mass[0], factor * before.mass[0], rtol=1e-9, atol=0), name
        trace = np.sum(after.inertia), 4 * factor * np.sum(before.inertia)
        assert np.isclose(*trace, rtol=1e-9, atol=0), name


# -- ``is_shell`` says which geoms MuJoCo weighs by their surface, however that is set. --------
#
# MuJoCo is the referee: with ``mass="volume"`` scaling leaves densities alone, so
# MuJoCo computes every scaled geom's mass from its scaled geometry, and a body
# holding one geom grows in mass by the factor squared when that geom is a shell
# and by the factor cubed when it is a solid.


#: One geom per body: shell inertia written on the geom, given by its class, by its
#: body's ``childclass``, or by its mesh (written on the mesh or given by its class);
#: and solids of each kind.
_GEOMS = """<mujoco><default>
  <default class="skin"><geom shellinertia="true"/></default>
  <default class="hollow"><mesh inertia="shell"/></default>
</default><asset>
  <mesh name="solid_tetra" vertex="0 0 0  .1 0 0  .02 .08 0  .01 .02 .06"/>
  <mesh name="shell_tetra" inertia="shell" vertex="0 0 0  .09 0 0  .03 .07 0  .02 .01 .05"/>
  <mesh name="class_tetra" class="hollow" vertex="0 0 0  .08 0 0  .01 .06 0  .03 .02 .07"/>
</asset><worldbody>
  <body name="written_shell"><freejoint/><geom type="box" size=".05 .04 .03"
    shellinertia="true"/></body>
  <body name="class_shell"><freejoint/><geom class="skin" size=".04"/></body>
  <body name="childclass_shell" childclass="skin"><freejoint/><geom type="capsule"
    size=".02 .06"/></body>
  <body name="mesh_shell"><freejoint/><geom type="mesh" mesh="shell_tetra"/></body>
  <body name="mesh_class_shell"><freejoint/><geom type="mesh" mesh="class_tetra"/></body>
  <body name="solid_box"><freejoint/><geom type="box" size=".05 .04 .03"/></body>
  <body name="solid_sphere"><freejoint/><geom size=".04" shellinertia="false"/></body>
  <body name="solid_mesh"><freejoint/><geom type="mesh" mesh="solid_tetra"/></body>
</worldbody></mujoco>"""


@pytest.mark.parametrize("factor", [2.0, 0.5])
def test_is_shell_is_true_exactly_for_the_geoms_mujoco_weighs_by_area(factor: float) -> None:
    """Each body's mass grows by the factor squared exactly where ``is_shell`` says so."""
    model = loads(_GEOMS)
    original = mujoco.MjModel.from_xml_string(_GEOMS)
    grown = mujoco.MjModel.from_xml_string(dumps(scaled(model, factor, mass="volume")))
    context = ScaleContext(factors=(2.0, 2.0, 2.0), classes=DefaultClasses.of(model), model=model)
    found = {
        ancestors[-1].name: is_shell(element, ancestors, context)
        for element, key, ancestors in keyed_walk(model)
        if key == "body/geom"
    }
    by_mujoco = {}
    for name in found:
        ratio = grown.body(name).mass[0] / original.body(name).mass[0]
        assert np.isclose(ratio, factor**2, rtol=1e-9) or np.isclose(ratio, factor**3, rtol=1e-9)
        by_mujoco[name] = bool(np.isclose(ratio, factor**2, rtol=1e-9))
    assert found == by_mujoco
    assert sorted(name for name, shell in found.items() if shell) == [
        "childclass_shell",
        "class_shell",
        "mesh_class_shell",
        "mesh_shell",
        "written_shell",
    ]


def test_without_a_model_no_mesh_is_known_to_be_a_shell() -> None:
    """A context without a model knows no mesh asset: a mesh geom is weighed as a solid.

    Only a box written ``shellinertia`` is a shell then, as in a model.
    """
    context = ScaleContext(factors=(2.0, 2.0, 2.0))
    model = loads(_GEOMS)
    geoms = {
        ancestors[-1].name: element
        for element, key, ancestors in keyed_walk(model)
        if key == "body/geom"
    }
    assert not is_shell(geoms["mesh_shell"], (), context)
    assert is_shell(geoms["written_shell"], (), context)


# -- Where ``scaled(mass="keep")`` writes a density, checked against MuJoCo's masses. ----------
#
# Under ``mass="keep"`` a geom weighed by its density gets the density that keeps its
# mass; a geom of the world body weighs nothing in MuJoCo and is left alone. MuJoCo
# compiling the original is the referee: every array of the scaled model is the
# original's scaled, masses unchanged (``scaled_model_problems``).


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
