"""robosuite's value helpers (number text, paths, sizes, dicts, ids), as robosuite wrote them."""

from __future__ import annotations

import os
from collections.abc import Iterable
from typing import Any, cast

import numpy as np
import numpy.typing as npt

from mjcf_model.compat.assets import assets_root

__all__ = [
    "add_to_dict",
    "array_to_string",
    "convert_to_string",
    "get_ids",
    "get_size",
    "normalize_scale_array",
    "save_sim_model",
    "string_to_array",
    "xml_path_completion",
]

#: The element types ``get_ids`` accepts.
_ID_TYPES = ["geom", "body", "joint", "site", "actuator", "sensor", "tendon", "camera", "light"]


def xml_path_completion(xml_path: str, root: str | None = None) -> str:
    """An absolute path (leading ``"/"``) stays; a relative one is joined to ``root``.

    ``root`` defaults to robosuite's ``models/assets``, found without importing
    robosuite.

    Raises:
        MjcfLookupError: ``root`` is not given and robosuite is not installed.

    Examples:
        >>> xml_path_completion("/abs/a.xml"), xml_path_completion("a.xml", root="/r")
        ('/abs/a.xml', '/r/a.xml')

    """
    if xml_path.startswith("/"):
        return xml_path
    if root is None:
        root = assets_root()
    return os.path.join(root, xml_path)


def array_to_string(array: Iterable[Any]) -> str:
    """Each item formatted with ``"{}".format``, joined by single spaces.

    Examples:
        >>> array_to_string([0.5, 0, True]), array_to_string(np.array([0.5, 0]))
        ('0.5 0 True', '0.5 0.0')

    """
    return " ".join([f"{x}" for x in array])


def string_to_array(string: str) -> npt.NDArray[Any]:
    """Numbers separated by single spaces as a float array; ``"None"`` items stay ``None``.

    Raises:
        ValueError: Two spaces in a row, tabs, newlines or an empty string (as robosuite).

    Examples:
        >>> string_to_array("1 None 2")
        array([1.0, None, 2.0], dtype=object)

    """
    return np.array([float(x) if x != "None" else None for x in string.strip().split(" ")])


def parse_numbers(string: str) -> npt.NDArray[Any]:
    """:func:`string_to_array` with any white space between numbers, as the tree functions read."""
    tokens = string.split()
    if not tokens:
        raise ValueError("could not convert string to float: ''")
    return np.array([float(x) if x != "None" else None for x in tokens])


def text_of(value: Any, *, exact: bool) -> str | None:
    """The text of ``convert_to_string``'s rule, or ``None`` where it has none.

    ``exact`` checks types exactly, as robosuite does; without it (for the object
    classes) subclasses count and numpy scalars are read as Python numbers first.
    """
    if type(value) is str:  # the common case, first
        return value

    def kind(*types: type) -> bool:
        return type(value) in types if exact else isinstance(value, types)

    if kind(str, np.str_):
        return cast(str, value)
    if kind(list, tuple, np.ndarray):
        return array_to_string(value)
    if not exact and isinstance(value, np.generic):
        value = value.item()
    if kind(int, float, bool):
        return str(value).lower()
    return None


def convert_to_string(inp: Any) -> str:
    """Attribute text for a list, tuple, array, int, float, bool or string.

    Types are checked exactly, as in robosuite: numpy scalars and ``None`` are refused.

    Raises:
        ValueError: Any other type.

    Examples:
        >>> convert_to_string(True), convert_to_string([True, 2]), convert_to_string(1e-8)
        ('true', 'True 2', '1e-08')

    """
    text = text_of(inp, exact=True)
    if text is None:
        raise ValueError(f"Unsupported type received: got {type(inp)}")
    return text


def get_size(
    size: Any,
    size_max: Any,
    size_min: Any,
    default_max: Any,
    default_min: Any,
    rng: Any = None,
) -> npt.NDArray[Any]:
    """``size`` as an array, or one drawn uniformly between the minimum and maximum.

    One ``rng.uniform(low, high)`` call per value, in order, as robosuite draws;
    the bounds default to ``default_max``/``default_min``, whose length is the size's.

    Raises:
        ValueError: The defaults differ in length, or ``size`` is given with bounds.

    Examples:
        >>> get_size(None, None, None, [0.07] * 2, [0.03] * 2, np.random.default_rng(0))
        array([0.05547847, 0.04079147])

    """
    if len(default_max) != len(default_min):
        raise ValueError(
            f"default_max = {default_max!s} and default_min = {default_min!s}"
            " have different lengths"
        )
    if size is not None:
        if (size_max is not None) or (size_min is not None):
            raise ValueError(
                f"size = {size} overrides size_max = {size_max}, size_min = {size_min}"
            )
    else:
        if size_max is None:
            size_max = default_max
        if size_min is None:
            size_min = default_min
        if rng is None:  # made only to draw (robosuite makes it in any case)
            rng = np.random.default_rng()
        size = np.array([rng.uniform(size_min[i], size_max[i]) for i in range(len(default_max))])
    return np.array(size)


def add_to_dict(
    dic: dict[Any, list[Any]],
    fill_in_defaults: bool = True,
    default_value: Any = None,
    **kwargs: Any,
) -> dict[Any, list[Any]]:
    """Append each keyword's value to the list ``dic[key]``; changes and returns ``dic``.

    With ``fill_in_defaults``, unmentioned lists get ``default_value`` appended,
    and a new key's list is padded with ``n`` of them, ``n`` being (robosuite's
    quirk, kept) the length of the first existing *key* in set order.

    Examples:
        >>> d = {}
        >>> for values in ({"a": 1, "b": 2}, {"a": 3, "c": 4}, {"b": 5}):
        ...     d = add_to_dict(d, **values)
        >>> d
        {'a': [1, 3, None], 'b': [2, None, 5], 'c': [None, 4, None]}

    """
    keys = set(dic.keys())
    n = len(next(iter(keys))) if keys else 0
    for k, v in kwargs.items():
        if k in dic:
            dic[k].append(v)
            keys.remove(k)
        else:
            dic[k] = [default_value] * n + [v] if fill_in_defaults else [v]
    if fill_in_defaults:
        for k in keys:
            dic[k].append(default_value)
    return dic


def save_sim_model(sim: Any, fname: str) -> None:
    """Write ``sim``'s model to ``fname`` with ``sim.save(file=f, format="xml")`` (mujoco-py's API).

    Examples:
        >>> import tempfile, types
        >>> sim = types.SimpleNamespace(save=lambda file, format: file.write("<mujoco/>"))
        >>> path = os.path.join(tempfile.mkdtemp(), "m.xml")
        >>> save_sim_model(sim, path)
        >>> open(path).read()
        '<mujoco/>'

    """
    with open(fname, "w") as f:
        sim.save(file=f, format="xml")


def get_ids(
    sim: Any, elements: Any, element_type: str = "geom", inplace: bool = False
) -> list[Any]:
    """The ids of ``elements`` (names or ids, one or a list) from ``sim.model.<type>_name2id``.

    Always a list; ints are kept; ``inplace`` replaces the items of the given list.

    Raises:
        AssertionError: An unknown ``element_type``.

    Examples:
        >>> import types
        >>> model = types.SimpleNamespace(geom_name2id={"a": 0, "b": 1}.__getitem__)
        >>> get_ids(types.SimpleNamespace(model=model), ["b", 7, "a"])
        [1, 7, 0]

    """
    if type(elements) is not list:
        elements = [elements]
    if not inplace:
        elements = list(elements)
    assert element_type in _ID_TYPES, "Invalid element type"
    for i, element in enumerate(elements):
        if type(element) is not int:
            element_func = sim.model.__getattribute__(f"{element_type}_name2id")
            elements[i] = element_func(element)
    return cast(list[Any], elements)


def normalize_scale_array(scale: Any) -> npt.NDArray[Any]:
    """A scale factor as three numbers: one number is repeated (ints stay ints).

    Raises:
        ValueError: Neither one nor three numbers.

    Examples:
        >>> normalize_scale_array(2), normalize_scale_array([[1.0], [2.0], [3.0]])
        (array([2, 2, 2]), array([1., 2., 3.]))

    """
    scale_array = np.array(scale).flatten()
    if scale_array.size == 1:
        return np.repeat(scale_array, 3)
    if scale_array.size != 3:
        raise ValueError("Scale must be a scalar or a 3-element array.")
    return scale_array
