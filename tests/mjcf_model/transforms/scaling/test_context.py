"""Tests of ``mjcf_model.transforms.scaling.context``: the factors every scaling rule reads."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest

from mjcf_model.serializers import loads
from mjcf_model.transforms.scaling.context import ScaleContext, factor_cycle, times, times_cycle
from mjcf_model.tree.defaults import DefaultClasses

#: A cube weighed by its density, its half size given per axis.
CUBE = """<mujoco><worldbody><body><freejoint/>
  <geom type="box" size="{} {} {}" density="1000"/>
</body></worldbody></mujoco>"""


def _cube(x: float, y: float, z: float) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(CUBE.format(0.1 * x, 0.1 * y, 0.1 * z))


@pytest.mark.parametrize("factors", [(2.0, 2.0, 2.0), (2.0, 3.0, 4.0), (0.5, 1.5, 1.0)])
def test_volume_mass_and_inertia_factors_are_what_mujoco_weighs(
    factors: tuple[float, float, float],
) -> None:
    """Under ``mass="volume"`` a cube's mass and inertias change as MuJoCo computes them."""
    context = ScaleContext(factors=factors, mass="volume")
    original, scaled = _cube(1, 1, 1), _cube(*factors)
    mass_ratio = scaled.body_mass[1] / original.body_mass[1]
    assert math.isclose(context.volume, mass_ratio, rel_tol=1e-12)
    assert context.mass_factor == context.volume
    inertia_ratio = scaled.body_inertia[1] / original.body_inertia[1]
    assert np.allclose(context.cycles.inertia[:3], inertia_ratio, rtol=1e-12, atol=0)
    assert ScaleContext(factors=factors).mass_factor == 1.0  # "keep"


def test_a_uniform_factor_is_exact_and_mixed_ones_average() -> None:
    """Equal factors give themselves, their square and cube exactly; mixed ones their mean."""
    uniform = ScaleContext(factors=(0.8, 0.8, 0.8))
    assert uniform.mean == 0.8 and uniform.area == 0.8**2 and uniform.volume == 0.8 * 0.8 * 0.8
    assert uniform.cycles.per_axis == (0.8,)
    mixed = ScaleContext(factors=(1.0, 2.0, 6.0))
    assert mixed.mean == 3.0 and mixed.volume == 12.0
    assert math.isclose(mixed.area, 12.0 ** (2 / 3), rel_tol=1e-15)
    assert mixed.cycles.per_axis == (1.0, 2.0, 6.0)
    assert mixed.cycles.sizes == (
        (1.0, 2.0, 6.0),
        (3.0, 2.0, 6.0),
        (1.5, 6.0, 6.0),
        (1.0, 2.0, 6.0),
    )


def test_a_length_along_an_axis_is_the_scaled_unit_axis() -> None:
    """The factor along an axis is the length of the unit axis scaled; a zero axis takes x's."""
    context = ScaleContext(factors=(2.0, 3.0, 4.0))
    assert context.along((1.0, 0.0, 0.0)) == 2.0 and context.along((0.0, 0.0, 5.0)) == 4.0
    assert math.isclose(context.along((1.0, 1.0, 0.0)), math.sqrt((4 + 9) / 2), rel_tol=1e-15)
    assert context.along((0.0, 0.0, 0.0)) == 2.0


def test_the_joint_layout_is_mujocos_qpos_order() -> None:
    """Joints come in MuJoCo's ``qpos`` order, each with its type, classes applied."""
    text = """<mujoco>
      <default><default class="s"><joint type="slide" axis="1 0 0"/></default></default>
      <worldbody>
        <body name="a"><joint name="h"/><geom size="0.1"/>
          <body name="c"><joint name="s" class="s"/><geom size="0.1"/></body>
        </body>
        <body name="b"><freejoint name="f"/><geom size="0.1"/>
          <body name="d"><joint name="ball" type="ball"/><geom size="0.1"/></body>
        </body>
      </worldbody>
    </mujoco>"""
    model = loads(text)
    context = ScaleContext(factors=(2.0, 2.0, 2.0), model=model, classes=DefaultClasses.of(model))
    compiled = mujoco.MjModel.from_xml_string(text)
    assert context.layout is not None
    assert [j.name for j in context.layout] == [
        compiled.joint(i).name for i in range(compiled.njnt)
    ]
    kinds = {"free": 0, "ball": 1, "slide": 2, "hinge": 3}
    assert [kinds[j.type] for j in context.layout] == compiled.jnt_type.tolist()
    joint = context.joint("s")
    assert joint is not None and np.array_equal(
        joint.axis, compiled.jnt_axis[compiled.joint("s").id]
    )
    assert context.joint("missing") is None
    assert ScaleContext(factors=(2.0, 2.0, 2.0)).layout == ()


def test_values_are_multiplied_in_their_own_shape() -> None:
    """Numbers stay numbers, vectors vectors and text text, the factors cycled over them."""
    assert times((1.0, 2.0, 3.0), (2.0, 3.0, 4.0)) == (2.0, 6.0, 12.0)
    assert times(0.5, 2) == 1.0
    assert times("0.25 1 1", [2, 3]) == "0.5 3 2"
    assert times_cycle((1.0, 2.0), (10.0,)) == (10.0, 20.0)
    assert factor_cycle([2, 2, 2]) == (2.0,) and factor_cycle(np.array([1, 2])) == (1.0, 2.0)
