"""Variants without recompiling: write a model's changed values into its compiled arrays.

Physical randomisation mostly changes values a compiled model holds one for one: a
geom's colour and contact parameters, a joint's damping, an actuator's gains, a
body's explicit mass. :func:`patched` finds what changed between two models (the
unchanged subtrees they share are skipped), writes each change into a copy of the
compiled model, and recomputes what MuJoCo derives from it (``mj_setConst``, the
stiffness and damping of ``springdamper`` joints, the damping of ``dampratio`` servos,
and the mean mass and inertia of ``<statistic>``). A value changed in a default class is
written into exactly the elements that take it from that class. A variant made by
:func:`mjcf_model.scaled` from the model itself is written as every array times its
unit's factor (:mod:`mjcf_model.bridge.scale_patching`). Anything else (a new element or
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
import math
import warnings
from collections.abc import Iterator
from typing import TYPE_CHECKING

import numpy

from mjcf_model.bridge.compiling import compiled
from mjcf_model.bridge.numbering import numbering
from mjcf_model.bridge.scale_patching import (
    Scaling,
    restore_scaled,
    scaled_model,
    scaling_of,
    scratch_data,
)
from mjcf_model.caching import BoundedCache, IdentityCache
from mjcf_model.errors import MjcfRecompiledWarning
from mjcf_model.nodes.base import (
    AnyElement,
    Element,
    TypedElement,
    attribute_items,
    get_attribute,
)
from mjcf_model.nodes.root import Mujoco
from mjcf_model.schema.namespaces import child_key
from mjcf_model.serializers.locations import element_at
from mjcf_model.tree.defaults import ACTUATOR_DEFAULT_TAGS, DefaultClasses
from mjcf_model.values import Value, numbers_of

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
        ``before`` wrote, or when ``after`` is ``scaled(before, factor, mass=...)``
        with one factor (then to a millionth of each array's scale: a compile rounds
        the scaled 32-bit mesh vertices again; see
        :mod:`mjcf_model.bridge.scale_patching`), else compiled in full (with a
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
    scaling = scaling_of(after)
    if scaling is not None and scaling.source is before:
        outcome = _scaled_variant(model, before, after, scaling, into)
    else:
        outcome = _physical_variant(model, before, after, into)
    if isinstance(outcome, str):
        warnings.warn(
            f"patched() compiles the model again: {_readable(outcome, after)}",
            MjcfRecompiledWarning,
            stacklevel=2,
        )
        return compiled(after)
    return outcome


def _readable(message: str, root: AnyElement) -> str:
    """``message`` with each element it names by index path (``at (0, 2)``) named by path.

    The index path counts element children only, as the comparison walks them.

    Examples:
        >>> from mjcf_model import loads
        >>> model = loads('<mujoco><worldbody><!-- a --><geom name="g"/></worldbody></mujoco>')
        >>> _readable("<geom> size at (0, 0): '1' -> '2'", model)
        "<geom> size at /mujoco/worldbody/geom[@name='g']: '1' -> '2'"

    """
    pieces, rest = [], message
    while (start := rest.find("at (")) >= 0:
        end = rest.find(")", start)
        inside = rest[start + 4 : end].rstrip(",").split(", ") if end > start else []
        where = _element_path(root, inside) if all(p.isdigit() for p in inside) else None
        if where is None:
            pieces.append(rest[: start + 4])
            rest = rest[start + 4 :]
            continue
        pieces.append(rest[:start] + f"at {where}")
        rest = rest[end + 1 :]
    return "".join(pieces) + rest


def _element_path(root: AnyElement, indices: list[str]) -> str | None:
    """The element path of the element at ``indices`` among element children; ``None``: none."""
    current, children_path = root, []
    for index in map(int, indices):
        positions = [i for i, c in enumerate(current.children) if isinstance(c, Element)]
        if index >= len(positions):
            return None
        children_path.append(positions[index])
        child = current.children[positions[index]]
        assert isinstance(child, Element)
        current = child
    found = element_at(root, tuple(children_path))
    return found[1] if found is not None and indices else None


def _scaled_variant(
    model: mujoco.MjModel,
    before: Mujoco,
    after: Mujoco,
    scaling: Scaling,
    into: mujoco.MjModel | None,
) -> mujoco.MjModel | str:
    """``model`` scaled as ``after`` is ``before`` scaled; or why it must be compiled."""
    if len(set(scaling.factors)) > 1:
        return f"scaled by {scaling.factors}: per-axis factors are compiled"
    if scaling.surface_masses:
        return (
            f"{scaling.surface_masses[0]} spreads its mass over its surface, which"
            ' mass="volume" scales with the area'
        )
    springs, problem = _springdampers(before)
    servos = _position_servos(before)
    problem = problem or _damp_ratios(before)[1] or (servos if isinstance(servos, str) else None)
    if problem is not None or isinstance(servos, str):
        return problem or "unreachable"
    result = scaled_model(model, after, scaling.factors[0], scaling.mass, into, servos=servos)
    if isinstance(result, str):
        return result
    _spring_dampers(result, springs)
    _position_dampings(result, _damp_ratios(before)[0])
    return result


def _physical_variant(
    model: mujoco.MjModel, before: Mujoco, after: Mujoco, into: mujoco.MjModel | None
) -> mujoco.MjModel | str:
    """``model`` changed as ``after`` differs from ``before``; or why it must be compiled."""
    import mujoco

    changes: list[tuple[str, str, int, tuple[float, ...]]] = []
    problem = _mapped(model, before, after, changes)
    if problem is not None:
        return problem
    if into is None:
        result = copy.copy(model)
    else:
        result = into
        restore_scaled(model, into)  # an earlier scaled variant wrote every float array
        for field in _PATCHED:  # what an earlier variant wrote goes back to the model's
            getattr(result, field)[...] = getattr(model, field)
    # One assignment per field and length of value (a later change of a row wins).
    grouped: dict[tuple[str, int], tuple[list[int], list[tuple[float, ...]]]] = {}
    for field, _, row, numbers in changes:
        rows, values = grouped.setdefault((field, len(numbers)), ([], []))
        rows.append(row)
        values.append(numbers)
    for (field, count), (rows, values) in grouped.items():
        array = getattr(result, field)
        if array.ndim == 1:
            array[rows] = [numbers[0] for numbers in values]
        else:
            array[rows, :count] = values
    # A model patched before may hold what an earlier variant derived: derive it all again
    # (before MuJoCo 4.0 only fields that derive nothing are patched).
    again = into is not None and int(mujoco.__version__.split(".")[0]) >= 4
    if again or any(field in ("geom_margin", "geom_gap") for field, _, _, _ in changes):
        _body_margins(result)
    if again or any(field not in _LOCAL for field, _, _, _ in changes):
        mujoco.mj_setConst(result, scratch_data(result))
        _restate(result, before)
        _position_dampings(result, _damp_ratios(before)[0])
    _spring_dampers(result, _springdampers(before)[0])
    return result


def _spring_dampers(model: mujoco.MjModel, joints: list[tuple[int, float, float]]) -> None:
    """The stiffness and damping MuJoCo's compiler derives from each joint's ``springdamper``.

    As the compiler computes them (``mjCModel::AutoSpringDamper``), from the joint's
    ``dof_invweight0`` as :func:`mujoco.mj_setConst` left it: the mean inertia of its
    degrees of freedom, a time constant and a damping ratio (``joints``: the joint's row,
    its time constant and its ratio). They replace any written stiffness and damping.
    """
    for row, timeconst, dampratio in joints:
        start = int(model.jnt_dofadr[row])
        count = {0: 6, 1: 3}.get(int(model.jnt_type[row]), 1)
        total = 0.0
        for dof in range(start, start + count):
            total += float(model.dof_invweight0[dof])
        inertia = count / max(_MINVAL, total)
        model.jnt_stiffness[row] = inertia / max(
            _MINVAL, timeconst * timeconst * dampratio * dampratio
        )
        model.dof_damping[start : start + count] = 2 * inertia / max(_MINVAL, timeconst)


#: MuJoCo's ``mjMINVAL``: the least divisor its compiler divides by.
_MINVAL = 1e-15


def _body_margins(model: mujoco.MjModel) -> None:
    """Each body's margin: the largest margin plus gap of its geoms, as MuJoCo compiles it."""
    model.body_margin[:] = 0
    numpy.maximum.at(model.body_margin, model.geom_bodyid, model.geom_margin + model.geom_gap)


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
    pending: list[_Pending] = []
    classes_changed: list[tuple[int, ...]] = []
    problem = _differences(before, after, None, (), pending, classes_changed)
    if problem is not None:
        return problem
    if classes_changed:
        unmapped = _class_changes(model, before, after, pending)
        if unmapped is not None:
            return unmapped
    if not pending:
        return None
    rows = _Rows(before)
    springs = _springdampers(before)[1] or _damp_ratios(before)[1]
    if springs is not None:
        return springs
    for key, element, attribute, numbers, written, path in pending:
        if key == "body/inertial" and rows.inertia_settings:
            return f"the compiler's {rows.inertia_settings} changes how inertials compile"
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


#: A change to write: the element's key, the element, the attribute, its new numbers, how
#: many numbers the compiled row took from what was written before (``None``: none, the
#: whole row is MuJoCo's default), and the element's path.
_Pending = tuple[str, AnyElement, str, tuple[float, ...], int | None, tuple[int, ...]]


def _differences(
    before: AnyElement,
    after: AnyElement,
    context: str | None,
    path: tuple[int, ...],
    pending: list[_Pending],
    classes_changed: list[tuple[int, ...]],
) -> str | None:
    """Collect mappable changes below two elements into ``pending``; the first that is not.

    A changed ``<default>`` is noted in ``classes_changed`` (see :func:`_class_changes`).
    """
    if before is after:
        return None
    key = child_key(context, before.tag) if context is not None or before.tag == "mujoco" else None
    if before.tag != after.tag or key is None:
        return f"<{after.tag}> at {path} changed"
    if key.startswith("default"):  # a class reaches every element that uses it
        if before != after:
            classes_changed.append(path)
        return None
    if getattr(before, "text", None) != getattr(after, "text", None):
        return f"the text of <{after.tag}> at {path} changed"
    fields = FIELDS.get(key, {})
    for name, was, now in _changed_attributes(before, after):
        numbers, written = numbers_of(now), numbers_of(was)
        if name not in fields or numbers is None:
            return f"<{after.tag}> {name} at {path}: {was!r} -> {now!r}"
        pending.append(
            (key, before, name, numbers, None if written is None else len(written), path)
        )
    kept, made = before.children, after.children
    if kept is made:
        return None
    if len(kept) != len(made):
        return _differences_by_elements(before, after, key, path, pending, classes_changed)
    index = 0
    for old_child, new_child in zip(kept, made, strict=True):
        if old_child is new_child:  # shared: unchanged (a comment, too, keeps its place)
            if isinstance(old_child, Element):
                index += 1
            continue
        if not isinstance(old_child, Element) or not isinstance(new_child, Element):
            return _differences_by_elements(before, after, key, path, pending, classes_changed)
        problem = _differences(old_child, new_child, key, (*path, index), pending, classes_changed)
        if problem is not None:
            return problem
        index += 1
    return None


def _differences_by_elements(
    before: AnyElement,
    after: AnyElement,
    key: str,
    path: tuple[int, ...],
    pending: list[_Pending],
    classes_changed: list[tuple[int, ...]],
) -> str | None:
    """:func:`_differences` of the children, paired element by element (comments moved)."""
    kept, made = _elements(before), _elements(after)
    if len(kept) != len(made):
        return f"the children of <{after.tag}> at {path} changed"
    for index, (old_child, new_child) in enumerate(zip(kept, made, strict=True)):
        problem = _differences(old_child, new_child, key, (*path, index), pending, classes_changed)
        if problem is not None:
            return problem
    return None


def _changed_attributes(
    before: AnyElement, after: AnyElement
) -> list[tuple[str, Value | None, Value | None]]:
    """Each attribute whose value differs between two elements: its name, old and new value.

    Two typed elements of one class with the same ``extra`` are compared by the fields
    they store (a variant changes a few of them); any others by their attribute items.
    """
    if (
        type(before) is type(after)
        and isinstance(before, TypedElement)
        and isinstance(after, TypedElement)
        and before.extra == after.extra
    ):
        info = type(before).__node_info__
        rank, names, held, holding = info.rank, info.names, before.__dict__, after.__dict__
        changed: list[tuple[str, Value | None, Value | None]] = []
        shared = 0
        for field, was in held.items():
            if field in holding:
                shared += 1
            now = holding.get(field)
            if now is not was and field in rank and now != was:
                changed.append((names[rank[field]], was, now))
        if shared != len(holding):  # fields only the variant stores
            changed += [
                (names[rank[field]], None, holding[field])
                for field in holding.keys() - held.keys()
                if field in rank and holding[field] is not None
            ]
        return changed
    old, new = dict(attribute_items(before)), dict(attribute_items(after))
    return [
        (name, old.get(name), new.get(name))
        for name in old.keys() | new.keys()
        if old.get(name) != new.get(name)
    ]


def _sections(model: Mujoco, tag: str) -> list[dict[str, object]]:
    """The attributes of each top-level ``tag`` section of ``model``."""
    return [dict(attribute_items(child)) for child in _elements(model) if child.tag == tag]


def _elements(element: AnyElement) -> list[AnyElement]:
    """The element children of ``element`` (comments left out)."""
    return [child for child in element.children if isinstance(child, Element)]


def _class_changes(
    model: mujoco.MjModel, before: Mujoco, after: Mujoco, pending: list[_Pending]
) -> str | None:
    """Add to ``pending`` what changed default classes change; the first change they cannot.

    The classes must keep their names, nesting and default elements, and each changed
    default value its count of numbers (or, newly written, fill a whole row). Each geom,
    joint and actuator is then resolved as MuJoCo resolves it (:func:`_resolved`) in both
    models: where the value it takes from its classes differs, that element changes, and
    only that one.
    """
    old, new = DefaultClasses.of(before), DefaultClasses.of(after)
    same_layers = all(len(held) == len(new.layers.get(key, ())) for key, held in old.layers.items())
    if dict(old.parents) != dict(new.parents) or old.layers.keys() != new.layers.keys():
        same_layers = False
    if not same_layers:
        return "a default class, or a default element in one, was added or removed"
    changed: dict[str, set[str]] = {}  # by the tag elements read defaults for
    layers = [
        (name, tag, setting, variant)
        for (name, tag), held in old.layers.items()
        for setting, variant in zip(held, new.layers[name, tag], strict=True)
    ]
    for name, tag, setting, variant in layers:
        was, now = dict(attribute_items(setting)), dict(attribute_items(variant))
        for attribute in was.keys() | now.keys():
            if was.get(attribute) == now.get(attribute):
                continue
            numbers, written = numbers_of(now.get(attribute)), numbers_of(was.get(attribute))
            whole = written is None and len(numbers or ()) == _row_width(model, tag, attribute)
            if numbers is None or not (whole or (written and len(numbers) == len(written))):
                return (
                    f"<{tag}> {attribute} of default class {name!r}:"
                    f" {was.get(attribute)!r} -> {now.get(attribute)!r}"
                )
            reader = "actuator" if tag in ACTUATOR_DEFAULT_TAGS else tag
            changed.setdefault(reader, set()).add(attribute)
    for key, element, ancestors, variant, variant_ancestors, path in _paired_walk(before, after):
        fields = FIELDS.get(key)
        if fields is None or key == "body/inertial":
            continue
        reader = "actuator" if key.startswith("actuator/") else element.tag
        for attribute in sorted(changed.get(reader, ())):
            taken = _resolved(old, element, ancestors, reader, attribute)
            taking = _resolved(new, variant, variant_ancestors, reader, attribute)
            if taken == taking:
                continue
            if attribute not in fields or taking is None:
                return f"<{element.tag}> {attribute} at {path}, changed by its default class"
            count = None if taken is None else len(taken)
            pending.append((key, element, attribute, taking, count, path))
    return None


def _row_width(model: mujoco.MjModel, tag: str, attribute: str) -> int | None:
    """How many numbers the compiled row of a default ``<tag>``'s ``attribute`` holds.

    ``None`` when the attribute maps to no array (see :data:`FIELDS`).
    """
    key = f"actuator/{tag}" if tag in ACTUATOR_DEFAULT_TAGS else f"body/{tag}"
    field = FIELDS.get(key, {}).get(attribute)
    if field is None:
        return None
    array = getattr(model, field)
    return int(array.shape[1]) if array.ndim == 2 else 1


def _resolved(
    classes: DefaultClasses,
    element: AnyElement,
    ancestors: tuple[AnyElement, ...],
    reader: str,
    attribute: str,
) -> tuple[float, ...] | None:
    """The numbers ``attribute`` of ``element`` compiles from, as far as they are written.

    MuJoCo starts from the default elements of the element's classes, outermost first
    (``reader`` names which: a tag, or ``"actuator"``), and each written value replaces
    as many numbers as it holds; the element's own value goes last. ``None`` when
    nothing is written (the row is MuJoCo's own default).
    """
    row: list[float] = []
    name = classes.class_of(element, ancestors)
    for setting in (*classes.settings_along(name, reader), element):
        numbers = numbers_of(get_attribute(setting, attribute))
        if numbers:
            row[: len(numbers)] = numbers
    return tuple(row) if row else None


def _paired_walk(
    before: AnyElement, after: AnyElement
) -> Iterator[
    tuple[
        str, AnyElement, tuple[AnyElement, ...], AnyElement, tuple[AnyElement, ...], tuple[int, ...]
    ]
]:
    """Each element of two models of the same shape outside ``<default>``, with the other's.

    Yields the key, the element, its ancestors, the element at its place in ``after``,
    that one's ancestors, and the path (as :func:`_differences` numbers it).
    """
    stack: list[
        tuple[
            AnyElement,
            AnyElement,
            str | None,
            tuple[AnyElement, ...],
            tuple[AnyElement, ...],
            tuple[int, ...],
        ]
    ] = [(before, after, None, (), (), ())]
    while stack:
        was, now, context, above, above_now, path = stack.pop()
        key = child_key(context, was.tag) if context is not None or was.tag == "mujoco" else None
        if key is None or key.startswith("default"):
            continue
        yield key, was, above, now, above_now, path
        pairs = zip(_elements(was), _elements(now), strict=True)
        inner, inner_now = (*above, was), (*above_now, now)
        for index, (old_child, new_child) in enumerate(pairs):
            stack.append((old_child, new_child, key, inner, inner_now, (*path, index)))


def _springdampers(before: Mujoco) -> tuple[list[tuple[int, float, float]], str | None]:
    """The joints of ``before`` whose stiffness and damping a ``springdamper`` sets.

    Each as its compiled row, time constant and damping ratio (both positive: MuJoCo
    ignores the setting otherwise); and what stops a patch, when such a joint has no
    row this module can tell (inside a ``<replicate>``). Remembered per model.
    """
    known = _SPRINGS.get(id(before))
    if known is not None and known[0] is before:
        return known[1]
    classes = DefaultClasses.of(before)
    joints: list[tuple[int, float, float]] = []
    problem: str | None = None
    if classes.sets("joint") or any(
        get_attribute(element, "springdamper") is not None
        for key, element, *_ in _paired_walk(before, before)
        if key == "body/joint"
    ):
        rows = _numbering(before)
        for key, element, ancestors, *_, path in _paired_walk(before, before):
            if key != "body/joint":
                continue
            setting = _resolved(classes, element, ancestors, "joint", "springdamper")
            if setting is None or len(setting) < 2 or min(setting[:2]) <= 0:
                continue
            row = rows.get(path)
            if row is None:
                problem = f"cannot tell which compiled joint the springdamper at {path} sets"
                break
            joints.append((row, setting[0], setting[1]))
        joints.sort()
    return _SPRINGS.remember(id(before), (before, (joints, problem)))[1]


def _damp_ratios(before: Mujoco) -> tuple[list[tuple[int, float]], str | None]:
    """The actuators of ``before`` whose damping MuJoCo derives from a damping ratio.

    A position servo's ``dampratio`` (or a positive third ``biasprm``) is a ratio the
    compiler turns into a damping from the masses it moves. Each as its compiled row
    and ratio: the last of ``biasprm``, ``kv`` and ``dampratio`` written along its
    classes, outermost first, then on the element, sets it. And what stops a patch,
    when such an actuator has no row this module can tell. Remembered per model.
    """
    return _RATIOS.recall_for(before, lambda: _find_damp_ratios(before))


def _find_damp_ratios(before: Mujoco) -> tuple[list[tuple[int, float]], str | None]:
    """What :func:`_damp_ratios` answers, computed."""
    classes = DefaultClasses.of(before)
    actuators = [
        (element, ancestors, path)
        for key, element, ancestors, *_, path in _paired_walk(before, before)
        if key.startswith("actuator/")
    ]
    found: list[tuple[int, float]] = []
    rows: dict[tuple[int, ...], int] | None = None
    for element, ancestors, path in actuators:
        name = classes.class_of(element, ancestors)
        ratio = 0.0
        for setting in (*classes.settings_along(name, "actuator"), element):
            bias = numbers_of(get_attribute(setting, "biasprm"))
            if bias is not None and len(bias) >= 3:
                ratio = bias[2]
            kv = numbers_of(get_attribute(setting, "kv"))
            if kv:
                ratio = -kv[0]
            damp = numbers_of(get_attribute(setting, "dampratio"))
            if damp:
                ratio = damp[0]
        if ratio <= 0:
            continue
        rows = _numbering(before) if rows is None else rows
        row = rows.get(path)
        if row is None:
            return [], f"cannot tell which compiled actuator the damping ratio at {path} sets"
        found.append((row, ratio))
    return sorted(found), None


def _position_servos(before: Mujoco) -> list[int] | str:
    """The compiled rows of the ``<position>`` actuators of ``before`` on a joint.

    Its controls and ``ctrlrange`` (its own or its class's: ``scaled`` writes either,
    scaled, on the actuator) are lengths on a slide joint; or what stops a patch, when
    such an actuator has no row this module can tell.
    """
    return _SERVOS.recall_for(before, lambda: _find_position_servos(before))


def _find_position_servos(before: Mujoco) -> list[int] | str:
    """What :func:`_position_servos` answers, computed."""
    servos: list[int] = []
    rows: dict[tuple[int, ...], int] | None = None
    for key, element, *_, path in _paired_walk(before, before):
        if key != "actuator/position" or get_attribute(element, "joint") is None:
            continue
        rows = _numbering(before) if rows is None else rows
        row = rows.get(path)
        if row is None:
            return f"cannot tell which compiled actuator the <position> at {path} is"
        servos.append(row)
    return sorted(servos)


#: What :func:`_position_servos` found for the last few models.
_SERVOS: IdentityCache[list[int] | str] = IdentityCache(8)


#: What :func:`_damp_ratios` found for the last few models.
_RATIOS: IdentityCache[tuple[list[tuple[int, float]], str | None]] = IdentityCache(8)


def _position_dampings(model: mujoco.MjModel, actuators: list[tuple[int, float]]) -> None:
    """The damping MuJoCo's compiler derives from each position servo's damping ratio.

    As the compiler computes it at ``qpos0``: ``2 * ratio * sqrt(kp * mass)``, the mass
    being each moved degree of freedom's ``dof_M0`` over its transmission squared
    (``actuators``: each servo's row and ratio); only where ``biasprm`` is
    ``-gainprm`` and the gain and bias are fixed and affine, as MuJoCo requires.
    """
    if not actuators:
        return
    import mujoco

    data = scratch_data(model)
    mujoco.mj_kinematics(model, data)
    mujoco.mj_comPos(model, data)
    mujoco.mj_tendon(model, data)
    mujoco.mj_transmission(model, data)
    for row, ratio in actuators:
        gain, bias = model.actuator_gainprm[row], model.actuator_biasprm[row]
        if (
            model.actuator_gaintype[row] != int(mujoco.mjtGain.mjGAIN_FIXED)
            or model.actuator_biastype[row] != int(mujoco.mjtBias.mjBIAS_AFFINE)
            or gain[0] != -bias[1]
        ):
            continue
        start, count = int(data.moment_rowadr[row]), int(data.moment_rownnz[row])
        mass = 0.0
        for entry in range(start, start + count):
            lever = abs(float(data.actuator_moment[entry]))
            if lever * lever > _MINVAL:
                mass += float(model.dof_M0[data.moment_colind[entry]]) / (lever * lever)
        bias[2] = -(ratio * 2 * math.sqrt(gain[0] * mass))


#: What :func:`_springdampers` found for the last few models, by ``id`` (kept with the model).
_SPRINGS: BoundedCache[int, tuple[Mujoco, tuple[list[tuple[int, float, float]], str | None]]] = (
    BoundedCache(8)
)


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

    def row(self, path: tuple[int, ...]) -> int | None:
        """The compiled row of the geom, joint, inertial (its body) or actuator at ``path``."""
        return _numbering(self.before).get(path)


def _numbering(before: Mujoco) -> dict[tuple[int, ...], int]:
    """The compiled row of each geom, joint, inertial (its body's) and actuator, by path.

    The paths count element children only (comments left out), as :func:`_paired_walk`
    numbers them; :func:`~mjcf_model.bridge.numbering.numbering` counts every child.
    """
    return _ELEMENT_ROWS.recall_for(before, lambda: _by_element_index(before))


#: What :func:`_numbering` found for the last few models.
_ELEMENT_ROWS: IdentityCache[dict[tuple[int, ...], int]] = IdentityCache(8)


def _by_element_index(before: Mujoco) -> dict[tuple[int, ...], int]:
    rows = numbering(before).rows
    found: dict[tuple[int, ...], int] = {}
    stack: list[tuple[AnyElement, tuple[int, ...], tuple[int, ...]]] = [(before, (), ())]
    while stack:
        element, path, counted = stack.pop()
        if path in rows:
            found[counted] = rows[path]
        elements = 0
        for index, child in enumerate(element.children):
            if isinstance(child, Element):
                stack.append((child, (*path, index), (*counted, elements)))
                elements += 1
    return found
