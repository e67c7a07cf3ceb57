"""Comparing compiled MuJoCo models field by field: the referee of every round trip.

>>> import mujoco
>>> a = mujoco.MjModel.from_xml_string("<mujoco><worldbody><geom size='1'/></worldbody></mujoco>")
>>> b = mujoco.MjModel.from_xml_string("<mujoco><worldbody><geom size='2'/></worldbody></mujoco>")
>>> model_differences(a, a), "geom_size" in model_differences(a, b)
([], True)
"""

from __future__ import annotations

import functools
import os
import tempfile
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np

__all__ = [
    "NAME_FIELDS",
    "compile_text_beside",
    "compiled_names",
    "differing_fields",
    "field_value",
    "model_differences",
    "model_fields",
    "path_fields",
    "struct_field_names",
]

#: Fields that describe how the model was loaded, not the model.
_IGNORED = frozenset({"signature"})


@functools.cache
def model_fields() -> tuple[str, ...]:
    """The names of ``MjModel``'s array and size fields, in a stable order.

    Examples:
        >>> "body_pos" in model_fields()
        True

    """
    import mujoco

    model = mujoco.MjModel.from_xml_string("<mujoco/>")
    names = []
    for name in dir(model):
        if name.startswith("_") or name in _IGNORED:
            continue
        value = getattr(model, name, None)
        if isinstance(value, (np.ndarray, int, float, bytes)):
            names.append(name)
    return tuple(sorted(names))


#: The fields that hold the name table, and the buffer size that grows with it:
#: renaming changes them and nothing else.
NAME_FIELDS = frozenset({"names", "names_map", "nnames", "nnames_map", "nbuffer"})


@functools.cache
def path_fields() -> frozenset[str]:
    """The fields that record the file paths assets were read from (``paths``, ``*_pathadr``).

    A model compiled from other paths to the same files (moved, bundled, read
    from an asset dictionary) differs in these and nothing else.

    Examples:
        >>> sorted(path_fields())[:3]
        ['hfield_pathadr', 'mesh_pathadr', 'nbuffer']

    """
    found = {name for name in model_fields() if name.endswith("_pathadr")}
    return frozenset({*found, "paths", "npaths", "nbuffer"})


def _name_address_fields() -> tuple[str, ...]:
    return tuple(name for name in model_fields() if name.startswith("name_"))


def compiled_names(model: Any) -> dict[str, list[str]]:
    """The name of every object of a compiled model, by kind (``"body"``, ``"mesh"``...).

    Unnamed objects have ``""``; the world body is ``"world"``.

    Examples:
        >>> import mujoco
        >>> m = mujoco.MjModel.from_xml_string(
        ...     "<mujoco><worldbody><geom name='g' size='1'/></worldbody></mujoco>")
        >>> compiled_names(m)["geom"], compiled_names(m)["body"]
        (['g'], ['world'])

    """
    table = bytes(model.names)
    names: dict[str, list[str]] = {}
    for field in _name_address_fields():
        kind = field[len("name_") : -len("adr")]
        names[kind] = [
            table[address : table.index(b"\0", address)].decode()
            for address in getattr(model, field)
        ]
    return names


def _struct_fields(value: Any) -> dict[str, Any]:
    return {
        name: getattr(value, name)
        for name in dir(value)
        if not name.startswith("_") and not callable(getattr(value, name))
    }


def _equal(a: Any, b: Any) -> bool:
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a, b = np.asarray(a), np.asarray(b)
        if a.shape != b.shape:
            return False
        if a.dtype == b.dtype and a.tobytes() == b.tobytes():
            return True  # the same bits (most fields of two models): equal, NaN and all
        if a.dtype.kind == "f":
            return bool(np.array_equal(a, b, equal_nan=True))
        return bool(np.array_equal(a, b))
    if isinstance(a, float) and isinstance(b, float) and a != a and b != b:
        return True
    return bool(a == b)


#: The groups of ``MjModel.vis`` whose fields are compared.
_VIS_GROUPS = ("global_", "quality", "headlight", "map", "scale", "rgba")


@functools.cache
def struct_field_names() -> tuple[str, ...]:
    """The fields of ``MjModel``'s ``opt``, ``stat`` and ``vis`` structs, dotted.

    Examples:
        >>> "opt.timestep" in struct_field_names(), "vis.global_.fovy" in struct_field_names()
        (True, True)

    """
    import mujoco

    model = mujoco.MjModel.from_xml_string("<mujoco/>")
    names = [
        f"{struct}.{name}"
        for struct in ("opt", "stat")
        for name in _struct_fields(getattr(model, struct))
    ]
    names += [
        f"vis.{group}.{name}"
        for group in _VIS_GROUPS
        for name in _struct_fields(getattr(model.vis, group))
    ]
    return tuple(names)


def field_value(model: Any, name: str) -> Any:
    """A field of a compiled model by name, dotted for a struct's (``"opt.timestep"``).

    Examples:
        >>> import mujoco
        >>> m = mujoco.MjModel.from_xml_string("<mujoco><option timestep='0.01'/></mujoco>")
        >>> field_value(m, "opt.timestep"), field_value(m, "nbody")
        (0.01, 1)

    """
    return functools.reduce(getattr, name.split("."), model)


def differing_fields(a: Any, b: Any, names: Iterable[str]) -> list[str]:
    """Which of the fields ``names`` differ between two ``MjModel`` objects (NaN equals NaN).

    Examples:
        >>> import mujoco
        >>> m = mujoco.MjModel.from_xml_string("<mujoco/>")
        >>> differing_fields(m, m, ["nbody", "opt.timestep"])
        []

    """
    return [name for name in names if not _equal(field_value(a, name), field_value(b, name))]


def model_differences(a: Any, b: Any, *, ignore: frozenset[str] = frozenset()) -> list[str]:
    """The names of the fields in which two ``MjModel`` objects differ.

    Compares every array and size field (the name table ``names`` included) and
    the ``opt``, ``vis`` and ``stat`` structs, exactly (NaN equals NaN), except
    the fields named in ``ignore`` (for instance :data:`NAME_FIELDS` and the
    ``name_*adr`` address arrays after a renaming).

    Examples:
        >>> import mujoco
        >>> m = mujoco.MjModel.from_xml_string("<mujoco/>")
        >>> model_differences(m, m)
        []

    """
    names = (*model_fields(), *struct_field_names())
    return differing_fields(a, b, [name for name in names if name not in ignore])


def compile_text_beside(text: str, original: str | os.PathLike[str]) -> Any:
    """Compile MJCF text as if it were the file ``original``.

    The text is written to a temporary file in the same directory, so relative
    mesh, texture and include paths resolve as they do for the original; the
    file is removed afterwards.

    Examples:
        >>> import pathlib, tempfile
        >>> path = pathlib.Path(tempfile.mkdtemp()) / "m.xml"
        >>> compile_text_beside("<mujoco/>", path).nbody
        1

    """
    import mujoco

    directory = Path(original).parent
    handle, temporary = tempfile.mkstemp(prefix=".mjcf-model-", suffix=".xml", dir=directory)
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as stream:
            stream.write(text)
        return mujoco.MjModel.from_xml_path(temporary)
    finally:
        os.unlink(temporary)
