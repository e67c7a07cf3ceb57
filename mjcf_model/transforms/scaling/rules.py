"""The scaling rule of every schema key, built from :mod:`mjcf_model.transforms.scaling.pieces`.

>>> from mjcf_model import Site
>>> from mjcf_model.transforms.scaling.context import ScaleContext
>>> RULES["body/site"](Site(pos=[1, 0, 0]), (), ScaleContext(factors=(2.0, 2.0, 2.0)))
{'pos': (2.0, 0.0, 0.0), 'size': (0.01, 0.01, 0.01)}
"""

from __future__ import annotations

import functools
from collections.abc import Mapping, Sequence
from types import MappingProxyType

import numpy as np

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.transforms.scaling.context import ScaleContext, times
from mjcf_model.transforms.scaling.couplings import (
    fixed_tendon,
    joint_coupling,
    slide_factor,
    spatial_tendon,
    tendon_coefficient,
    tendon_coupling,
)
from mjcf_model.transforms.scaling.friction import friction_rule
from mjcf_model.transforms.scaling.mass import geom_density
from mjcf_model.transforms.scaling.pieces import (
    NO_LENGTHS,
    BuiltinRule,
    Changes,
    Rule,
    ValueRule,
    builtin_default,
    combine,
    inertias,
    lengths,
    masses,
    points,
    principal_inertias,
)
from mjcf_model.transforms.scaling.plugins import makes_sdf, sdf_config, sdf_mesh_scale
from mjcf_model.tree.queries import attribute_values
from mjcf_model.tree.traversal import keyed_walk
from mjcf_model.values import Value, format_value, numbers_of

__all__ = ["RULES", "UNSCALED_BY_DECISION"]

#: Elements with a length-sounding attribute that are deliberately left alone, and why.
UNSCALED_BY_DECISION: Mapping[str, str] = MappingProxyType(
    {
        "default/tendon": "shared by spatial and fixed tendons; each tendon writes its own "
        "scaled lengths instead",
        "custom/numeric": "size is a count of values, not a length",
    }
)


def _mean(element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext) -> float:
    return context.mean


def _per_axis(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> tuple[float, float, float]:
    return context.factors


def _builtin_length(attribute: str, tag: str) -> Rule:
    """A length MuJoCo gives a non-zero default (camera ``ipd``, light ``bulbradius``)."""
    return BuiltinRule(attribute, tag, functools.partial(builtin_default, tag, attribute), _mean)


def _size_factors(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> tuple[float, ...]:
    """The factors of a geom's or site's size, by how many values it writes (see ``Cycles``)."""
    return _factors_of_size(len(numbers_of(get_attribute(element, "size")) or ()), context)


def _scaled_size(value: Value, context: ScaleContext) -> Value | None:
    """A geom's ``size`` scaled (every value is a length, whatever the type)."""
    size = value if type(value) is tuple else numbers_of(value)
    if size is None:
        return None
    factors = _factors_of_size(len(size), context)
    return tuple([n * f for n, f in zip(size, factors, strict=False)])


def _factors_of_size(count: int, context: ScaleContext) -> tuple[float, ...]:
    """The factors of a size of ``count`` values; more than three is not MJCF."""
    if count > 3:
        raise MjcfValueError(
            f"a size of {count} numbers cannot be scaled: MuJoCo reads at most 3 ('too much data')"
        )
    return context.cycles.sizes[count]


_geom_size = ValueRule("size", _scaled_size)


_site_size = BuiltinRule(
    "size", "site", functools.partial(builtin_default, "site", "size"), _size_factors
)


_JOINT_LENGTHS = ("range", "ref", "springref", "margin")
_JOINT_READ = ("type", "axis", *_JOINT_LENGTHS)


def _joint(element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext) -> Changes:
    """Ranges, references and margins are lengths for slide joints only.

    A value a joint inherits was scaled in its class when that class's joints
    slide; where the joint's own type differs, the right value is written on it.
    """
    classes = context.classes
    kind, axis, *lengths_written = attribute_values(element, _JOINT_READ)
    inherited = classes.inherited(element, ancestors, "joint")
    if kind is None and "type" in inherited:
        kind = inherited["type"][0]
    if axis is None and "axis" in inherited:
        axis = inherited["axis"][0]
    factor = slide_factor(kind, axis, context)
    changes: Changes = {}
    for attribute, own in zip(_JOINT_LENGTHS, lengths_written, strict=True):
        if own is not None:
            if factor != 1.0:
                changes[attribute] = times(own, factor)
            continue
        found = inherited.get(attribute)
        if found is None:
            continue
        value, provider = found
        provider_given = classes.given(provider, "joint")
        provider_kind = provider_given.get("type")
        provider_axis = provider_given.get("axis")
        provider_factor = slide_factor(
            provider_kind and provider_kind[0], provider_axis and provider_axis[0], context
        )
        if provider_factor != factor:
            changes[attribute] = times(value, factor)
    return changes


def _target_factor(element: AnyElement, key: str | None, context: ScaleContext) -> float:
    """The factor of an actuator's control: a position servo on a slide joint aims at a length."""
    if key != "actuator/position":
        return 1.0
    info = context.joint(get_attribute(element, "joint"))
    return context.along(info.axis) if info is not None and info.type == "slide" else 1.0


def _position_ctrlrange(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """A position actuator on a slide joint takes targets in length units.

    A range its class gives is not scaled in the class (the class's servos may turn
    hinges): the scaled range is written on the actuator instead.
    """
    factor = _target_factor(element, "actuator/position", context)
    if factor == 1.0:
        return {}
    value = get_attribute(element, "ctrlrange")
    if value is None:
        found = context.classes.given_to(element, ancestors).get("ctrlrange")
        value = found[0] if found is not None else None
    return {} if value is None else {"ctrlrange": times(value, factor)}


def _control_factors(context: ScaleContext) -> tuple[float, ...]:
    """The factor of each actuator's control, in the model's actuator order."""
    model = context.model

    def compute() -> tuple[float, ...]:
        walked = keyed_walk(model) if model is not None else ()
        return tuple(
            _target_factor(element, key, context)
            for element, key, _ in walked
            if key is not None and key.startswith("actuator/") and not key.endswith("/config")
        )

    return context.cached("control factors", compute)


def _keyframe(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """Mocap positions, the slide and free-joint parts of ``qpos`` and ``qvel``, position targets.

    A ``ctrl`` value of a position servo on a slide joint is a length, as its
    ``ctrlrange`` is. A short key's values are the leading entries.
    """
    changes = points("mpos")[0](element, ancestors, context)
    if context.layout is None:
        return changes
    qpos: list[float] = []
    qvel: list[float] = []
    for joint in context.layout:
        if joint.type == "free":
            qpos += [*context.factors, 1, 1, 1, 1]
            qvel += [*context.factors, 1, 1, 1]
        elif joint.type == "ball":
            qpos += [1, 1, 1, 1]
            qvel += [1, 1, 1]
        else:
            factor = context.along(joint.axis) if joint.type == "slide" else 1.0
            qpos.append(factor)
            qvel.append(factor)
    controls = _control_factors(context)
    for attribute, factors in (("qpos", qpos), ("qvel", qvel), ("ctrl", controls)):
        value = numbers_of(get_attribute(element, attribute))
        # a short key gives the leading entries (MuJoCo completes the rest from the
        # scaled model); a long one MuJoCo rejects, and it is left as it is
        if value is not None and len(value) <= len(factors):
            changes[attribute] = tuple(
                v * f for v, f in zip(value, factors[: len(value)], strict=True)
            )
    return changes


def _hfield(element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext) -> Changes:
    size = numbers_of(get_attribute(element, "size"))
    if size is None:
        return {}
    x, y, z = context.factors
    return {"size": tuple(n * f for n, f in zip(size, (x, y, z, z), strict=False))}


def _weld_relpose(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """The first three of ``relpose`` are a position; the rest a quaternion."""
    pose = numbers_of(get_attribute(element, "relpose"))
    if pose is None:
        return {}
    return {
        "relpose": tuple(v * f for v, f in zip(pose, (*context.factors, 1, 1, 1, 1), strict=False))
    }


def _area_factor(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> float:
    return context.mean**2


#: A cylinder's ``area``; MuJoCo's built-in one (1) is written, scaled, where nothing sets
#: it (a ``diameter``, scaled as a length, still overrides it).
_builtin_area = BuiltinRule("area", "cylinder", lambda: (1.0,), _area_factor)


def _cylinder_area(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """The area, unless a diameter sets it: a class's diameter is an area the class gives.

    MuJoCo turns a ``diameter`` into the area of the element (or class) writing it,
    so an area written on an element would override its class's diameter.
    """
    unwritten = get_attribute(element, "area") is None
    diameter = context.classes.resolve(element, ancestors, "diameter", "cylinder")
    if unwritten and diameter is not None:
        return {}
    return _builtin_area(element, ancestors, context)


_GEOM = combine(
    points("pos", "fromto"),
    _geom_size,
    lengths("margin", "gap"),
    friction_rule("geom"),
    masses("mass"),
)
_SITE = combine(points("pos", "fromto"), _site_size)
_CAMERA = combine(
    points("pos"),
    _builtin_length("ipd", "camera"),
    lengths("focal", "sensorsize", "principal"),
)
_LIGHT = combine(
    points("pos"),
    _builtin_length("bulbradius", "light"),
    _builtin_length("range", "light"),
)
_CONTACT = combine(lengths("margin", "gap"), friction_rule("pair"))
_FLEX_CONTACT = combine(lengths("margin", "gap"), friction_rule("flex"))


def _site_gear(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """A site transmission's rotational gear where its length mixes lengths and angles.

    With a ``refsite`` MuJoCo measures ``gear[:3]`` along the site's offset and
    ``gear[3:]`` along its rotation. Where both parts are set the length is a
    length, so the rotational part is a lever arm and scales, as a hinge's
    ``coef`` does in a fixed tendon that also holds a slide joint. A purely
    translational gear needs nothing; a purely rotational one measures an angle.
    """
    if get_attribute(element, "site") is None or get_attribute(element, "refsite") is None:
        return {}
    own = numbers_of(get_attribute(element, "gear"))
    given = context.classes.given_to(element, ancestors).get("gear")
    inherited = numbers_of(given[0]) if given else None
    if own is None and inherited is None:
        return {}
    full = list(builtin_default("actuator", "gear"))  # a short gear is read over its class's
    for values in (inherited, own):
        full[: len(values or ())] = (values or ())[:6]
    if not any(full[:3]) or not any(full[3:]):
        return {}
    return {"gear": (*full[:3], *(v * context.mean for v in full[3:]))}


_ACTUATOR = combine(lengths("cranklength"), _site_gear)
_MESH_SCALE = BuiltinRule(
    "scale", "mesh", functools.partial(builtin_default, "mesh", "scale"), _per_axis
)


def _mesh(element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext) -> Changes:
    """A mesh made by an SDF plugin scales through the plugin's settings, not ``scale``."""
    rule = sdf_mesh_scale if makes_sdf(element) else _MESH_SCALE
    return rule(element, ancestors, context)


#: The flexcomp types whose points MuJoCo multiplies by ``scale`` (the others ignore it).
_POINT_TYPES = frozenset({"direct", "mesh", "gmsh"})
#: MuJoCo's default flexcomp ``spacing`` and ``inertiabox`` (``user_flexcomp.cc``).
_FLEXCOMP_SPACING, _FLEXCOMP_INERTIABOX = (0.02, 0.02, 0.02), (0.005,)
_FLEX_RADIUS = BuiltinRule(
    "radius", "flex", functools.partial(builtin_default, "flex", "radius"), _mean
)
_FLEXCOMP_COMMON = combine(points("pos"), _FLEX_RADIUS, masses("mass"))
_FLEXCOMP_SCALE = BuiltinRule(
    "scale", "flexcomp", functools.partial(builtin_default, "mesh", "scale"), _per_axis
)


def _flexcomp(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """Each generated point once: through ``scale`` or through ``spacing``, never both.

    MuJoCo multiplies the points of the ``direct``, ``mesh`` and ``gmsh`` types
    (``point``, the file's vertices, and ``origin``) by ``scale``, and builds the
    other types from ``spacing`` alone. A ``disc``'s points grow with the square
    of its spacing, so that spacing takes the square root of the factors; it must
    still exceed twice the radius plus the margin, which grow linearly.
    """
    changes = _FLEXCOMP_COMMON(element, ancestors, context)
    box = numbers_of(get_attribute(element, "inertiabox")) or _FLEXCOMP_INERTIABOX
    changes["inertiabox"] = format_value(box[0] * context.mean)  # a text field
    kind = get_attribute(element, "type") or "grid"
    if kind in _POINT_TYPES:
        return {**changes, **_FLEXCOMP_SCALE(element, ancestors, context)}
    spacing = numbers_of(get_attribute(element, "spacing")) or _FLEXCOMP_SPACING
    factors = np.sqrt(context.factors) if kind == "disc" else np.asarray(context.factors)
    changes["spacing"] = times(tuple(spacing), factors)
    radius = (numbers_of(changes.get("radius")) or (0.0,))[0]
    # the children are scaled before their parent: the contact margin read here is scaled
    margin = sum(
        (numbers_of(get_attribute(c, "margin")) or (0.0,))[0]
        for c in element.elements
        if c.tag == "contact"
    )
    if kind == "disc" and min(numbers_of(changes["spacing"]) or ()) < 2 * radius + margin:
        raise MjcfValueError(
            f"cannot scale the disc flexcomp {get_attribute(element, 'name')!r} by "
            f"{context.factors}: its spacing grows with the square root of the factor but "
            "must exceed twice its radius plus its margin, which grow with the factor; "
            "use a smaller factor or a larger spacing"
        )
    return changes


_EXPLICIT: dict[str, Rule] = {
    "option": combine(lengths("o_margin")),
    "compiler": combine(masses("boundmass", "settotalmass"), inertias("boundinertia")),
    "statistic": combine(
        points("center"), lengths("extent", "meansize"), masses("meanmass"), inertias("meaninertia")
    ),
    "default/mesh": combine(points("scale")),
    "default/joint": combine(points("pos"), _joint),
    "default/geom": _GEOM,
    "default/site": _SITE,
    "default/camera": _CAMERA,
    "default/light": _LIGHT,
    "default/pair": _CONTACT,
    "asset/mesh": _mesh,
    "asset/mesh/plugin/config": sdf_config,
    "body/geom/plugin/config": sdf_config,
    "extension/plugin/instance/config": sdf_config,
    "asset/hfield": _hfield,
    "asset/skin": combine(points("vertex"), lengths("inflate")),
    "asset/skin/bone": combine(points("bindpos")),
    "body": combine(points("pos")),
    "body/inertial": combine(
        points("pos"), masses("mass"), principal_inertias("diaginertia"), inertias("fullinertia")
    ),
    "body/joint": combine(points("pos"), _joint),
    "body/geom": combine(_GEOM, geom_density),
    "body/site": _SITE,
    "body/camera": _CAMERA,
    "body/light": _LIGHT,
    "body/flexcomp": _flexcomp,
    "body/flexcomp/elasticity": combine(lengths("thickness")),
    "body/flexcomp/contact": _FLEX_CONTACT,
    "body/frame": combine(points("pos")),
    "body/replicate": combine(points("offset")),
    "deformable/flex": combine(points("vertex", "nodecoord"), _FLEX_RADIUS),
    "deformable/flex/contact": _FLEX_CONTACT,
    "deformable/flex/elasticity": combine(lengths("thickness")),
    "deformable/skin": combine(points("vertex"), lengths("inflate")),
    "deformable/skin/bone": combine(points("bindpos")),
    "contact/pair": _CONTACT,
    "tendon/spatial": spatial_tendon,
    "tendon/fixed": fixed_tendon,
    "tendon/fixed/joint": tendon_coefficient,
    "equality/connect": combine(points("anchor")),
    "equality/joint": joint_coupling,
    "equality/tendon": tendon_coupling,
    "equality/weld": combine(points("anchor"), _weld_relpose),
    "actuator/position": combine(_ACTUATOR, _position_ctrlrange),
    "actuator/cylinder": combine(_ACTUATOR, lengths("diameter"), _cylinder_area),
    "default/cylinder": combine(_ACTUATOR, lengths("diameter"), _cylinder_area),
    "keyframe/key": _keyframe,
}


def _rule_of(key: str) -> Rule:
    if key in _EXPLICIT:
        return _EXPLICIT[key]
    section = key.split("/")[0]
    actuator_default = section == "default" and "cranklength" in SCHEMA[key].attributes
    if (section == "actuator" and not key.endswith("/config")) or actuator_default:
        return _ACTUATOR
    return NO_LENGTHS


#: The scaling rule of every schema key (``NO_LENGTHS`` where nothing is a length).
RULES: Mapping[str, Rule] = MappingProxyType({key: _rule_of(key) for key in SCHEMA})
