"""Tests of ``mjcf_model.nodes.compiler``: compile-time and simulation settings."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Compiler, Option, OptionFlag, Statistic
from mjcf_model.serializers import loads
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

#: Every settings element, each with values MuJoCo's defaults do not have.
SETTINGS = """<mujoco>
  <compiler angle="degree" autolimits="true"><lengthrange mode="none"/></compiler>
  <option timestep="0.004" gravity="0 0 -5" integrator="RK4">
    <flag contact="disable" energy="enable"/>
  </option>
  <size memory="1M" nuserdata="3"/>
  <statistic meansize="0.3" center="0 0 1"/>
  <worldbody><body><joint range="-90 90"/><geom size="0.1"/></body></worldbody>
</mujoco>
"""
MODULE = "mjcf_model.nodes.compiler"


def test_settings_load_typed_and_are_what_mujoco_compiles() -> None:
    """Each typed value is MuJoCo's: the options, the flags, the statistic, the angle unit."""
    model = loads(SETTINGS)
    assert loaded_from(model, MODULE) == declared_in(MODULE)
    compiled = mujoco.MjModel.from_xml_string(SETTINGS)
    compiler = next(c for c in model.children if isinstance(c, Compiler))
    option = next(c for c in model.children if isinstance(c, Option))
    statistic = next(c for c in model.children if isinstance(c, Statistic))
    flag = next(c for c in option.children if isinstance(c, OptionFlag))
    assert option.timestep == compiled.opt.timestep
    assert np.array_equal(option.gravity, compiled.opt.gravity)
    assert compiled.opt.integrator == mujoco.mjtIntegrator.mjINT_RK4 and option.integrator == "RK4"
    assert (
        flag.contact == "disable"
        and compiled.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_CONTACT
    )
    assert flag.energy == "enable" and compiled.opt.enableflags & mujoco.mjtEnableBit.mjENBL_ENERGY
    assert statistic.meansize == compiled.stat.meansize
    assert compiler.angle == "degree"
    assert np.allclose(compiled.jnt_range[0], np.radians([-90, 90]), rtol=1e-15, atol=0)
    assert text_round_trip_differences(SETTINGS) == []
