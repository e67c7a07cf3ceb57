"""``is_shell`` says which geoms MuJoCo weighs by their surface, however that is set.

MuJoCo is the referee: with ``mass="volume"`` scaling leaves densities alone, so
MuJoCo computes every scaled geom's mass from its scaled geometry, and a body
holding one geom grows in mass by the factor squared when that geom is a shell
and by the factor cubed when it is a solid.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.mass import is_shell
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.traversal import keyed_walk
from serializers import dumps, loads

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
