"""Compile-time and simulation settings: ``<compiler>``, ``<option>``, ``<size>``, ``<statistic>``.

>>> Option(timestep="0.002", gravity=[0, 0, -9.81]).gravity
(0.0, 0.0, -9.81)
"""

from __future__ import annotations

from typing import ClassVar

import attrs

from mjcf_model.base import TypedElement
from mjcf_model.values import (
    Floats,
    Ints,
    float_key,
    to_float,
    to_floats,
    to_int,
    to_ints,
    to_str,
    to_vec1to2,
    to_vec1to5,
    to_vec3,
)

__all__ = ["Compiler", "LengthRange", "Option", "OptionFlag", "Size", "Statistic"]


@attrs.frozen(kw_only=True, repr=False)
class Compiler(TypedElement):
    """Compiler settings: angle units, asset directories, inertia handling."""

    tag: ClassVar[str] = "compiler"
    #: Compiler setting ``alignfree``; see the MuJoCo XML reference.
    alignfree: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``angle``; see the MuJoCo XML reference.
    angle: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``assetdir``; see the MuJoCo XML reference.
    assetdir: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``autolimits``; see the MuJoCo XML reference.
    autolimits: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``balanceinertia``; see the MuJoCo XML reference.
    balanceinertia: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``boundinertia``; see the MuJoCo XML reference.
    boundinertia: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``boundmass``; see the MuJoCo XML reference.
    boundmass: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``conflict``; see the MuJoCo XML reference.
    conflict: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``coordinate``; see the MuJoCo XML reference.
    coordinate: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``discardvisual``; see the MuJoCo XML reference.
    discardvisual: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``eulerseq``; see the MuJoCo XML reference.
    eulerseq: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``fitaabb``; see the MuJoCo XML reference.
    fitaabb: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``fusestatic``; see the MuJoCo XML reference.
    fusestatic: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``inertiafromgeom``; see the MuJoCo XML reference.
    inertiafromgeom: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``inertiagrouprange``; see the MuJoCo XML reference.
    inertiagrouprange: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``meshdir``; see the MuJoCo XML reference.
    meshdir: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``passthrough``; see the MuJoCo XML reference.
    passthrough: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``savecanonical``; see the MuJoCo XML reference.
    savecanonical: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``savecompiled``; see the MuJoCo XML reference.
    savecompiled: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``saveinertial``; see the MuJoCo XML reference.
    saveinertial: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``settotalmass``; see the MuJoCo XML reference.
    settotalmass: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``strippath``; see the MuJoCo XML reference.
    strippath: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``texturedir``; see the MuJoCo XML reference.
    texturedir: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``usethread``; see the MuJoCo XML reference.
    usethread: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class LengthRange(TypedElement):
    """How actuator length ranges are computed."""

    tag: ClassVar[str] = "lengthrange"
    #: Compiler setting ``accel``; see the MuJoCo XML reference.
    accel: str | None = attrs.field(default=None, converter=to_str)
    #: Sampling interval (and phase).
    interval: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``inttotal``; see the MuJoCo XML reference.
    inttotal: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``maxforce``; see the MuJoCo XML reference.
    maxforce: str | None = attrs.field(default=None, converter=to_str)
    #: How the element tracks its target (``fixed``, ``track``, ``trackcom``, ...).
    mode: str | None = attrs.field(default=None, converter=to_str)
    #: Time constant(s).
    timeconst: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``timestep``; see the MuJoCo XML reference.
    timestep: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``tolrange``; see the MuJoCo XML reference.
    tolrange: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``useexisting``; see the MuJoCo XML reference.
    useexisting: str | None = attrs.field(default=None, converter=to_str)
    #: Compiler setting ``uselimit``; see the MuJoCo XML reference.
    uselimit: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Option(TypedElement):
    """Simulation options: timestep, gravity, solver, integrator."""

    tag: ClassVar[str] = "option"
    #: Simulation option ``actuatorgroupdisable``; see the MuJoCo XML reference.
    actuatorgroupdisable: Ints | None = attrs.field(default=None, converter=to_ints)
    #: Simulation option ``ccd_iterations``; see the MuJoCo XML reference.
    ccd_iterations: int | None = attrs.field(default=None, converter=to_int)
    #: Simulation option ``ccd_tolerance``; see the MuJoCo XML reference.
    ccd_tolerance: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Simulation option ``cone``; see the MuJoCo XML reference.
    cone: str | None = attrs.field(default=None, converter=to_str)
    #: Density used to compute mass from volume.
    density: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Simulation option ``gravity``; see the MuJoCo XML reference.
    gravity: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Simulation option ``impratio``; see the MuJoCo XML reference.
    impratio: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Simulation option ``integrator``; see the MuJoCo XML reference.
    integrator: str | None = attrs.field(default=None, converter=to_str)
    #: Simulation option ``iterations``; see the MuJoCo XML reference.
    iterations: int | None = attrs.field(default=None, converter=to_int)
    #: Simulation option ``jacobian``; see the MuJoCo XML reference.
    jacobian: str | None = attrs.field(default=None, converter=to_str)
    #: Simulation option ``ls_iterations``; see the MuJoCo XML reference.
    ls_iterations: int | None = attrs.field(default=None, converter=to_int)
    #: Simulation option ``ls_tolerance``; see the MuJoCo XML reference.
    ls_tolerance: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Simulation option ``magnetic``; see the MuJoCo XML reference.
    magnetic: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Simulation option ``noslip_iterations``; see the MuJoCo XML reference.
    noslip_iterations: int | None = attrs.field(default=None, converter=to_int)
    #: Simulation option ``noslip_tolerance``; see the MuJoCo XML reference.
    noslip_tolerance: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Simulation option ``o_friction``; see the MuJoCo XML reference.
    o_friction: Floats | None = attrs.field(default=None, converter=to_floats)
    #: Simulation option ``o_margin``; see the MuJoCo XML reference.
    o_margin: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Simulation option ``o_solimp``; see the MuJoCo XML reference.
    o_solimp: Floats | None = attrs.field(default=None, converter=to_vec1to5)
    #: Simulation option ``o_solref``; see the MuJoCo XML reference.
    o_solref: Floats | None = attrs.field(default=None, converter=to_vec1to2)
    #: Simulation option ``sdf_initpoints``; see the MuJoCo XML reference.
    sdf_initpoints: int | None = attrs.field(default=None, converter=to_int)
    #: Simulation option ``sdf_iterations``; see the MuJoCo XML reference.
    sdf_iterations: int | None = attrs.field(default=None, converter=to_int)
    #: Simulation option ``sleep_tolerance``; see the MuJoCo XML reference.
    sleep_tolerance: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Simulation option ``solver``; see the MuJoCo XML reference.
    solver: str | None = attrs.field(default=None, converter=to_str)
    #: Simulation option ``timestep``; see the MuJoCo XML reference.
    timestep: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Simulation option ``tolerance``; see the MuJoCo XML reference.
    tolerance: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Simulation option ``viscosity``; see the MuJoCo XML reference.
    viscosity: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Simulation option ``wind``; see the MuJoCo XML reference.
    wind: Floats | None = attrs.field(default=None, converter=to_vec3)


@attrs.frozen(kw_only=True, repr=False)
class OptionFlag(TypedElement):
    """Enable or disable parts of the simulation pipeline."""

    tag: ClassVar[str] = "flag"
    #: Enable or disable ``actuation`` (``enable``/``disable``).
    actuation: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``autoreset`` (``enable``/``disable``).
    autoreset: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``clampctrl`` (``enable``/``disable``).
    clampctrl: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``constraint`` (``enable``/``disable``).
    constraint: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``contact`` (``enable``/``disable``).
    contact: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``damper`` (``enable``/``disable``).
    damper: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``diagexact`` (``enable``/``disable``).
    diagexact: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``energy`` (``enable``/``disable``).
    energy: str | None = attrs.field(default=None, converter=to_str)
    #: Whether edge equality constraints are generated.
    equality: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``eulerdamp`` (``enable``/``disable``).
    eulerdamp: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``filterparent`` (``enable``/``disable``).
    filterparent: str | None = attrs.field(default=None, converter=to_str)
    #: Dry friction loss.
    frictionloss: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``fwdinv`` (``enable``/``disable``).
    fwdinv: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``gravity`` (``enable``/``disable``).
    gravity: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``invdiscrete`` (``enable``/``disable``).
    invdiscrete: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``ipc`` (``enable``/``disable``).
    ipc: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``island`` (``enable``/``disable``).
    island: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``limit`` (``enable``/``disable``).
    limit: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``midphase`` (``enable``/``disable``).
    midphase: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``multiccd`` (``enable``/``disable``).
    multiccd: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``nativeccd`` (``enable``/``disable``).
    nativeccd: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``override`` (``enable``/``disable``).
    override: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``refsafe`` (``enable``/``disable``).
    refsafe: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``sensor`` (``enable``/``disable``).
    sensor: str | None = attrs.field(default=None, converter=to_str)
    #: Sleep policy of the body's tree.
    sleep: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``speculative`` (``enable``/``disable``).
    speculative: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``spring`` (``enable``/``disable``).
    spring: str | None = attrs.field(default=None, converter=to_str)
    #: Enable or disable ``warmstart`` (``enable``/``disable``).
    warmstart: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Size(TypedElement):
    """Memory and array size hints."""

    tag: ClassVar[str] = "size"
    #: Size setting ``memory``; see the MuJoCo XML reference.
    memory: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nconmax``; see the MuJoCo XML reference.
    nconmax: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``njmax``; see the MuJoCo XML reference.
    njmax: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nkey``; see the MuJoCo XML reference.
    nkey: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nstack``; see the MuJoCo XML reference.
    nstack: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nuser_actuator``; see the MuJoCo XML reference.
    nuser_actuator: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nuser_body``; see the MuJoCo XML reference.
    nuser_body: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nuser_cam``; see the MuJoCo XML reference.
    nuser_cam: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nuser_geom``; see the MuJoCo XML reference.
    nuser_geom: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nuser_jnt``; see the MuJoCo XML reference.
    nuser_jnt: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nuser_sensor``; see the MuJoCo XML reference.
    nuser_sensor: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nuser_site``; see the MuJoCo XML reference.
    nuser_site: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nuser_tendon``; see the MuJoCo XML reference.
    nuser_tendon: str | None = attrs.field(default=None, converter=to_str)
    #: Size setting ``nuserdata``; see the MuJoCo XML reference.
    nuserdata: str | None = attrs.field(default=None, converter=to_str)


@attrs.frozen(kw_only=True, repr=False)
class Statistic(TypedElement):
    """Model statistics that override the computed ones."""

    tag: ClassVar[str] = "statistic"
    #: Model statistic ``center``; see the MuJoCo XML reference.
    center: Floats | None = attrs.field(default=None, converter=to_vec3)
    #: Model statistic ``extent``; see the MuJoCo XML reference.
    extent: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Model statistic ``meaninertia``; see the MuJoCo XML reference.
    meaninertia: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Model statistic ``meanmass``; see the MuJoCo XML reference.
    meanmass: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
    #: Model statistic ``meansize``; see the MuJoCo XML reference.
    meansize: float | None = attrs.field(default=None, converter=to_float, eq=float_key)
