"""Scaled variants without recompiling: a compiled model scaled array by array.

``scaled(model, s)`` multiplies every length of a model (and its masses, under
``mass="volume"``); compiling the result processes every mesh again, which costs
seconds for a robot with detailed meshes. :func:`scaled_model` writes the same change
into a copy of the compiled model instead: every float array is multiplied by the
factor of its unit (:data:`mjcf_model.bridge.scaled_fields.FLOAT_FIELDS`), and what
MuJoCo derives from masses, inertias and lengths together is derived again as its
compiler derives it (``mj_setConst``, the statistics of the model and the length of
each degree of freedom, ``springdamper`` joints).

:func:`mjcf_model.patched` calls it when its variant is the result of
:func:`mjcf_model.scaled` (which remembers what it scaled, :func:`remember_scaling`)
applied to the model it was given. It answers with the reason instead where the
scaled model would compile to something else than the arrays multiplied: a flex or a
plugin (derived from its scaled shape or settings), a muscle (its length range is
found by simulation), a frame offset that scaling carries across MuJoCo's tolerance
for "the same frame", an array this table does not know (a newer MuJoCo), and any
model before MuJoCo 4.0 (which derives a scaled mesh's frame anew). ``patched`` adds
per-axis factors and masses on a surface under ``mass="volume"``.

>>> from mjcf_model import compiled, loads, patched, scaled
>>> ball = loads('<mujoco><worldbody><body pos="0 0 1"><freejoint/><geom size="0.1"/>'
...              '</body></worldbody></mujoco>')
>>> big = patched(compiled(ball), ball, scaled(ball, 2, mass="volume"))
>>> big.geom_size[0].tolist(), big.body_pos[1].tolist()
([0.2, 0.0, 0.0], [0.0, 0.0, 2.0])
>>> round(float(big.body_mass[1] / compiled(ball).body_mass[1]), 9)
8.0
"""

from __future__ import annotations

import copy
import weakref
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import attrs
import numpy
import numpy.typing as npt

from mjcf_model.bridge.scaled_fields import FLOAT_FIELDS, float_fields
from mjcf_model.caching import BoundedCache, IdentityCache
from mjcf_model.nodes.base import get_attribute
from mjcf_model.nodes.root import Mujoco
from mjcf_model.values import numbers_of

if TYPE_CHECKING:
    import mujoco

__all__ = [
    "Scaling",
    "remember_scaling",
    "restore_scaled",
    "scaled_model",
    "scaling_of",
    "scratch_data",
]

#: A numpy array of any kind.
Array = npt.NDArray[Any]

#: How each model :func:`mjcf_model.scaled` made was scaled, by ``id``, while it lives
#: (a loop may make all its variants first and patch them later).
_SCALINGS: dict[int, tuple[weakref.ref[Any], Scaling]] = {}


@attrs.frozen
class Scaling:
    """How :func:`mjcf_model.scaled` made a model."""

    #: The model it scaled.
    source: object
    #: The x, y and z factors.
    factors: tuple[float, float, float]
    #: The mass policy, ``"keep"`` or ``"volume"``.
    mass: str
    #: The geoms (at most one named) whose mass grows with their area, not their volume.
    surface_masses: Sequence[str] = ()


def remember_scaling(
    result: object,
    source: object,
    factors: tuple[float, float, float],
    mass: str,
    surface_masses: Sequence[str] = (),
) -> None:
    """Note that ``result`` is ``source`` scaled by ``factors`` under the ``mass`` policy."""
    key = id(result)
    gone = _SCALINGS.pop  # the entry leaves with the model
    _SCALINGS[key] = (
        weakref.ref(result, lambda _: gone(key, None)),
        Scaling(source, factors, mass, tuple(surface_masses)),
    )


def scaling_of(model: object) -> Scaling | None:
    """How ``model`` was scaled, if :func:`mjcf_model.scaled` made it lately."""
    found = _SCALINGS.get(id(model))
    return None if found is None or found[0]() is not model else found[1]


#: MuJoCo's tolerance for an offset that leaves a frame "the same" as its body's.
_SAME_POSITION = 1e-6


def scaled_model(
    model: mujoco.MjModel,
    after: Mujoco,
    factor: float,
    mass: str,
    into: mujoco.MjModel | None,
    *,
    servos: Sequence[int] = (),
) -> mujoco.MjModel | str:
    """``model`` as ``after`` compiles, ``after`` being its source scaled by ``factor``.

    Args:
        model: The source compiled.
        after: The source scaled (its ``<statistic>`` values replace computed ones).
        factor: The one factor of every length.
        mass: The mass policy ``after`` was scaled under.
        into: A copy of ``model`` to write into (see :func:`mjcf_model.patched`).
        servos: The rows of the source's ``<position>`` actuators on a joint: on a
            slide joint, ``scaled`` takes their controls and ``ctrlrange`` for lengths.

    Returns:
        The model, ``into`` when given; or why it cannot be written array by array.

    """
    import mujoco

    problem = _problem(model, factor)
    if problem is not None:
        return problem
    # Masses (and the compiler's mass bounds and total, which scaled() scales alike).
    masses = factor**3 if mass == "volume" else 1.0
    result = copy.copy(model) if into is None else into
    targets = _targets(model, factor, servos)
    for field, multiplier in FLOAT_FIELDS.items():
        value = getattr(model, field, None)
        if value is None or multiplier is None:
            continue  # not in this MuJoCo, or derived below
        factors: float | Array | None = targets.get(field)
        if factors is None and value.size:
            factors = multiplier(model, factor, masses)
        if isinstance(factors, numpy.ndarray):
            if value.ndim == 1 and factors.ndim == 2:  # per-row factors of a one-column field
                factors = factors[:, 0]
            getattr(result, field)[...] = value * factors
        elif factors is not None and factors != 1.0:
            getattr(result, field)[...] = value * factors
        elif into is not None:  # what an earlier variant wrote there goes back
            getattr(result, field)[...] = value
    if into is not None:
        _HOLDING.add(into)
    data = scratch_data(result)
    mujoco.mj_setConst(result, data)
    _statistics(result, data)
    _written_statistics(result, after)
    return result


#: The ``MjData`` of the last few models written into (making one costs more than a patch).
_DATA: IdentityCache[Any] = IdentityCache(4)


def scratch_data(model: mujoco.MjModel) -> mujoco.MjData:
    """An ``MjData`` for ``model`` to compute in, reset to the model's state at ``qpos0``.

    The same one for a model patched again, reset (its mocap bodies too, which follow the
    model's ``body_pos``).
    """
    import mujoco

    data = _DATA.recall_for(model, lambda: mujoco.MjData(model))
    mujoco.mj_resetData(model, data)
    return data


#: The models a scaled variant was written into (:func:`restore_scaled` sets them back);
#: not a bounded cache: forgetting one would leave a scaled variant under the next.
_HOLDING: weakref.WeakSet[Any] = weakref.WeakSet()


def restore_scaled(model: mujoco.MjModel, into: mujoco.MjModel) -> None:
    """Set every array a scaled variant wrote into ``into`` back to ``model``'s, if one did."""
    if into not in _HOLDING:
        return
    _HOLDING.discard(into)
    for field in FLOAT_FIELDS:
        value = getattr(model, field, None)
        if value is not None:
            getattr(into, field)[...] = value
    into.stat.center = model.stat.center
    for name in ("extent", "meaninertia", "meanmass", "meansize"):
        setattr(into.stat, name, getattr(model.stat, name))


def _targets(model: mujoco.MjModel, factor: float, servos: Sequence[int]) -> dict[str, Array]:
    """The factors of ``key_ctrl`` and ``actuator_ctrlrange``: position servos on slide joints."""
    factors = numpy.ones(model.nu)
    for row in servos:
        joint = int(model.actuator_trnid[row, 0])
        if model.actuator_trntype[row] == 0 and model.jnt_type[joint] == 2:  # slide
            factors[row] = factor
    return {"key_ctrl": factors[None, :], "actuator_ctrlrange": factors[:, None]}


def _problem(model: mujoco.MjModel, factor: float) -> str | None:
    """Why the scaled model would not compile to ``model``'s arrays multiplied, if it would not."""
    import mujoco

    if int(mujoco.__version__.split(".")[0]) < 4:
        return "MuJoCo before 4.0 derives a scaled mesh's frame anew (compile it)"
    unknown = _UNKNOWN.recall(type(model), lambda: _unknown_fields(model))
    if unknown:
        return f"this MuJoCo has arrays scaling does not know: {', '.join(unknown)}"
    if model.nflex:
        return "flexes derive their stiffness from their scaled shape"
    if model.nplugin:
        return "a plugin computes its shape or force from its scaled settings"
    muscles = (model.actuator_gaintype == int(mujoco.mjtGain.mjGAIN_MUSCLE)) | (
        model.actuator_biastype == int(mujoco.mjtBias.mjBIAS_MUSCLE)
    )
    if numpy.any(muscles):
        return "a muscle's length range is found by simulation"
    crossing = _crossing_offsets(model, factor)
    if crossing is not None:
        return crossing
    return None


def _unknown_fields(model: mujoco.MjModel) -> list[str]:
    """The float arrays of this MuJoCo's ``MjModel`` that the table does not classify."""
    return [field for field in float_fields(model) if field not in FLOAT_FIELDS]


#: :func:`_unknown_fields`, once per ``MjModel`` class (one per MuJoCo in a process).
_UNKNOWN: BoundedCache[type, list[str]] = BoundedCache(4)


def _crossing_offsets(model: mujoco.MjModel, factor: float) -> str | None:
    """A frame offset that scaling carries across MuJoCo's tolerance for the same frame."""
    low, high = sorted((_SAME_POSITION, _SAME_POSITION / factor))
    low, high = 0.99 * low, 1.01 * high
    ipos = numpy.asarray(model.body_ipos)
    offsets: list[tuple[str, Array]] = [("body", ipos), ("joint", model.jnt_pos)]
    for kind in ("geom", "site"):
        position = numpy.asarray(getattr(model, f"{kind}_pos"))
        offsets.append((kind, position))
        offsets.append((kind, position - ipos[getattr(model, f"{kind}_bodyid")]))
    for kind, offset in offsets:
        if not offset.size:
            continue
        largest = numpy.max(numpy.abs(offset), axis=1)
        crossing = numpy.flatnonzero((largest >= low) & (largest <= high))
        if crossing.size:
            row = int(crossing[0])
            return (
                f"scaling carries an offset of {kind} {row} ({largest[row]:g}) across MuJoCo's"
                f" {_SAME_POSITION:g} tolerance for a frame that is its body's"
            )
    return None


def _statistics(model: mujoco.MjModel, data: mujoco.MjData) -> None:
    """The ``stat`` centre, extent and mean size and each ``dof_length``, as MuJoCo computes them.

    MuJoCo 4.0's compiler measures them at ``qpos0`` (``setStat``): the box around
    bodies, inertial frames, joint anchors, sites and geoms (a geom by its bounding
    radius; a plane or height field by a tenth of its size); each body's size, the
    longest reach from its centre of mass to its joints and its children's joints and
    to its geoms' bounding spheres, at least ``1e-5``; their mean; a rotational degree
    of freedom's length is its body's size.
    """
    import mujoco

    mujoco.mj_resetData(model, data)  # mj_setConst leaves the springs' pose
    mujoco.mj_kinematics(model, data)
    points = [data.xpos[1:], data.xipos[1:], data.xanchor, data.site_xpos]
    radius = numpy.asarray(model.geom_rbound, dtype=float).copy()
    size = numpy.asarray(model.geom_size)
    planes = (model.geom_type == int(mujoco.mjtGeom.mjGEOM_PLANE)) & (radius <= 0)
    finite = numpy.maximum(size[:, 0], size[:, 1])
    radius[planes] = numpy.where(finite[planes] != 0, finite[planes] * 0.1, 1.0)
    fields = (model.geom_type == int(mujoco.mjtGeom.mjGEOM_HFIELD)) & (radius <= 0)
    if numpy.any(fields):
        hfield = numpy.max(numpy.asarray(model.hfield_size), axis=1) * 0.1
        radius[fields] = hfield[model.geom_dataid[fields]]
    lows = [numpy.min(p, axis=0) for p in points if len(p)]
    highs = [numpy.max(p, axis=0) for p in points if len(p)]
    if model.ngeom:
        lows.append(numpy.min(data.geom_xpos - radius[:, None], axis=0))
        highs.append(numpy.max(data.geom_xpos + radius[:, None], axis=0))
    low = numpy.min([numpy.full(3, 1e10), *lows], axis=0)
    high = numpy.max([numpy.full(3, -1e10), *highs], axis=0)
    model.stat.center = (low + high) * 0.5
    if high[0] > low[0]:
        model.stat.extent = max(1e-5, float(numpy.max(high - low)))
    body = numpy.zeros(model.nbody)
    xipos = data.xipos
    for joint in range(model.njnt):
        anchor = data.xanchor[joint]
        owner = int(model.jnt_bodyid[joint])
        for which in (owner, int(model.body_parentid[owner])):
            body[which] = max(body[which], float(numpy.linalg.norm(xipos[which] - anchor)))
    body[0] = 0
    reach = numpy.linalg.norm(data.geom_xpos - xipos[model.geom_bodyid], axis=1)
    for geom in numpy.flatnonzero(model.geom_rbound > 0):
        owner = int(model.geom_bodyid[geom])
        if owner > 0:
            body[owner] = max(body[owner], float(model.geom_rbound[geom] + reach[geom]))
    if model.nbody > 1:
        body[1:] = numpy.maximum(body[1:], 1e-5)
        meansize = 0.0
        for value in body[1:]:
            meansize += float(value) / (model.nbody - 1)
        model.stat.meansize = meansize
    if model.nv:
        rotational = _rotational_dofs(model)
        model.dof_length[:] = numpy.where(rotational, body[model.dof_bodyid], 1.0)
    model.stat.extent = max(float(model.stat.extent), 2 * float(model.stat.meansize))
    if model.nbody > 1:
        total = 0.0
        for value in model.body_mass[1:]:
            total += float(value)
        model.stat.meanmass = total / (model.nbody - 1)
    if model.nv:
        total = 0.0
        for value in model.dof_M0:
            total += float(value)
        model.stat.meaninertia = total / model.nv


def _rotational_dofs(model: mujoco.MjModel) -> Array:
    """Which degrees of freedom turn: ball and hinge joints', and a free joint's last three."""
    kinds = model.jnt_type[model.dof_jntid]
    offset = numpy.arange(model.nv) - model.jnt_dofadr[model.dof_jntid]
    return numpy.asarray((kinds == 1) | (kinds == 3) | ((kinds == 0) & (offset >= 3)))


#: The ``<statistic>`` attributes that replace what MuJoCo computes, as ``stat`` names them.
_WRITTEN = ("extent", "meaninertia", "meanmass", "meansize", "center")


def _written_statistics(model: mujoco.MjModel, after: Mujoco) -> None:
    """The ``<statistic>`` values ``after`` writes, over what was computed."""
    for section in after.elements:
        if section.tag != "statistic":
            continue
        for name in _WRITTEN:
            numbers = numbers_of(get_attribute(section, name))
            if numbers is None:
                continue
            if name == "center":
                model.stat.center = numbers
            else:
                setattr(model.stat, name, numbers[0])
