"""How every float array of a compiled ``MjModel`` changes when a model is scaled by ``s``.

:data:`FLOAT_FIELDS` classifies each field, for a uniform factor ``s`` and the
mass factor ``m`` of the ``mass=`` policy (``"keep"``: 1; ``"volume"``: ``s**3``
for solids), as one kind: a length (``s``), a mass (``m``), an inertia
(``m * s**2``), unchanged (angles, quaternions, unitless ratios, colours, solver
parameters, forces, times, user data), mixed (rows or columns of different
kinds, worked out from the original model's joint, tendon, actuator and
equality types), or derived (computed by MuJoCo from masses, inertias and
armatures together, such as ``dof_invweight0``, which :func:`mjcf_model.patched`
has MuJoCo derive again after writing the others).

:func:`mjcf_model.patched` writes a scaled variant into a compiled model with it
(:mod:`mjcf_model.bridge.scale_patching`); the tests check ``scaled`` against it and
both against MuJoCo compiling the scaled model.

Units follow MuJoCo's ``mjmodel.h`` comments and XML reference. Time is never
scaled, so velocities of lengths (``key_qvel`` of slide joints) are lengths too.
What ``scaled`` leaves alone by decision although it has a length in its unit
is listed as unchanged with the reason, in :data:`UNSCALED_BY_DECISION`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import Any

import numpy as np
import numpy.typing as npt

__all__ = ["DERIVED", "FLOAT_FIELDS", "UNSCALED_BY_DECISION", "Multiplier", "float_fields"]

#: A numpy array of any kind.
Array = npt.NDArray[Any]

#: The factor a field is multiplied by: from the original model, ``s`` and ``m``;
#: a number, or an array broadcasting over the field (rows, or rows by columns).
Multiplier = Callable[[Any, float, float], "float | Array"]

# MuJoCo's enum values (``mjtJoint``, ``mjtWrap``...), stable across its releases and
# checked against them in the tests: reading this table does not import MuJoCo.
_FREE, _SLIDE = 0, 2
_WRAP_JOINT = 1
_TRN_JOINT, _TRN_JOINTINPARENT, _TRN_TENDON, _TRN_SITE = 0, 1, 3, 4
_GAIN_FIXED, _BIAS_AFFINE, _DYN_FILTER = 0, 1, 2
_EQ_CONNECT, _EQ_WELD, _EQ_JOINT, _EQ_TENDON = 0, 1, 2, 3
_OBJ_SITE = 6
#: MuJoCo's ``mjMAXVAL``: the size of an infinite plane's bounding box.
_MAXVAL = 1e10


def _length(model: Any, s: float, m: float) -> float:
    return s


def _unchanged(model: Any, s: float, m: float) -> float:
    return 1.0


def _mass(model: Any, s: float, m: float) -> float:
    return m


def _inertia(model: Any, s: float, m: float) -> float:
    return m * s * s


def _columns(*factors: str) -> Multiplier:
    """Columns of different kinds: ``"1"`` unchanged, ``"s"`` a length."""

    def multiplier(model: Any, s: float, m: float) -> Array:
        return np.array([s if f == "s" else 1.0 for f in factors])

    return multiplier


def _joint_factors(model: Any, s: float) -> Array:
    """Per joint: ``s`` for a slide joint (its coordinate is a length), else 1."""
    return np.where(model.jnt_type == _SLIDE, s, 1.0)


def _per_joint(model: Any, s: float, m: float) -> Array:
    return _joint_factors(model, s)[:, None]


def _coordinates(model: Any, s: float, velocity: bool) -> Array:
    """Per ``qpos`` (or ``qvel``) entry: ``s`` for slide joints and free positions, else 1."""
    factors = np.ones(model.nv if velocity else model.nq)
    addresses = model.jnt_dofadr if velocity else model.jnt_qposadr
    for kind, start in zip(model.jnt_type, addresses, strict=True):
        if kind == _SLIDE:
            factors[start] = s
        elif kind == _FREE:
            factors[start : start + 3] = s
    return factors


def _qpos(model: Any, s: float, m: float) -> Array:
    return _coordinates(model, s, velocity=False)


def _qvel(model: Any, s: float, m: float) -> Array:
    return _coordinates(model, s, velocity=True)


def tendon_factors(model: Any, s: float) -> Array:
    """Per tendon: ``s`` for a spatial tendon and a fixed one over a slide joint, else 1.

    A fixed tendon's length ``sum(coef * q)`` over hinges alone is an angle; with a
    slide joint in it, it is a length (a hinge's ``coef`` is then a lever arm).
    """
    factors = np.ones(model.ntendon)
    for tendon, (start, count) in enumerate(zip(model.tendon_adr, model.tendon_num, strict=True)):
        kinds, ids = model.wrap_type[start : start + count], model.wrap_objid[start : start + count]
        spatial = np.any(kinds != _WRAP_JOINT)
        if spatial or np.any(model.jnt_type[ids] == _SLIDE):
            factors[tendon] = s
    return factors


def _wrap_parameters(model: Any, s: float, m: float) -> Array:
    """A fixed tendon's ``coef``: the tendon's length per unit of its joint's coordinate.

    The other wrap parameters (pulley divisors, side sites) are unitless or ids.
    """
    factors = np.ones(model.nwrap)
    joints, tendons = _joint_factors(model, s), tendon_factors(model, s)
    for tendon, (start, count) in enumerate(zip(model.tendon_adr, model.tendon_num, strict=True)):
        for wrap in range(start, start + count):
            if model.wrap_type[wrap] == _WRAP_JOINT:
                factors[wrap] = tendons[tendon] / joints[model.wrap_objid[wrap]]
    return factors


def _per_tendon(model: Any, s: float, m: float) -> Array:
    return tendon_factors(model, s)[:, None]


def _spatial_tendons(model: Any, s: float, m: float) -> Array:
    """Widths: spatial tendons only (a fixed tendon is not drawn)."""
    spatial = [
        np.any(model.wrap_type[a : a + n] != _WRAP_JOINT)
        for a, n in zip(model.tendon_adr, model.tendon_num, strict=True)
    ]
    return np.where(np.array(spatial, dtype=bool), s, 1.0)[:, None]


def _mixed_site_gears(model: Any) -> Array:
    """Per actuator: a site transmission with a refsite whose gear has both parts."""
    gear = np.asarray(model.actuator_gear)
    return np.asarray(
        (model.actuator_trntype == _TRN_SITE)
        & (model.actuator_trnid[:, 1] >= 0)
        & np.any(gear[:, :3] != 0, axis=1)
        & np.any(gear[:, 3:] != 0, axis=1)
    )


def _actuator_gear(model: Any, s: float, m: float) -> Array:
    """Ratios, but for the rotational part of a mixed site gear: a lever arm (times s)."""
    factors = np.ones(np.shape(model.actuator_gear))
    factors[_mixed_site_gears(model), 3:] = s
    return factors


def _transmission_factors(model: Any, s: float) -> Array:
    """Per actuator: the factor of its length (slide joint, tendon, site or crank)."""
    joints, tendons = _joint_factors(model, s), tendon_factors(model, s)
    factors = np.ones(model.nu)
    for actuator, (kind, target) in enumerate(
        zip(model.actuator_trntype, model.actuator_trnid[:, 0], strict=True)
    ):
        if kind in (_TRN_JOINT, _TRN_JOINTINPARENT):
            factors[actuator] = joints[target]
        elif kind == _TRN_TENDON:
            factors[actuator] = tendons[target]
        elif kind == _TRN_SITE and not np.any(model.actuator_gear[actuator, :3]):
            factors[actuator] = 1.0  # a purely rotational gear measures an angle
        else:  # site, slider-crank, body: lengths in space (a mixed site gear: a length)
            factors[actuator] = s
    return factors


def _actuator_lengths(model: Any, s: float, m: float) -> Array:
    return _transmission_factors(model, s)[:, None]


def _position_servos(model: Any) -> Array:
    """Which actuators are ``<position>`` servos on a joint: ``bias = -kp * length``."""
    return np.asarray(
        (model.actuator_trntype == _TRN_JOINT)
        & (model.actuator_gaintype == _GAIN_FIXED)
        & (model.actuator_biastype == _BIAS_AFFINE)
        & (model.actuator_gainprm[:, 0] != 0)
        & (model.actuator_biasprm[:, 1] == -model.actuator_gainprm[:, 0])
    )


def _targets(model: Any, s: float) -> Array:
    """Per actuator: the factor of its control, a length for a position servo on a slide joint."""
    return np.where(_position_servos(model), _transmission_factors(model, s), 1.0)


def _ctrlrange(model: Any, s: float, m: float) -> Array:
    return _targets(model, s)[:, None]


def _key_ctrl(model: Any, s: float, m: float) -> Array:
    return _targets(model, s)[None, :]


def _cylinder_gains(model: Any, s: float, m: float) -> Array:
    """A ``<cylinder>``'s gain is its area.

    A cylinder compiles to filter dynamics, a fixed gain (the area) and an affine
    bias of pressure alone (``bias[1:3]`` zero); a ``<general>`` written the same
    way is taken for one.
    """
    cylinder = (
        (model.actuator_dyntype == _DYN_FILTER)
        & (model.actuator_gaintype == _GAIN_FIXED)
        & (model.actuator_biastype == _BIAS_AFFINE)
        & np.all(model.actuator_biasprm[:, 1:3] == 0, axis=1)
    )
    factors = np.ones(model.actuator_gainprm.shape)
    factors[cylinder, 0] = s * s
    return factors


def _equality_data(model: Any, s: float, m: float) -> Array:
    """Anchors and relative poses of connect and weld; joint and tendon polynomials.

    A connect's data are its anchor and the other body's; a weld's its anchor and
    its relative position, then a quaternion and a torque scale. Between sites,
    MuJoCo refuses an anchor or a relative pose and reads neither: their slots keep
    its built-in data (``0 1 0 ...``), which stay. A joint or tendon coupling
    ``y1 = a0 + a1 y2 + ... + a4 y2**4`` has ``a_k`` in units of ``y1 / y2**k``.
    """
    factors = np.ones(model.eq_data.shape)
    joints, tendons = _joint_factors(model, s), tendon_factors(model, s)
    for row, (kind, first, second) in enumerate(
        zip(model.eq_type, model.eq_obj1id, model.eq_obj2id, strict=True)
    ):
        if kind in (_EQ_CONNECT, _EQ_WELD):
            if model.eq_objtype[row] != _OBJ_SITE:
                factors[row, :6] = s
        elif kind in (_EQ_JOINT, _EQ_TENDON):
            of = joints if kind == _EQ_JOINT else tendons
            if second < 0:  # the object is held at a0; MuJoCo keeps the rest as written
                factors[row, 0] = of[first]
            else:
                factors[row, :5] = of[first] / of[second] ** np.arange(5)
    return factors


def _intrinsics(model: Any, s: float, m: float) -> Array:
    """Focal length and principal point: lengths where a sensor size makes MuJoCo use them."""
    return np.where(np.any(model.cam_sensorsize != 0, axis=1), s, 1.0)[:, None]


def _geom_boxes(model: Any, s: float, m: float) -> Array:
    """Bounding boxes (centre, half sizes); an infinite plane's stay at MuJoCo's infinity."""
    return np.where(np.abs(model.geom_aabb) >= _MAXVAL / 2, 1.0, s)


def _fluid(model: Any, s: float, m: float) -> Array:
    """Ellipsoid fluid model: flag and five coefficients, then added mass and inertia.

    MuJoCo computes the last six from the geom's semi-axes alone (volume-like
    ``s**3`` and ``s**5``), whatever the mass policy.
    """
    return np.array([1.0] * 6 + [s**3] * 3 + [s**5] * 3)


#: Marks a field MuJoCo derives from masses, inertias and armatures together.
DERIVED: None = None

#: The kind of every float array of ``MjModel`` (MuJoCo 3.9 and 4.0), as a multiplier.
FLOAT_FIELDS: Mapping[str, Multiplier | None] = MappingProxyType(
    {
        # actuators
        "actuator_acc0": DERIVED,
        "actuator_actrange": _unchanged,
        "actuator_armature": _unchanged,
        "actuator_biasprm": _unchanged,
        "actuator_ctrlrange": _ctrlrange,
        "actuator_cranklength": _length,
        "actuator_damping": _unchanged,
        "actuator_dampingpoly": _unchanged,
        "actuator_delay": _unchanged,
        "actuator_dynprm": _unchanged,
        "actuator_forcerange": _unchanged,
        "actuator_gainprm": _cylinder_gains,
        "actuator_gear": _actuator_gear,
        "actuator_length0": _actuator_lengths,
        "actuator_lengthrange": _actuator_lengths,
        "actuator_user": _unchanged,
        # bodies
        "body_gravcomp": _unchanged,
        "body_inertia": _inertia,
        "body_invweight0": DERIVED,
        "body_ipos": _length,
        "body_iquat": _unchanged,
        "body_margin": _length,
        "body_mass": _mass,
        "body_pos": _length,
        "body_quat": _unchanged,
        "body_subtreemass": _mass,
        "body_user": _unchanged,
        # bounding volumes
        "bvh_aabb": _length,
        "oct_aabb": _length,
        "oct_coeff": _length,
        # cameras
        "cam_fovy": _unchanged,
        "cam_intrinsic": _intrinsics,
        "cam_ipd": _length,
        "cam_mat0": _unchanged,
        "cam_pos": _length,
        "cam_pos0": _length,
        "cam_poscom0": _length,
        "cam_quat": _unchanged,
        "cam_sensorsize": _length,
        "cam_user": _unchanged,
        # degrees of freedom
        "dof_M0": DERIVED,
        "dof_armature": _unchanged,
        "dof_damping": _unchanged,
        "dof_dampingpoly": _unchanged,
        "dof_frictionloss": _unchanged,
        "dof_invweight0": DERIVED,
        "dof_length": DERIVED,
        "dof_solimp": _unchanged,
        "dof_solref": _unchanged,
        "efm0_L": DERIVED,
        # equality constraints
        "eq_data": _equality_data,
        "eq_solimp": _unchanged,
        "eq_solref": _unchanged,
        # flexes
        "flex_bending": DERIVED,
        "flex_damping": _unchanged,
        "flex_edgedamping": _unchanged,
        "flex_edgestiffness": _unchanged,
        "flex_friction": _columns("1", "s", "s"),
        "flex_gap": _length,
        "flex_margin": _length,
        "flex_node": _length,
        "flex_node0": _length,
        "flex_radius": _length,
        "flex_rgba": _unchanged,
        "flex_size": _length,
        "flex_solimp": _unchanged,
        "flex_solmix": _unchanged,
        "flex_solref": _unchanged,
        "flex_stiffness": DERIVED,
        "flex_texcoord": _unchanged,
        "flex_vert": _length,
        "flex_vert0": _unchanged,
        "flex_vertmetric": DERIVED,  # MuJoCo 3.9: metrics derived from the vertices
        "flex_yield": _unchanged,
        "flexedge_invweight0": DERIVED,
        "flexedge_length0": _length,
        # geoms
        "geom_aabb": _geom_boxes,
        "geom_adhesion": _unchanged,
        "geom_fluid": _fluid,
        "geom_friction": _columns("1", "s", "s"),
        "geom_gap": _length,
        "geom_margin": _length,
        "geom_pos": _length,
        "geom_quat": _unchanged,
        "geom_rbound": _length,
        "geom_rgba": _unchanged,
        "geom_size": _length,
        "geom_solimp": _unchanged,
        "geom_solmix": _unchanged,
        "geom_solref": _unchanged,
        "geom_surfacevel": _unchanged,
        "geom_user": _unchanged,
        # height fields, meshes, skins, materials
        "hfield_data": _unchanged,
        "hfield_size": _length,
        "mat_emission": _unchanged,
        "mat_metallic": _unchanged,
        "mat_reflectance": _unchanged,
        "mat_rgba": _unchanged,
        "mat_roughness": _unchanged,
        "mat_shininess": _unchanged,
        "mat_specular": _unchanged,
        "mat_texrepeat": _unchanged,
        "mesh_normal": _unchanged,
        "mesh_polynormal": _unchanged,
        "mesh_pos": _length,
        "mesh_quat": _unchanged,
        "mesh_scale": _length,
        "mesh_texcoord": _unchanged,
        "mesh_vert": _length,
        "skin_bonebindpos": _length,
        "skin_bonebindquat": _unchanged,
        "skin_bonevertweight": _unchanged,
        "skin_inflate": _length,
        "skin_rgba": _unchanged,
        "skin_texcoord": _unchanged,
        "skin_vert": _length,
        # joints
        "jnt_actfrcrange": _unchanged,
        "jnt_axis": _unchanged,
        "jnt_margin": _per_joint,
        "jnt_pos": _length,
        "jnt_range": _per_joint,
        "jnt_solimp": _unchanged,
        "jnt_solref": _unchanged,
        "jnt_springyield": _unchanged,
        "jnt_stiffness": _unchanged,
        "jnt_stiffnesspoly": _unchanged,
        "jnt_user": _unchanged,
        "qpos0": _qpos,
        "qpos_spring": _qpos,
        # keyframes
        "key_act": _unchanged,
        "key_ctrl": _key_ctrl,
        "key_mpos": _length,
        "key_mquat": _unchanged,
        "key_plastic": _unchanged,
        "key_qpos": lambda model, s, m: _qpos(model, s, m)[None, :],
        "key_qvel": lambda model, s, m: _qvel(model, s, m)[None, :],
        "key_time": _unchanged,
        # lights
        "light_ambient": _unchanged,
        "light_attenuation": _unchanged,
        "light_bulbradius": _length,
        "light_cutoff": _unchanged,
        "light_diffuse": _unchanged,
        "light_dir": _unchanged,
        "light_dir0": _unchanged,
        "light_exponent": _unchanged,
        "light_intensity": _unchanged,
        "light_pos": _length,
        "light_pos0": _length,
        "light_poscom0": _length,
        "light_range": _length,
        "light_softness": _unchanged,
        "light_specular": _unchanged,
        # custom data
        "numeric_data": _unchanged,
        "tuple_objprm": _unchanged,
        # contact pairs
        "pair_adhesion": _unchanged,
        "pair_friction": _columns("1", "1", "s", "s", "s"),
        "pair_gap": _length,
        "pair_margin": _length,
        "pair_solimp": _unchanged,
        "pair_solref": _unchanged,
        "pair_solreffriction": _unchanged,
        # sensors
        "sensor_cutoff": _unchanged,
        "sensor_delay": _unchanged,
        "sensor_interval": _unchanged,
        "sensor_noise": _unchanged,
        "sensor_user": _unchanged,
        # sites
        "site_pos": _length,
        "site_quat": _unchanged,
        "site_rgba": _unchanged,
        "site_size": _length,
        "site_user": _unchanged,
        # tendons
        "tendon_actfrcrange": _unchanged,
        "tendon_armature": _unchanged,
        "tendon_damping": _unchanged,
        "tendon_dampingpoly": _unchanged,
        "tendon_frictionloss": _unchanged,
        "tendon_invweight0": DERIVED,
        "tendon_length0": _per_tendon,
        "tendon_lengthspring": _per_tendon,
        "tendon_margin": _per_tendon,
        "tendon_range": _per_tendon,
        "tendon_rgba": _unchanged,
        "tendon_solimp_fri": _unchanged,
        "tendon_solimp_lim": _unchanged,
        "tendon_solref_fri": _unchanged,
        "tendon_solref_lim": _unchanged,
        "tendon_springyield": _unchanged,
        "tendon_stiffness": _unchanged,
        "tendon_stiffnesspoly": _unchanged,
        "tendon_user": _unchanged,
        "tendon_width": _spatial_tendons,
        "wrap_prm": _wrap_parameters,
    }
)

#: Fields whose unit has a length in it that ``scaled`` leaves alone on purpose.
UNSCALED_BY_DECISION: Mapping[str, str] = MappingProxyType(
    {
        "geom_solimp": "the impedance width is a distance, but solver settings stay",
        "light_attenuation": "rendering falloff per length; lights keep their look",
        "mat_texrepeat": "repeats per length with texuniform; materials stay",
        "sensor_cutoff": "in the sensor's units, a length for position sensors",
        "jnt_stiffness": "force per length on slide joints; forces are not scaled",
    }
)


def float_fields(model: Any) -> tuple[str, ...]:
    """The names of the float arrays of a compiled ``MjModel``, in a stable order."""
    return tuple(
        name
        for name in sorted(dir(model))
        if not name.startswith("_")
        and isinstance(value := getattr(model, name, None), np.ndarray)
        and value.dtype.kind == "f"
    )
