"""Per-world arrays for GPU simulators: the fields that differ between variants, stacked.

MJX and MuJoCo Warp simulate many worlds of one model at once, and randomise a model
field by giving it a leading world axis. :func:`batched` makes those arrays from
variants of one model: each variant is patched into one scratch copy of the compiled
base (:func:`~mjcf_model.patched`; compiled in full where it must be), and every field in
which some variant differs from the base is returned, one row per variant, named as
``MjModel`` names it.

>>> from mjcf_model import loads, map_elements, with_attributes
>>> robot = loads('<mujoco><worldbody><geom name="g" size="0.1"/></worldbody></mujoco>')
>>> def tinted(red):
...     def tint(element, key, ancestors):
...         is_geom = key == "body/geom"
...         return with_attributes(element, {"rgba": (red, 0, 0, 1)}) if is_geom else element
...     return map_elements(tint, robot)
>>> arrays = batched(robot, [tinted(0.25), tinted(0.75)])
>>> list(arrays), arrays["geom_rgba"].shape, arrays["geom_rgba"][:, 0, 0].tolist()
(['geom_rgba'], (2, 1, 4), [0.25, 0.75])
"""

from __future__ import annotations

import copy
import functools
from collections.abc import Sequence
from typing import Any

import numpy
from numpy.typing import NDArray

from mjcf_model.bridge.compare import (
    differing_fields,
    field_value,
    model_fields,
    struct_field_names,
)
from mjcf_model.bridge.compiling import compiled
from mjcf_model.bridge.patching import patched
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.root import Mujoco

__all__ = ["batched"]


def batched(base: Mujoco, variants: Sequence[Mujoco]) -> dict[str, NDArray[Any]]:
    """The fields in which ``variants`` differ from ``base``, stacked one row per variant.

    For simulators that step many worlds of one model (MJX, MuJoCo Warp): compile
    ``base``, hand it to the simulator, and replace each returned field by its array,
    whose first axis is the world. Row ``i`` of each array is the field of
    ``compiled(variants[i])``; every field not returned is the base's in every variant.

    Args:
        base: The model the variants were made from.
        variants: Models of the same structure as ``base``: the same elements, values
            changed (colours, friction, masses, gains, default classes... whatever
            :func:`~mjcf_model.patched` writes is written without a compile; any other
            change compiles that variant, with a
            :class:`~mjcf_model.MjcfRecompiledWarning`).

    Returns:
        A dict from ``MjModel`` field names (``"geom_rgba"``; ``"opt.timestep"`` and
        ``"stat.meanmass"`` for the fields of its structs) to arrays of shape
        ``(len(variants), *field.shape)``, sorted by name (the structs' fields last).

    Raises:
        MjcfValueError: a variant changes a size or count of the model (``ngeom``,
            ``nmeshvert``...) or the shape of a field: the worlds of one batch share one
            structure. The message names the first variant and field that do.

    Examples:
        >>> from mjcf_model import loads, map_elements, with_attributes
        >>> robot = loads('<mujoco><worldbody><body><joint/><geom size="0.1"/></body>'
        ...               '</worldbody></mujoco>')
        >>> def damped(value):
        ...     def damp(element, key, ancestors):
        ...         is_joint = key == "body/joint"
        ...         return with_attributes(element, {"damping": value}) if is_joint else element
        ...     return map_elements(damp, robot)
        >>> batched(robot, [damped(0.5), damped(2.0), robot])["dof_damping"].tolist()
        [[0.5], [2.0], [0.0]]

    """
    model = compiled(base)
    scratch = copy.copy(model)
    rows: list[dict[str, NDArray[Any]]] = []
    for index, variant in enumerate(variants):
        result = patched(model, base, variant, into=scratch)
        names = _patchable_fields() if result is scratch else _every_field()
        changed = {name: _field(result, name) for name in differing_fields(result, model, names)}
        for name, value in sorted(changed.items(), key=_sizes_first):
            was = _field(model, name)
            if not isinstance(value, numpy.ndarray) or value.shape != was.shape:
                raise MjcfValueError(
                    f"variant {index} changes {name} from {_shown(was)} to {_shown(value)}:"
                    " the worlds of one batch share the base model's sizes and counts"
                    " (batch the variants of each structure apart)"
                )
        rows.append({name: value.copy() for name, value in changed.items()})
    returned = {name for changed in rows for name in changed}
    return {
        name: numpy.stack([changed.get(name, _field(model, name)) for changed in rows])
        for name in _ordered(returned)
    }


#: The prefixes of the fields ``patched`` never writes and ``mj_setConst`` never derives:
#: meshes, textures, height fields, skins, bounding volumes, names and paths (the biggest
#: arrays of a model, left out of the comparison of a patched variant with its base).
_UNPATCHED_PREFIXES = ("mesh_", "tex_", "hfield_", "skin_", "bvh_", "oct_", "name", "path")


@functools.cache
def _every_field() -> tuple[str, ...]:
    """Every field :func:`~mjcf_model.bridge.compare.model_differences` compares."""
    return (*model_fields(), *struct_field_names())


@functools.cache
def _patchable_fields() -> tuple[str, ...]:
    """The fields a patched variant may change: arrays but the unpatched, ``opt`` and ``stat``.

    A patched variant keeps the base's sizes (MuJoCo's model is the same structure).
    """
    import mujoco

    empty = mujoco.MjModel.from_xml_string("<mujoco/>")
    return tuple(
        name
        for name in _every_field()
        if not name.startswith(("vis.", *_UNPATCHED_PREFIXES))
        and not name.endswith("_pathadr")
        and not isinstance(field_value(empty, name), int | bytes)
    )


def _field(model: Any, name: str) -> Any:
    """A field of a compiled model by its name; dotted for a struct's (``"opt.timestep"``).

    A struct's number comes as a 0-d array; a size of the model (``ngeom``) as it is.
    """
    value = field_value(model, name)
    return numpy.asarray(value) if "." in name else value


#: The sizes that count what a model's author writes, in the order a message names them
#: (before sizes MuJoCo derives from them, such as ``nbvh`` or ``nbuffer``).
_WRITTEN_COUNTS = (
    "nbody", "njnt", "ngeom", "nsite", "ncam", "nlight", "nflex", "nmesh", "nskin", "nhfield",
    "ntex", "nmat", "npair", "nexclude", "neq", "ntendon", "nu", "nsensor", "nnumeric",
    "ntext", "ntuple", "nkey", "nplugin",
)  # fmt: skip


def _sizes_first(item: tuple[str, Any]) -> tuple[int, int]:
    """Sort key: the counts an author writes, then other sizes, then what they size."""
    name, value = item
    if not isinstance(value, int):
        return (2, 0)
    if name in _WRITTEN_COUNTS:
        return (0, _WRITTEN_COUNTS.index(name))
    return (1, 0)


def _shown(value: Any) -> str:
    """A field's value for a message: a size as it is, an array by its shape."""
    return f"shape {value.shape}" if isinstance(value, numpy.ndarray) and value.ndim else str(value)


def _ordered(names: set[str]) -> list[str]:
    """``names`` sorted, the fields of ``MjModel`` itself before those of its structs."""
    return sorted(names, key=lambda name: (name.count("."), name))
