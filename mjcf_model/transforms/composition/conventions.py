"""A model rewritten into another model's ``<compiler>`` conventions, its meaning kept.

MuJoCo reads a model's angles, Euler sequences, limit flags and inertias under
the settings of one ``<compiler>``. A child attached into a parent is read under
the parent's, so :func:`in_conventions` rewrites the child so that MuJoCo
compiles each of its bodies, joints, geoms, sites and actuators as it compiles
the child alone. Each setting (the effective value: the ``<compiler>`` sections
merged, later attributes winning, MuJoCo's default where none is written) is
handled so:

================== ===========================================================
``angle``          converted: ``euler`` and the angle of ``axisangle`` (bodies,
                   frames, geoms, sites, cameras, inertials, flexcomps,
                   replicates and their defaults); ``range`` of hinge and ball
                   joints, ``ref``, ``springref``, ``springyield`` of hinges.
                   A joint that inherits such a value gets it written, converted
                   (only its final type says whether it is an angle); the
                   default class keeps its value for the slide joints it reaches.
                   A joint range MuJoCo leaves as written (an unlimited joint's)
                   is left so too. Degrees become exactly the radians MuJoCo
                   makes of them; radians become the degrees MuJoCo reads back
                   exactly, where a double does (else as under ``eulerseq``).
``eulerseq``       converted: an element's ``euler``, where no class orients
                   it, becomes exactly the ``quat`` MuJoCo compiles from it.
                   Otherwise (in a ``<default>``, on a ``<replicate>``, or where
                   a class gives the element an orientation) it is rewritten in
                   the parent's sequence: the same notation, so what an element
                   overrides of its class stays as it was in MuJoCo 3.9 (which
                   prefers a class's ``euler`` to an element's ``quat``) and 4.0
                   alike; the quaternion agrees to about 1e-16, 1e-11 near gimbal
                   lock. Refused where the parent's sequence cannot say it: it
                   repeats an axis, or a ``<replicate>`` (which turns copy ``i``
                   by ``i`` times its angles) has no such angles in it.
``autolimits``     carried: ``limited``, ``actuatorfrclimited``, ``ctrllimited``,
                   ``forcelimited``, ``actlimited`` written where unset or auto.
``alignfree``      carried: ``align`` written on free joints. Refused for a
                   ``<joint type="free">`` in a leaf body (write ``<freejoint>``).
inertia settings   carried (``inertiafromgeom``, ``boundmass``, ``boundinertia``,
                   ``balanceinertia``, ``inertiagrouprange``, ``settotalmass``):
                   the child is
                   compiled alone and each body MuJoCo would read differently
                   gets an explicit ``<inertial>``; refused, naming the settings,
                   where the parent's still change a body (its
                   ``inertiafromgeom="true"`` ignores inertials, its ``boundmass``
                   exceeds a mass, its ``settotalmass`` rescales every mass).
``fitaabb``        refused when it differs and a geom is fitted to a mesh.
path settings      :data:`PATH_SETTINGS`: not handled here; file paths are left
                   alone.
model-wide         :data:`MODEL_WIDE_SETTINGS`: the parent's value is kept.
================== ===========================================================

>>> from mjcf_model import dumps, loads
>>> child = loads('<mujoco><compiler angle="radian"/><worldbody><body name="b">'
...               '<joint name="j" range="0 1.5"/><geom size="1"/></body></worldbody></mujoco>')
>>> print(dumps(in_conventions(child, loads("<mujoco/>")), canonical=True), end="")
<mujoco>
  <worldbody>
    <body name="b">
      <joint name="j" range="0 85.94366926962348"/>
      <geom size="1"/>
    </body>
  </worldbody>
</mujoco>
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from typing import Any

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.base import AnyElement, get_attribute, with_attributes
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.transforms.composition.compiler_settings import (
    CONVERTED_SETTINGS,
    INERTIA_SETTINGS,
    MODEL_WIDE_SETTINGS,
    NUMERIC_SETTINGS,
    PATH_SETTINGS,
    Settings,
    compiler_settings,
)
from mjcf_model.transforms.composition.inertia import Changes, inertia_kept
from mjcf_model.transforms.composition.rotations import (
    ORIENTATIONS,
    euler_angles,
    euler_product,
    euler_quat,
    in_unit,
    joint_radians,
    orientation_radians,
    quat_distance,
)
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.traversal import keyed_walk, map_elements, refuse_opaque, with_children
from mjcf_model.values import Value, numbers_of

__all__ = [
    "CONVERTED_SETTINGS",
    "MODEL_WIDE_SETTINGS",
    "PATH_SETTINGS",
    "compiler_settings",
    "in_conventions",
]

#: The joint values read in the compiler's angle unit, by joint type.
_JOINT_ANGLES = {"hinge": ("range", "ref", "springref", "springyield"), "ball": ("range",)}
#: Each limit flag and the range whose presence ``autolimits`` reads.
_LIMIT_FLAGS = {
    "limited": "range",
    "actuatorfrclimited": "actuatorfrcrange",
    "ctrllimited": "ctrlrange",
    "forcelimited": "forcerange",
    "actlimited": "actrange",
}


def _differing(mine: Settings, theirs: Settings) -> set[str]:
    def reading(name: str, settings: Settings) -> object:
        text = settings[name].strip()
        return numbers_of(text) if name in NUMERIC_SETTINGS else text

    return {name for name in CONVERTED_SETTINGS if reading(name, mine) != reading(name, theirs)}


class _Rewriter:
    """The element rewrites of one conversion: angles, limit flags, free joint alignment."""

    def __init__(
        self, child: Mujoco, mine: Settings, theirs: Settings, differing: set[str]
    ) -> None:
        self.classes = DefaultClasses.of(child)
        self.mine, self.theirs, self.differing = mine, theirs, differing
        self.from_degrees = mine["angle"] == "degree"
        self.to_degrees = theirs["angle"] == "degree"

    def angle(self, value: float, reading: Callable[[float], float]) -> float:
        """An angle in the child's unit, in the parent's (``reading`` is MuJoCo's conversion)."""
        radians = reading(value) if self.from_degrees else value
        return in_unit(radians, self.to_degrees, reading)

    def resolve(
        self, element: AnyElement, ancestors: Sequence[AnyElement], name: str
    ) -> Value | None:
        """``name`` for ``element``: its own, else its classes' (where actuators share one)."""
        own = get_attribute(element, name)
        if own is not None:
            return own
        found = self.classes.given_to(element, ancestors).get(name)
        return None if found is None else found[0]

    def __call__(
        self, element: AnyElement, key: str | None, ancestors: Sequence[AnyElement]
    ) -> AnyElement:
        spec = SCHEMA.get(key or "")
        if spec is None:
            return element
        changes: Changes = {}
        if {"angle", "eulerseq"} & self.differing and "euler" in spec.attributes:
            changes.update(self.orientation(element, ancestors, spec.key))
        if "angle" in self.differing and spec.key == "body/joint":
            changes.update(self.joint_angles(element, ancestors))
        if "autolimits" in self.differing and not spec.key.startswith("default/"):
            changes.update(self.limits(element, ancestors, spec.key))
        if "alignfree" in self.differing:
            changes.update(self.alignment(element, ancestors, spec.key))
        if "fitaabb" in self.differing and spec.key == "body/geom":
            self.refuse_fitted(element, ancestors)
        return with_attributes(element, changes) if changes else element

    def orientation(
        self, element: AnyElement, ancestors: Sequence[AnyElement], key: str
    ) -> Changes:
        """``euler`` in the parent's unit and sequence, or as ``quat``; ``axisangle`` in its unit.

        Where the conversion is not exact (another sequence, or degrees no double
        reads back as the radians) and no class orients the element, its turn is
        written as ``quat`` instead: exactly the quaternion MuJoCo compiles.
        """
        changes: Changes = {}
        euler = _numbers(element, "euler")
        if euler is not None:
            radians = [orientation_radians(v) if self.from_degrees else v for v in euler]
            converted = [in_unit(r, self.to_degrees, orientation_radians) for r in radians]
            exact = self.mine["eulerseq"] == self.theirs["eulerseq"] and (
                not self.to_degrees
                or all(orientation_radians(c) == r for c, r in zip(converted, radians, strict=True))
            )
            if not exact and self.quat_kept(element, ancestors, key):
                changes["euler"] = None
                changes["quat"] = euler_product(radians, self.mine["eulerseq"])
            elif self.mine["eulerseq"] != self.theirs["eulerseq"]:
                turned = self.in_sequence(element, radians)
                changes["euler"] = tuple(
                    in_unit(r, self.to_degrees, orientation_radians) for r in turned
                )
            else:
                changes["euler"] = tuple(converted)
        axisangle = _numbers(element, "axisangle")
        if axisangle is not None and "angle" in self.differing:
            changes["axisangle"] = (*axisangle[:3], self.angle(axisangle[3], orientation_radians))
        return changes

    def quat_kept(self, element: AnyElement, ancestors: Sequence[AnyElement], key: str) -> bool:
        """Whether MuJoCo compiles ``element`` with its own ``quat``, whatever its MuJoCo release.

        Not in a ``<default>`` (a class's ``quat`` would lose to an outer class's
        ``euler`` in MuJoCo 3.9), not where a class orients the element (3.9
        prefers the class's ``euler``, ``axisangle``... to the element's ``quat``),
        and not on a ``<replicate>`` (it has no ``quat``).
        """
        if key.startswith("default/") or "quat" not in SCHEMA[key].attributes:
            return False
        given = self.classes.inherited(element, ancestors)
        return not any(name in given for name in ORIENTATIONS)

    def in_sequence(self, element: AnyElement, radians: list[float]) -> list[float]:
        """The same turn in the parent's sequence.

        A ``<replicate>`` turns copy ``i`` by ``i`` times its angles, so there the
        new angles must give the same turn at every multiple.
        """
        mine, theirs = self.mine["eulerseq"], self.theirs["eulerseq"]
        turned = euler_angles(euler_quat(radians, mine), theirs)
        count = numbers_of(get_attribute(element, "count")) if element.tag == "replicate" else None
        multiples = range(2, int(count[0]) if count else 0)
        if turned is None or any(
            quat_distance(
                euler_quat([i * a for a in turned], theirs),
                euler_quat([i * r for r in radians], mine),
            )
            > 1e-12
            for i in multiples
        ):
            raise MjcfValueError(
                f"the parent's eulerseq={theirs!r} cannot express the turn of the child's "
                f"<{element.tag} euler> (eulerseq={mine!r}); give the two models the same eulerseq"
            )
        return list(turned)

    def joint_angles(self, element: AnyElement, ancestors: Sequence[AnyElement]) -> Changes:
        """Hinge and ball values, own or inherited (MuJoCo converts a range only if limited)."""
        kind = self.classes.resolve(element, ancestors, "type") or "hinge"
        changes: Changes = {}
        for name in _JOINT_ANGLES.get(str(kind), ()):
            value = numbers_of(self.classes.resolve(element, ancestors, name))
            if value is None or (
                name == "range" and not self.limited(element, ancestors, "limited")
            ):
                continue
            converted = tuple(self.angle(v, joint_radians) for v in value)
            changes[name] = converted if len(converted) > 1 else converted[0]
        return changes

    def limited(self, element: AnyElement, ancestors: Sequence[AnyElement], flag: str) -> bool:
        """Whether the child's MuJoCo reads ``flag`` (``limited``, ``ctrllimited``...) as true."""
        written = self.resolve(element, ancestors, flag)
        if written not in (None, "auto"):
            return written == "true"
        in_tendons = bool(ancestors) and ancestors[-1].tag == "tendon"
        if flag == "actuatorfrclimited" and in_tendons and not _infers_tendon_force_limits():
            return False
        bounds = numbers_of(self.resolve(element, ancestors, _LIMIT_FLAGS[flag]))
        if bounds is not None and len(bounds) == 2 and bounds[0] < bounds[1]:
            return True
        inherit = numbers_of(self.resolve(element, ancestors, "inheritrange"))
        return flag == "ctrllimited" and bool(inherit and inherit[0] > 0)

    def limits(self, element: AnyElement, ancestors: Sequence[AnyElement], key: str) -> Changes:
        """Every limit flag the element has, written as the child's ``autolimits`` reads it.

        An ``<intvelocity>`` sets ``actlimited`` itself (MuJoCo 3.9 has no such
        attribute, 4.0 ignores it and, under ``autolimits="false"``, rejects any
        ``actrange``: refused there).
        """
        if (
            key == "actuator/intvelocity"
            and self.theirs["autolimits"] == "false"
            and self.resolve(element, ancestors, "actrange") is not None
            and _rejects_actrange()
        ):
            raise MjcfValueError(
                "the parent's autolimits='false' makes MuJoCo reject the child's "
                "<intvelocity actrange>; give the two models the same autolimits"
            )
        return {
            flag: "true" if self.limited(element, ancestors, flag) else "false"
            for flag in _LIMIT_FLAGS
            if flag in SCHEMA[key].attributes
            and (key, flag) != ("actuator/intvelocity", "actlimited")
            and self.resolve(element, ancestors, flag) in (None, "auto")
        }

    def alignment(self, element: AnyElement, ancestors: Sequence[AnyElement], key: str) -> Changes:
        """The child's ``alignfree`` written on a free joint that does not say its own."""
        if key == "body/freejoint" and get_attribute(element, "align") in (None, "auto"):
            return {"align": self.mine["alignfree"]}
        if key == "body/joint" and self.classes.resolve(element, ancestors, "type") == "free":
            body = next(a for a in reversed(ancestors) if a.tag == "body")
            if not any(e.tag == "body" for e, _, _ in keyed_walk(body) if e is not body):
                raise MjcfValueError(
                    "the parent's alignfree differs from the child's, and a <joint "
                    'type="free"> cannot say which applies to it; write it as <freejoint>'
                )
        return {}

    def refuse_fitted(self, element: AnyElement, ancestors: Sequence[AnyElement]) -> None:
        """Raise for a geom fitted to a mesh (a primitive with ``mesh``): fitaabb sizes it."""
        mesh = self.classes.resolve(element, ancestors, "mesh")
        kind = self.classes.resolve(element, ancestors, "type") or "sphere"
        if mesh is not None and kind not in ("mesh", "sdf"):
            raise MjcfValueError(
                f"the parent's fitaabb differs from the child's, and geom "
                f"{get_attribute(element, 'name') or '(unnamed)'} is fitted to mesh {mesh!r}: "
                "its size would change; give the two models the same fitaabb"
            )


@functools.cache
def _probe(sections: str) -> Any:
    """A one-hinge (``j``) model with ``sections`` as the installed MuJoCo compiles it, or None.

    Where MuJoCo releases read a flag differently, the conversion asks MuJoCo.
    """
    import mujoco

    try:
        return mujoco.MjModel.from_xml_string(
            f'<mujoco><worldbody><body><joint name="j"/><geom size="1"/></body></worldbody>'
            f"{sections}</mujoco>"
        )
    except ValueError:
        return None


def _rejects_actrange() -> bool:
    """Whether MuJoCo rejects any ``<intvelocity actrange>`` under ``autolimits="false"`` (4.0)."""
    integrated = '<actuator><intvelocity joint="j" actrange="0 1"/></actuator>'
    return _probe(f'<compiler autolimits="false"/>{integrated}') is None


def _infers_tendon_force_limits() -> bool:
    """Whether a tendon's ``actuatorfrcrange`` makes it force-limited (not in MuJoCo 3.9)."""
    found = _probe(
        '<tendon><fixed actuatorfrcrange="-1 1"><joint joint="j" coef="1"/></fixed></tendon>'
    )
    return bool(found is not None and found.tendon_actfrclimited[0])


def _numbers(element: AnyElement, name: str) -> tuple[float, ...] | None:
    value = get_attribute(element, name)
    found = numbers_of(value)
    if value is not None and found is None:
        raise MjcfValueError(f"cannot convert <{element.tag} {name}={value!r}>: not numbers")
    return found


# --- the conversion ---------------------------------------------------------------------------


def in_conventions(child: Mujoco, parent: Mujoco) -> Mujoco:
    """The child rewritten to mean under the parent's ``<compiler>`` what it means under its own.

    Under the parent's ``<compiler>`` settings, MuJoCo compiles every body, joint,
    geom, site and actuator of the result exactly as it compiles the child alone
    under its own ``<compiler>``. The child's ``<compiler>`` sections are removed.

    How each setting is kept is in the module documentation and
    :data:`CONVERTED_SETTINGS`. The file-path settings (:data:`PATH_SETTINGS`) are
    not handled: file attributes are left as they are. The settings of
    :data:`MODEL_WIDE_SETTINGS` hold for the whole model (``fusestatic``,
    ``discardvisual``, ``usethread``, ``saveinertial``,
    ``savecompiled``, ``savecanonical``, ``conflict``, ``passthrough``,
    ``coordinate`` and the ``<lengthrange>`` element): the parent's stay; "as the
    child alone" means the child alone under those of the parent.

    Raises:
        MjcfValueError: A setting differs where no rewriting keeps the child's
            meaning (the message names it), or the child has ``<include>``
            elements (load it with ``inline_includes=True``).

    Examples:
        >>> from mjcf_model import loads
        >>> child = loads('<mujoco><compiler angle="radian" eulerseq="zyx"/><worldbody>'
        ...               '<body euler="1.5707963267948966 0 0"/></worldbody></mujoco>')
        >>> body = in_conventions(child, loads("<mujoco/>")).worldbody.bodies[0]
        >>> body.euler, [round(c, 9) + 0 for c in body.quat]
        (None, [0.707106781, 0.0, 0.0, 0.707106781])

    """
    mine, theirs = compiler_settings(child), compiler_settings(parent)
    differing = _differing(mine, theirs)
    result = child
    if differing:
        for element, key, _ in keyed_walk(child):
            refuse_opaque(element, key, "convert the compiler settings of")
        result = map_elements(_Rewriter(child, mine, theirs, differing), child)
        if differing & set(INERTIA_SETTINGS):
            result = inertia_kept(child, result, mine, theirs)
    kept = [c for c in result.children if getattr(c, "tag", None) != "compiler"]
    return with_children(result, kept)
