"""Compile-time and simulation settings: ``<compiler>``, ``<option>``, ``<size>``, ``<statistic>``.

>>> Option(timestep="0.002", gravity=[0, 0, -9.81]).gravity
(0.0, 0.0, -9.81)
"""

from __future__ import annotations

from typing import ClassVar

from mjcf_model.nodes.base import TypedElement
from mjcf_model.nodes.declaring import node
from mjcf_model.nodes.fields import integer, integers, number, numbers, text, vec1to2, vec1to5, vec3
from mjcf_model.values import Floats, Ints

__all__ = ["Compiler", "LengthRange", "Option", "OptionFlag", "Size", "Statistic"]


@node
class Compiler(TypedElement):
    """Compiler settings: angle units, asset directories, inertia handling."""

    schema_keys: ClassVar[tuple[str, ...]] = ("compiler",)
    #: Compiler setting ``alignfree``; see the MuJoCo XML reference.
    alignfree: str | None = text()
    #: Compiler setting ``angle``; see the MuJoCo XML reference.
    angle: str | None = text()
    #: Compiler setting ``assetdir``; see the MuJoCo XML reference.
    assetdir: str | None = text()
    #: Compiler setting ``autolimits``; see the MuJoCo XML reference.
    autolimits: str | None = text()
    #: Compiler setting ``balanceinertia``; see the MuJoCo XML reference.
    balanceinertia: str | None = text()
    #: Compiler setting ``boundinertia``; see the MuJoCo XML reference.
    boundinertia: str | None = text()
    #: Compiler setting ``boundmass``; see the MuJoCo XML reference.
    boundmass: str | None = text()
    #: Compiler setting ``conflict``; see the MuJoCo XML reference.
    conflict: str | None = text()
    #: Compiler setting ``coordinate``; see the MuJoCo XML reference.
    coordinate: str | None = text()
    #: Compiler setting ``discardvisual``; see the MuJoCo XML reference.
    discardvisual: str | None = text()
    #: Compiler setting ``eulerseq``; see the MuJoCo XML reference.
    eulerseq: str | None = text()
    #: Compiler setting ``fitaabb``; see the MuJoCo XML reference.
    fitaabb: str | None = text()
    #: Compiler setting ``fusestatic``; see the MuJoCo XML reference.
    fusestatic: str | None = text()
    #: Compiler setting ``inertiafromgeom``; see the MuJoCo XML reference.
    inertiafromgeom: str | None = text()
    #: Compiler setting ``inertiagrouprange``; see the MuJoCo XML reference.
    inertiagrouprange: str | None = text()
    #: Compiler setting ``meshdir``; see the MuJoCo XML reference.
    meshdir: str | None = text()
    #: Compiler setting ``passthrough``; see the MuJoCo XML reference.
    passthrough: str | None = text()
    #: Compiler setting ``savecanonical``; see the MuJoCo XML reference.
    savecanonical: str | None = text()
    #: Compiler setting ``savecompiled``; see the MuJoCo XML reference.
    savecompiled: str | None = text()
    #: Compiler setting ``saveinertial``; see the MuJoCo XML reference.
    saveinertial: str | None = text()
    #: Compiler setting ``settotalmass``; see the MuJoCo XML reference.
    settotalmass: str | None = text()
    #: Compiler setting ``strippath``; see the MuJoCo XML reference.
    strippath: str | None = text()
    #: Compiler setting ``texturedir``; see the MuJoCo XML reference.
    texturedir: str | None = text()
    #: Compiler setting ``usethread``; see the MuJoCo XML reference.
    usethread: str | None = text()


@node
class LengthRange(TypedElement):
    """How actuator length ranges are computed."""

    schema_keys: ClassVar[tuple[str, ...]] = ("compiler/lengthrange",)
    #: Compiler setting ``accel``; see the MuJoCo XML reference.
    accel: str | None = text()
    #: Sampling interval (and phase).
    interval: str | None = text()
    #: Compiler setting ``inttotal``; see the MuJoCo XML reference.
    inttotal: str | None = text()
    #: Compiler setting ``maxforce``; see the MuJoCo XML reference.
    maxforce: str | None = text()
    #: How the element tracks its target (``fixed``, ``track``, ``trackcom``, ...).
    mode: str | None = text()
    #: Time constant(s).
    timeconst: str | None = text()
    #: Compiler setting ``timestep``; see the MuJoCo XML reference.
    timestep: str | None = text()
    #: Compiler setting ``tolrange``; see the MuJoCo XML reference.
    tolrange: str | None = text()
    #: Compiler setting ``useexisting``; see the MuJoCo XML reference.
    useexisting: str | None = text()
    #: Compiler setting ``uselimit``; see the MuJoCo XML reference.
    uselimit: str | None = text()


@node
class Option(TypedElement):
    """Simulation options: timestep, gravity, solver, integrator."""

    schema_keys: ClassVar[tuple[str, ...]] = ("option",)
    #: Simulation option ``actuatorgroupdisable``; see the MuJoCo XML reference.
    actuatorgroupdisable: Ints | None = integers()
    #: Simulation option ``ccd_iterations``; see the MuJoCo XML reference.
    ccd_iterations: int | None = integer()
    #: Simulation option ``ccd_tolerance``; see the MuJoCo XML reference.
    ccd_tolerance: float | None = number()
    #: Simulation option ``cone``; see the MuJoCo XML reference.
    cone: str | None = text()
    #: Density used to compute mass from volume.
    density: float | None = number()
    #: Simulation option ``gravity``; see the MuJoCo XML reference.
    gravity: Floats | None = vec3()
    #: Simulation option ``impratio``; see the MuJoCo XML reference.
    impratio: float | None = number()
    #: Simulation option ``integrator``; see the MuJoCo XML reference.
    integrator: str | None = text()
    #: Simulation option ``iterations``; see the MuJoCo XML reference.
    iterations: int | None = integer()
    #: Simulation option ``jacobian``; see the MuJoCo XML reference.
    jacobian: str | None = text()
    #: Simulation option ``ls_iterations``; see the MuJoCo XML reference.
    ls_iterations: int | None = integer()
    #: Simulation option ``ls_tolerance``; see the MuJoCo XML reference.
    ls_tolerance: float | None = number()
    #: Simulation option ``magnetic``; see the MuJoCo XML reference.
    magnetic: Floats | None = vec3()
    #: Simulation option ``noslip_iterations``; see the MuJoCo XML reference.
    noslip_iterations: int | None = integer()
    #: Simulation option ``noslip_tolerance``; see the MuJoCo XML reference.
    noslip_tolerance: float | None = number()
    #: Simulation option ``o_friction``; see the MuJoCo XML reference.
    o_friction: Floats | None = numbers()
    #: Simulation option ``o_margin``; see the MuJoCo XML reference.
    o_margin: float | None = number()
    #: Simulation option ``o_solimp``; see the MuJoCo XML reference.
    o_solimp: Floats | None = vec1to5()
    #: Simulation option ``o_solref``; see the MuJoCo XML reference.
    o_solref: Floats | None = vec1to2()
    #: Simulation option ``sdf_initpoints``; see the MuJoCo XML reference.
    sdf_initpoints: int | None = integer()
    #: Simulation option ``sdf_iterations``; see the MuJoCo XML reference.
    sdf_iterations: int | None = integer()
    #: Simulation option ``sleep_tolerance``; see the MuJoCo XML reference.
    sleep_tolerance: float | None = number()
    #: Simulation option ``solver``; see the MuJoCo XML reference.
    solver: str | None = text()
    #: Simulation option ``timestep``; see the MuJoCo XML reference.
    timestep: float | None = number()
    #: Simulation option ``tolerance``; see the MuJoCo XML reference.
    tolerance: float | None = number()
    #: Simulation option ``viscosity``; see the MuJoCo XML reference.
    viscosity: float | None = number()
    #: Simulation option ``wind``; see the MuJoCo XML reference.
    wind: Floats | None = vec3()


@node
class OptionFlag(TypedElement):
    """Enable or disable parts of the simulation pipeline."""

    schema_keys: ClassVar[tuple[str, ...]] = ("option/flag",)
    #: Enable or disable ``actuation`` (``enable``/``disable``).
    actuation: str | None = text()
    #: Enable or disable ``autoreset`` (``enable``/``disable``).
    autoreset: str | None = text()
    #: Enable or disable ``clampctrl`` (``enable``/``disable``).
    clampctrl: str | None = text()
    #: Enable or disable ``constraint`` (``enable``/``disable``).
    constraint: str | None = text()
    #: Enable or disable ``contact`` (``enable``/``disable``).
    contact: str | None = text()
    #: Enable or disable ``damper`` (``enable``/``disable``).
    damper: str | None = text()
    #: Enable or disable ``diagexact`` (``enable``/``disable``).
    diagexact: str | None = text()
    #: Enable or disable ``energy`` (``enable``/``disable``).
    energy: str | None = text()
    #: Whether edge equality constraints are generated.
    equality: str | None = text()
    #: Enable or disable ``eulerdamp`` (``enable``/``disable``).
    eulerdamp: str | None = text()
    #: Enable or disable ``filterparent`` (``enable``/``disable``).
    filterparent: str | None = text()
    #: Dry friction loss.
    frictionloss: str | None = text()
    #: Enable or disable ``fwdinv`` (``enable``/``disable``).
    fwdinv: str | None = text()
    #: Enable or disable ``gravity`` (``enable``/``disable``).
    gravity: str | None = text()
    #: Enable or disable ``invdiscrete`` (``enable``/``disable``).
    invdiscrete: str | None = text()
    #: Enable or disable ``ipc`` (``enable``/``disable``).
    ipc: str | None = text()
    #: Enable or disable ``island`` (``enable``/``disable``).
    island: str | None = text()
    #: Enable or disable ``limit`` (``enable``/``disable``).
    limit: str | None = text()
    #: Enable or disable ``midphase`` (``enable``/``disable``).
    midphase: str | None = text()
    #: Enable or disable ``multiccd`` (``enable``/``disable``).
    multiccd: str | None = text()
    #: Enable or disable ``nativeccd`` (``enable``/``disable``).
    nativeccd: str | None = text()
    #: Enable or disable ``override`` (``enable``/``disable``).
    override: str | None = text()
    #: Enable or disable ``refsafe`` (``enable``/``disable``).
    refsafe: str | None = text()
    #: Enable or disable ``sensor`` (``enable``/``disable``).
    sensor: str | None = text()
    #: Sleep policy of the body's tree.
    sleep: str | None = text()
    #: Enable or disable ``speculative`` (``enable``/``disable``).
    speculative: str | None = text()
    #: Enable or disable ``spring`` (``enable``/``disable``).
    spring: str | None = text()
    #: Enable or disable ``warmstart`` (``enable``/``disable``).
    warmstart: str | None = text()


@node
class Size(TypedElement):
    """Memory and array size hints."""

    schema_keys: ClassVar[tuple[str, ...]] = ("size",)
    #: Size setting ``memory``; see the MuJoCo XML reference.
    memory: str | None = text()
    #: Size setting ``nconmax``; see the MuJoCo XML reference.
    nconmax: str | None = text()
    #: Size setting ``njmax``; see the MuJoCo XML reference.
    njmax: str | None = text()
    #: Size setting ``nkey``; see the MuJoCo XML reference.
    nkey: str | None = text()
    #: Size setting ``nstack``; see the MuJoCo XML reference.
    nstack: str | None = text()
    #: Size setting ``nuser_actuator``; see the MuJoCo XML reference.
    nuser_actuator: str | None = text()
    #: Size setting ``nuser_body``; see the MuJoCo XML reference.
    nuser_body: str | None = text()
    #: Size setting ``nuser_cam``; see the MuJoCo XML reference.
    nuser_cam: str | None = text()
    #: Size setting ``nuser_geom``; see the MuJoCo XML reference.
    nuser_geom: str | None = text()
    #: Size setting ``nuser_jnt``; see the MuJoCo XML reference.
    nuser_jnt: str | None = text()
    #: Size setting ``nuser_sensor``; see the MuJoCo XML reference.
    nuser_sensor: str | None = text()
    #: Size setting ``nuser_site``; see the MuJoCo XML reference.
    nuser_site: str | None = text()
    #: Size setting ``nuser_tendon``; see the MuJoCo XML reference.
    nuser_tendon: str | None = text()
    #: Size setting ``nuserdata``; see the MuJoCo XML reference.
    nuserdata: str | None = text()


@node
class Statistic(TypedElement):
    """Model statistics that override the computed ones."""

    schema_keys: ClassVar[tuple[str, ...]] = ("statistic",)
    #: Model statistic ``center``; see the MuJoCo XML reference.
    center: Floats | None = vec3()
    #: Model statistic ``extent``; see the MuJoCo XML reference.
    extent: float | None = number()
    #: Model statistic ``meaninertia``; see the MuJoCo XML reference.
    meaninertia: float | None = number()
    #: Model statistic ``meanmass``; see the MuJoCo XML reference.
    meanmass: float | None = number()
    #: Model statistic ``meansize``; see the MuJoCo XML reference.
    meansize: float | None = number()
