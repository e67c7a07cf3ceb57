"""Variants without recompiling: write a model's changed values into its compiled arrays.

Physical randomisation mostly changes values a compiled model holds one for one: a
geom's colour and contact parameters, a joint's damping, an actuator's gains, a
body's explicit mass. :func:`patched` finds what changed between two models (the
unchanged subtrees they share are skipped), writes each change into a copy of the
compiled model, and recomputes what MuJoCo derives from it (``mj_setConst``, and the
mean mass and inertia of ``<statistic>``). Anything else (a new element, a default
class, a size, a position...) is compiled again in full, with a
:class:`~mjcf_model.MjcfRecompiledWarning` that names the first such change.

>>> from mjcf_model import compiled, map_elements, with_attributes
>>> from mjcf_model import loads
>>> before = loads('<mujoco><worldbody><geom name="g" size="0.1" rgba="1 0 0 1"/>'
...                '</worldbody></mujoco>')
>>> def green(element, key, ancestors):
...     return with_attributes(element, {"rgba": (0, 1, 0, 1)}) if key == "body/geom" else element
>>> after = map_elements(green, before)
>>> patched(compiled(before), before, after).geom_rgba.tolist()
[[0.0, 1.0, 0.0, 1.0]]
"""

from __future__ import annotations

import copy
import functools
import warnings
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from mjcf_model.bridge.compiling import compiled
from mjcf_model.caching import BoundedCache
from mjcf_model.errors import MjcfRecompiledWarning
from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    attribute_items,
    get_attribute,
    with_attributes,
)
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import child_key
from mjcf_model.tree.traversal import keyed_walk, with_children
from mjcf_model.values import numbers_of

if TYPE_CHECKING:
    import mujoco

__all__ = ["FIELDS", "patched"]


#: The compiled array of each attribute that maps one for one, by element key: a
#: prefix of the array's row takes the written numbers.
FIELDS: dict[str, dict[str, str]] = {
    "body/geom": {
        "rgba": "geom_rgba",
        "friction": "geom_friction",
        "solref": "geom_solref",
        "solimp": "geom_solimp",
        "margin": "geom_margin",
        "gap": "geom_gap",
    },
    "body/joint": {
        "damping": "dof_damping",
        "armature": "dof_armature",
        "frictionloss": "dof_frictionloss",
        "stiffness": "jnt_stiffness",
    },
    "body/inertial": {"mass": "body_mass", "diaginertia": "body_inertia"},
    "actuator/general": {
        "gainprm": "actuator_gainprm",
        "biasprm": "actuator_biasprm",
        "gear": "actuator_gear",
        "ctrlrange": "actuator_ctrlrange",
        "forcerange": "actuator_forcerange",
    },
    **{
        f"actuator/{kind}": {
            "gear": "actuator_gear",
            "ctrlrange": "actuator_ctrlrange",
            "forcerange": "actuator_forcerange",
        }
        for kind in ("motor", "position", "velocity", "intvelocity", "damper", "cylinder")
    },
}

#: The fields MuJoCo before 4.0 also derives no statistic from (its compiler's ``center``,
#: ``extent`` and ``meansize`` follow masses, margins and control ranges): there only
#: these are patched, and any other change compiles again.
_BEFORE_4 = frozenset(
    {"geom_rgba", "geom_friction", "geom_solref", "geom_solimp", "dof_damping", "dof_frictionloss"}
)

#: Every array :func:`patched` writes.
_PATCHED = frozenset(array for arrays in FIELDS.values() for array in arrays.values())

#: Fields of a geom's contacts and looks: changing only these needs no ``mj_setConst``.
_LOCAL = frozenset(FIELDS["body/geom"].values()) | {"dof_damping", "dof_frictionloss"}

#: ``<compiler>`` settings under which explicit inertials are not compiled as written.
_INERTIA_SETTINGS = (
    "inertiafromgeom", "boundmass", "boundinertia", "balanceinertia", "settotalmass",
)  # fmt: skip


def patched(
    model: mujoco.MjModel,
    before: Mujoco,
    after: Mujoco,
    *,
    into: mujoco.MjModel | None = None,
) -> mujoco.MjModel:
    """A copy of ``model`` (compiled from ``before``) changed as ``after`` differs from it.

    Args:
        model: ``before`` compiled (:func:`mjcf_model.compiled`); it is not changed.
        before: The model ``model`` was compiled from.
        after: A variant of ``before``: the same elements, some values changed.
        into: A copy of ``model`` to write the variant into instead of a new copy (a
            variant loop makes one, ``copy.copy(model)``, and patches it each time; a
            copy of a mesh-heavy model costs more than the patch). Whatever an earlier
            variant wrote there is first set back to ``model``'s values. When the
            variant must be compiled, a new model is returned and ``into`` is left as
            it was.

    Returns:
        What ``compiled(after)`` returns, array for array: patched when every change
        is a value of :data:`FIELDS` that ``after`` writes whole (a full row: four
        numbers of ``rgba``, three of ``friction``...) or with as many numbers as
        ``before`` wrote, else compiled in full (with a
        :class:`~mjcf_model.MjcfRecompiledWarning`).

    Examples:
        >>> import copy
        >>> from mjcf_model import compiled, map_elements, with_attributes
        >>> from mjcf_model import loads
        >>> robot = loads('<mujoco><worldbody><geom size="0.1"/></worldbody></mujoco>')
        >>> base = compiled(robot)
        >>> scratch = copy.copy(base)
        >>> def red(element, key, ancestors):
        ...     is_geom = key == "body/geom"
        ...     return with_attributes(element, {"rgba": (1, 0, 0, 1)}) if is_geom else element
        >>> patched(base, robot, map_elements(red, robot), into=scratch) is scratch
        True
        >>> scratch.geom_rgba.tolist(), base.geom_rgba.tolist()
        ([[1.0, 0.0, 0.0, 1.0]], [[0.5, 0.5, 0.5, 1.0]])

    """
    import mujoco

    changes: list[tuple[str, str, int, tuple[float, ...]]] = []
    problem = _mapped(model, before, after, changes)
    if problem is not None:
        warnings.warn(
            f"patched() compiles the model again: {problem}",
            MjcfRecompiledWarning,
            stacklevel=2,
        )
        return compiled(after)
    if into is None:
        result = copy.copy(model)
    else:
        result = into
        for field in _PATCHED:  # what an earlier variant wrote goes back to the model's
            getattr(result, field)[...] = getattr(model, field)
    for field, _, row, numbers in changes:
        array = getattr(result, field)
        if array.ndim == 1:
            array[row] = numbers[0]
        else:
            array[row, : len(numbers)] = numbers
    # A model patched before may hold what an earlier variant derived: derive it all again
    # (before MuJoCo 4.0 only fields that derive nothing are patched).
    again = into is not None and int(mujoco.__version__.split(".")[0]) >= 4
    if again or any(field in ("geom_margin", "geom_gap") for field, _, _, _ in changes):
        _body_margins(result)
    if again or any(field not in _LOCAL for field, _, _, _ in changes):
        mujoco.mj_setConst(result, mujoco.MjData(result))
        _restate(result, before)
    return result


def _body_margins(model: mujoco.MjModel) -> None:
    """Each body's margin: the largest margin plus gap of its geoms, as MuJoCo compiles it."""
    model.body_margin[:] = 0
    for body, margin, gap in zip(model.geom_bodyid, model.geom_margin, model.geom_gap, strict=True):
        model.body_margin[body] = max(model.body_margin[body], margin + gap)


def _restate(model: mujoco.MjModel, source: Mujoco) -> None:
    """The ``<statistic>`` means MuJoCo computes from masses, unless the model sets them."""
    written = {name for section in _sections(source, "statistic") for name in section}
    if "meanmass" not in written and model.nbody > 1:
        total = 0.0
        for mass in model.body_mass[1:]:
            total += float(mass)
        model.stat.meanmass = total / (model.nbody - 1)
    if "meaninertia" not in written and model.nv > 0:
        total = 0.0
        for inertia in model.dof_M0:
            total += float(inertia)
        model.stat.meaninertia = total / model.nv


def _mapped(
    model: mujoco.MjModel,
    before: Mujoco,
    after: Mujoco,
    changes: list[tuple[str, str, int, tuple[float, ...]]],
) -> str | None:
    """Fill ``changes`` (field, attribute, row, numbers); the first change it cannot map."""
    pending: list[tuple[str, AnyElement, str, tuple[float, ...], int | None, tuple[int, ...]]] = []
    for problem in _differences(before, after, None, (), pending):
        return problem
    if not pending:
        return None
    rows = _Rows(before)
    for key, element, attribute, numbers, written, path in pending:
        if key == "body/inertial" and rows.inertia_settings:
            return f"the compiler's {rows.inertia_settings} changes how inertials compile"
        if key in ("body/joint", "body/inertial") and rows.springdamper:
            return "a springdamper sets stiffness and damping from the joints' masses"
        row = rows.row(path)
        if row is None:
            return f"cannot tell which compiled {key} the element at {path} is"
        field = FIELDS[key][attribute]
        array = getattr(model, field)
        whole = array.shape[1] if array.ndim == 2 else 1
        if len(numbers) != (whole if written is None else written) or len(numbers) > whole:
            # A shorter value takes the rest from its class: only a value as long as the
            # one it replaces (the same rest), or a whole row, is known in full.
            return f"<{element.tag}> {attribute} at {path}: {len(numbers)} numbers for {field}"
        if rows.before_4 and field not in _BEFORE_4:
            return f"MuJoCo before 4.0 derives statistics from {field}: <{element.tag}> {attribute}"
        if field.startswith("dof_"):
            count = {0: 6, 1: 3}.get(int(model.jnt_type[row]), 1)
            start = int(model.jnt_dofadr[row])
            changes.extend((field, attribute, start + i, numbers) for i in range(count))
        else:
            changes.append((field, attribute, row, numbers))
    return None


def _differences(
    before: AnyElement,
    after: AnyElement,
    context: str | None,
    path: tuple[int, ...],
    pending: list[tuple[str, AnyElement, str, tuple[float, ...], int | None, tuple[int, ...]]],
) -> Iterator[str]:
    """Collect mappable changes below two elements into ``pending``; yield what is not."""
    if before is after:
        return
    key = child_key(context, before.tag) if context is not None or before.tag == "mujoco" else None
    if before.tag != after.tag or key is None:
        yield f"<{after.tag}> at {path} changed"
        return
    if key.startswith("default"):  # a class reaches every element that uses it
        if before != after:
            yield f"the default class at {path} changed"
        return
    if getattr(before, "text", None) != getattr(after, "text", None):
        yield f"the text of <{after.tag}> at {path} changed"
        return
    old, new = dict(attribute_items(before)), dict(attribute_items(after))
    fields = FIELDS.get(key, {})
    for name in old.keys() | new.keys():
        if old.get(name) == new.get(name):
            continue
        numbers, written = numbers_of(new.get(name)), numbers_of(old.get(name))
        if name not in fields or numbers is None:
            yield f"<{after.tag}> {name} at {path}: {old.get(name)!r} -> {new.get(name)!r}"
            return
        pending.append(
            (key, before, name, numbers, None if written is None else len(written), path)
        )
    kept, made = _elements(before), _elements(after)
    if len(kept) != len(made):
        yield f"the children of <{after.tag}> at {path} changed"
        return
    for index, (old_child, new_child) in enumerate(zip(kept, made, strict=True)):
        yield from _differences(old_child, new_child, key, (*path, index), pending)


def _sections(model: Mujoco, tag: str) -> list[dict[str, object]]:
    """The attributes of each top-level ``tag`` section of ``model``."""
    return [dict(attribute_items(child)) for child in _elements(model) if child.tag == tag]


def _elements(element: AnyElement) -> list[AnyElement]:
    """The element children of ``element`` (comments left out)."""
    return [child for child in element.children if isinstance(child, Element)]


class _Rows:
    """Which compiled row each element of ``before`` is: MuJoCo's numbering, read once."""

    def __init__(self, before: Mujoco) -> None:
        import mujoco

        self.before = before
        settings = [
            name
            for section in _sections(before, "compiler")
            for name in section
            if name in _INERTIA_SETTINGS
        ]
        #: The compiler settings that change how inertials compile, as a list for people.
        self.inertia_settings = ", ".join(settings)
        #: Whether MuJoCo is older than 4.0 (see :data:`_BEFORE_4`).
        self.before_4 = int(mujoco.__version__.split(".")[0]) < 4

    @functools.cached_property
    def springdamper(self) -> bool:
        """Whether some joint or class has a ``springdamper`` (it sets stiffness and damping)."""
        return any(
            get_attribute(element, "springdamper") is not None
            for element, _, _ in keyed_walk(self.before)
        )

    def row(self, path: tuple[int, ...]) -> int | None:
        """The compiled row of the geom, joint, inertial (its body) or actuator at ``path``."""
        return _numbering(self.before).get(path)


#: The numbering of the last few models asked about, by ``id`` (each kept with its model,
#: so an ``id`` is not reused while its entry stands).
_NUMBERINGS: BoundedCache[int, tuple[Mujoco, dict[tuple[int, ...], int]]] = BoundedCache(8)


def _numbering(before: Mujoco) -> dict[tuple[int, ...], int]:
    """The compiled row of each geom, joint, inertial (its body) and actuator, by path.

    Every such element gets a unique name in a copy that MuJoCo compiles (names do
    not change the numbering), so MuJoCo itself says which row is whose. The last
    few models asked about are remembered: a variant loop asks about one.
    """
    known = _NUMBERINGS.get(id(before))
    if known is not None and known[0] is before:
        return known[1]
    import mujoco

    labels: dict[tuple[str, str], tuple[int, ...]] = {}
    named = _labelled(before, None, (), labels)
    compiled_model = compiled(named)
    kinds = {
        "geom": mujoco.mjtObj.mjOBJ_GEOM,
        "joint": mujoco.mjtObj.mjOBJ_JOINT,
        "body": mujoco.mjtObj.mjOBJ_BODY,
        "actuator": mujoco.mjtObj.mjOBJ_ACTUATOR,
    }
    rows: dict[tuple[int, ...], int] = {}
    for (kind, label), path in labels.items():
        row = mujoco.mj_name2id(compiled_model, kinds[kind], label)
        if row >= 0:
            rows[path] = row
    return _NUMBERINGS.remember(id(before), (before, rows))[1]


def _labelled(
    element: AnyElement,
    context: str | None,
    path: tuple[int, ...],
    labels: dict[tuple[str, str], tuple[int, ...]],
) -> Any:
    """``element`` with every geom, joint, body and actuator below it named ``mjcf_patch_*``.

    ``labels`` gets the path of each (object type, name); a body's is its inertial's path.
    """
    key = (
        child_key(context, element.tag) if context is not None or element.tag == "mujoco" else None
    )
    if key is None or key.startswith("default") or element.tag == "replicate":
        return element  # a replicate's copies would share a label (and are compiled again)
    elements = iter(_elements(element))
    inertial = None
    children: list[Any] = []
    for index, child in enumerate(elements):
        if child.tag == "inertial":
            inertial = (*path, index)
        children.append(_labelled(child, key, (*path, index), labels))
    labelled = with_children(element, children)
    if key == "body" and inertial is not None:
        target, kind = inertial, "body"
    elif key in ("body/geom", "body/joint"):
        target, kind = path, key.removeprefix("body/")
    elif key.startswith("actuator/"):
        target, kind = path, "actuator"
    else:
        return labelled
    name = get_attribute(element, "name")
    if name:  # named already: MuJoCo finds it by that name (references to it stay right)
        labels[(kind, str(name))] = target
        return labelled
    label = f"mjcf_patch_{kind}_{len(labels)}"
    labels[(kind, label)] = target
    return with_attributes(labelled, {"name": label})
