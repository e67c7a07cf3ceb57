"""Scaling a model: every length multiplied, angles and unitless values untouched.

:func:`scaled` walks the tree once and asks the rule of each element's schema key
(:data:`mjcf_model.transforms.scaling.rules.RULES`) which attributes change. Every key of the
namespace table has a rule, even if it is "no lengths", so an element type MuJoCo
adds fails a test until someone decides how it scales.

Uniform scaling is exact: MuJoCo compiles the result to a model whose body, geom,
site, joint, camera and light positions, geom and site sizes, mesh vertices,
slide-joint ranges and the torsional and rolling friction of geoms, flexes and
contact pairs are the original's times the factor. Where MuJoCo's built-in
default is a non-zero length (site size, camera ``ipd``, light ``bulbradius`` and
``range``, tendon ``width``, mesh ``scale``, torsional and rolling friction) and
nothing in the model sets it, the scaled value is written out (friction once, in
the main default class, or on a flex's ``<contact>``:
:mod:`mjcf_model.transforms.scaling.friction`). Three per-axis factors follow
robosuite's conventions and are an approximation (see :func:`scaled`).

>>> from mjcf_model import Body, Geom, Joint
>>> arm = Body(pos=[0, 0, 1], children=[Geom(type="capsule", size=[0.05, 0.2]),
...                                     Joint(type="slide", range=[0, 0.1])])
>>> big = scaled(arm, 2)
>>> big.pos, big.geoms[0].size, big.joints[0].range
((0.0, 0.0, 2.0), (0.1, 0.4), (0.0, 0.2))
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Literal

import numpy as np
import numpy.typing as npt

from mjcf_model.bridge.scale_patching import remember_scaling
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, get_attribute, with_attributes
from mjcf_model.serializers.skins import inline_skin_files
from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.friction import (
    FLEX_KEYS,
    with_flex_contact,
    with_friction_defaults,
)
from mjcf_model.transforms.scaling.pieces import NO_LENGTHS
from mjcf_model.transforms.scaling.plugins import SDF_SETTINGS_KEYS, with_sdf_settings
from mjcf_model.transforms.scaling.rules import RULES
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.traversal import (
    GUESS,
    SKIN_KEYS,
    map_elements,
    refuse_file_skin,
    refuse_opaque,
)

__all__ = ["MassPolicy", "scaled", "three_factors"]

#: ``"keep"``: every body keeps its mass (written masses stay; geoms weighed by
#: density get the density that keeps their mass) and inertias scale with length
#: squared; ``"volume"``: written masses scale with the volume, masses MuJoCo
#: computes from density follow the geometry (volume, or area for shell inertia),
#: and inertias scale with mass times length squared.
MassPolicy = Literal["keep", "volume"]


def three_factors(factor: npt.ArrayLike) -> tuple[float, float, float]:
    """One factor for all three axes, or three: finite and positive (the one place they are read).

    Examples:
        >>> three_factors(2), three_factors([1, 2, 3])
        ((2.0, 2.0, 2.0), (1.0, 2.0, 3.0))

    """
    values = np.asarray(factor, dtype=float).ravel()
    if values.size == 1:
        values = np.repeat(values, 3)
    if values.size != 3:
        raise MjcfValueError(f"the scale factor is a number or three numbers, found {factor!r}")
    if not all(math.isfinite(v) and v > 0 for v in values):
        raise MjcfValueError(
            f"scale factors must be finite and positive (mirroring is not a scaling), "
            f"found {factor!r}"
        )
    return (float(values[0]), float(values[1]), float(values[2]))


def scaled(node: AnyElement, factor: npt.ArrayLike, *, mass: MassPolicy = "keep") -> AnyElement:
    """A copy of ``node`` with every length multiplied by ``factor``.

    Lengths are positions (bodies, frames, geoms, sites, joints, cameras, lights,
    inertials, equality anchors, keyframe mocap positions and the length parts of
    keyframe ``qpos``/``qvel``), geom and site sizes (by type), ``fromto``, mesh
    ``scale``, height field ``size``, slide-joint ranges and references, spatial tendon
    lengths and widths, fixed tendon lengths when a slide joint is in them (and then
    their hinges' ``coef``, a lever arm), the ``polycoef`` of joint and tendon couplings
    whose coordinates are lengths (:mod:`mjcf_model.transforms.scaling.couplings`),
    contact margins and gaps, the friction of geoms, flexes and contact pairs but for
    its sliding values (torsional and rolling coefficients are lengths in MuJoCo; values
    MuJoCo fills from its built-in defaults are written, scaled), position actuators'
    ``ctrlrange`` on slide joints (a class's range is written on the actuator, scaled,
    as the class may serve hinges too), crank lengths, and the same attributes in
    default classes. A ``flexcomp``'s points scale once, through ``scale`` for the ``direct``,
    ``mesh`` and ``gmsh`` types and through ``spacing`` for the generated ones; a mesh
    made by an SDF plugin scales through the plugin's length settings
    (:mod:`mjcf_model.transforms.scaling.plugins`).

    Args:
        node: A model (``Mujoco``) or any element of one. Default classes are
            taken into account only for a whole model: in a part of one, an
            element that leaves a length with a non-zero built-in default
            unwritten (a site's size, a geom's rolling friction) gets MuJoCo's
            default written on it, scaled, as if no class set it.
        factor: One positive number, or three (x, y, z). Per-axis scaling follows
            robosuite: points scale per axis; a size of three values per axis,
            of two (cylinder, capsule) by the mean of x and y then by z, of one
            (sphere, ``fromto`` radius) by the mean of all three, like other
            lengths without a direction; slide ranges by the length of the
            scaled joint axis. It is an approximation wherever a frame is
            rotated relative to its parent, and for inertias; and because of the
            mean, per-axis scalings do not compose exactly (uniform ones do).
        mass: The mass policy (see :data:`MassPolicy`).

    Raises:
        MjcfValueError: for a factor that is not positive, a kept ``<include>``, an
            ``<attach>`` (the attached model is another file: scale it first), a
            mesh or geom made by a plugin other than MuJoCo's torus, bowl and gear
            SDFs, or a skin read from a ``.skn`` file in a model that does not know
            its folder (a loaded model has its skin files written inline first;
            otherwise call ``mjcf_model.serializers.skins.inline_skin_files(model, folder)``).

    Examples:
        >>> from mjcf_model import Inertial
        >>> scaled(Inertial(pos=[1, 0, 0], mass=2.0, diaginertia=[1, 1, 1]), 2, mass="volume")
        Inertial(pos=(2.0, 0.0, 0.0), diaginertia=(32.0, 32.0, 32.0), mass=16.0)

    """
    factors = three_factors(factor)
    if mass not in ("keep", "volume"):
        raise MjcfValueError(f"mass policy is 'keep' or 'volume', found {mass!r}")
    if factors == (1.0, 1.0, 1.0):
        return node

    source = node
    node = inline_skin_files(node)  # a skin file's vertices and bind poses are lengths
    classes = DefaultClasses.of(node)
    context = ScaleContext(factors=factors, mass=mass, classes=classes, model=node)

    def visit(element: AnyElement, key: str | None, ancestors: Sequence[AnyElement]) -> AnyElement:
        if key is None or key == "include":
            refuse_opaque(element, key, "scale")
            return element
        if key == "body/attach":
            raise MjcfValueError(
                "cannot scale an <attach>: the attached model is a separate file; "
                "scale that model and attach the result"
            )
        if key in SKIN_KEYS and get_attribute(element, "file"):
            refuse_file_skin(element, "scale", "holds its vertices and bind poses")
        changed = with_attributes(element, RULES[key](element, ancestors, context))
        if key in SDF_SETTINGS_KEYS:
            return with_sdf_settings(changed, key, ancestors, context)
        if key in FLEX_KEYS:
            return with_flex_contact(changed, context)
        if key == "mujoco":
            return with_friction_defaults(changed, context)
        return changed

    result = map_elements(visit, node, GUESS, kept=_UNSCALED)
    remember_scaling(
        result, source, factors, mass, context.surface_masses[:1]
    )  # patched() writes it into compiled arrays
    return result


#: The keys of elements that never change, when they have no children.
_UNSCALED = frozenset(
    key for key, rule in RULES.items() if rule is NO_LENGTHS and key not in SDF_SETTINGS_KEYS
) - {"include", "body/attach"}
