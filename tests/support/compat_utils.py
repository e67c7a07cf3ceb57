"""Helpers of the differential tests of ``mjcf_model.compat.mjcf_utils`` against robosuite.

Each case runs robosuite 1.5.2's function and ours on deep copies of the same
input and compares the resulting trees (``ET.tostring`` bytes), the return
values (elements by their position in their own tree) and the exception types.
``CASES`` counts the cases per function; with ``COMPAT_UTILS_CASES=<file>`` in
the environment each test process appends its counts to that file as JSON.
"""

from __future__ import annotations

import atexit
import copy
import json
import math
import os
import xml.etree.ElementTree as ET
from collections import Counter
from collections.abc import Callable, Iterable
from typing import Any

import numpy as np
from hypothesis import strategies as st
from robosuite.utils import mjcf_utils as rs

from mjcf_model.compat import mjcf_utils as ours
from mjcf_model.strategies import models
from serializers import to_etree

__all__ = [
    "CASES",
    "at",
    "comparable",
    "differential",
    "messy_trees",
    "named_elements",
    "normalised",
    "ours",
    "paths",
    "rs",
    "run",
    "same_arrays",
    "tree_bytes",
]

#: Differential cases run in this process, by function name.
CASES: Counter[str] = Counter()


def _dump_cases() -> None:
    target = os.environ.get("COMPAT_UTILS_CASES")
    if target and CASES:
        with open(target, "a") as stream:
            stream.write(json.dumps(dict(CASES)) + "\n")


atexit.register(_dump_cases)

Path = tuple[int, ...]
Operation = Callable[[Any, ET.Element], Any]


def paths(root: ET.Element) -> dict[int, Path]:
    """The position of every element of ``root`` (comments too), by ``id``."""
    found: dict[int, Path] = {}
    stack: list[tuple[ET.Element, Path]] = [(root, ())]
    while stack:
        element, path = stack.pop()
        found[id(element)] = path
        stack.extend((child, (*path, i)) for i, child in enumerate(element))
    return found


def at(root: ET.Element, path: Path) -> ET.Element:
    """The element at ``path`` below ``root``."""
    for index in path:
        root = root[index]
    return root


def tree_bytes(root: ET.Element) -> bytes:
    """The tree as robosuite prints it."""
    return ET.tostring(root)


def comparable(value: Any, positions: dict[int, Path]) -> Any:
    """``value`` with live elements replaced by their positions, so two trees' results compare."""
    if isinstance(value, ET.Element):
        path = positions.get(id(value))
        return ("element", path) if path is not None else ("new element", ET.tostring(value))
    if isinstance(value, dict):
        return ("dict", [(k, comparable(v, positions)) for k, v in value.items()])
    if isinstance(value, (list, tuple)):
        return (type(value).__name__, [comparable(v, positions) for v in value])
    if isinstance(value, np.ndarray):
        return ("array", value.dtype.str, value.shape, comparable(value.tolist(), positions))
    if isinstance(value, float) and math.isnan(value):
        return ("nan",)
    if hasattr(value, "tex_attrib"):  # a CustomMaterial
        return ("material", value.name, value.shared, value.tex_attrib, value.mat_attrib)
    return value


def same_arrays(left: Any, right: Any) -> bool:
    """Whether two arrays have the same dtype, shape and items (NaN equal to NaN)."""
    return bool(comparable(left, {}) == comparable(right, {}))


def run(function: Callable[..., Any], *args: Any, **kwargs: Any) -> tuple[Any, Any]:
    """``(result, None)``, or ``(None, exception type)`` when the call raises."""
    try:
        return function(*args, **kwargs), None
    except Exception as error:
        return None, type(error)


def normalised(root: ET.Element) -> ET.Element:
    """A copy of ``root`` with every attribute's white space collapsed to single spaces."""
    copied = copy.deepcopy(root)
    for element in copied.iter():
        for key, value in element.attrib.items():
            element.set(key, " ".join(value.split()))
    return copied


def differential(
    name: str, root: ET.Element, operation: Operation, *, right_on_crash: bool = False
) -> None:
    """Run ``operation(module, tree)`` for robosuite and for us on copies of ``root`` and compare.

    With ``right_on_crash``, where robosuite raises on numbers separated by
    more than one space (valid MJCF) and we do not, our result must be
    robosuite's on the input with its white space collapsed.
    """
    theirs_root, our_root = copy.deepcopy(root), copy.deepcopy(root)
    theirs, their_error = run(operation, rs, theirs_root)
    mine, my_error = run(operation, ours, our_root)
    my_positions = paths(our_root)
    CASES[name] += 1
    if right_on_crash and their_error is ValueError and my_error is None:
        assert tree_bytes(normalised(root)) != tree_bytes(root), f"{name}: robosuite raised"
        theirs_root = normalised(root)
        theirs, their_error = run(operation, rs, theirs_root)
        our_root = normalised(our_root)
        CASES[name + " (robosuite crashes on white space)"] += 1
    assert their_error == my_error, f"{name}: robosuite raised {their_error}, we {my_error}"
    if their_error is not None:
        return
    assert tree_bytes(our_root) == tree_bytes(theirs_root), name
    assert comparable(mine, my_positions) == comparable(theirs, paths(theirs_root)), name


_QUIRKS = [
    ("group", "1.0"),
    ("group", "1"),
    ("group", "0"),
    ("group", "3"),
    ("name", ""),
    ("name", "p_x"),
    ("name", "body"),
    ("material", "m"),
    ("material", "p_m"),
    ("class", "k"),
    ("childclass", "c"),
    ("objname", "o"),
    ("refname", "r"),
    ("rgba", "1 0 0 1"),
    ("rgba", "0.1 0.2 0.3"),
    ("pos", "0 0 0"),
    ("size", "0.1 0.2"),
]


@st.composite
def messy_trees(draw: st.DrawFn, aim: Iterable[str] | None = None) -> tuple[ET.Element, Path]:
    """A generated model as ElementTree, with some quirky attributes, and a subtree's path.

    The quirks are text robosuite treats specially (``group="1.0"``, names that
    start with a prefix, empty names, partial colours). With ``aim`` (tags), they
    land on elements of those tags when the tree has any: where the function
    under test reads them. Half the time the subtree is the whole tree.
    """
    root = to_etree(draw(models()))
    elements = [e for e in root.iter() if isinstance(e.tag, str)]
    aimed = [e for e in elements if aim is not None and e.tag in set(aim)]
    for _ in range(draw(st.integers(0, 4))):
        element = draw(st.sampled_from(aimed or elements))
        key, value = draw(st.sampled_from(_QUIRKS))
        element.set(key, value)
    all_paths = sorted(paths(root).values())
    path = draw(st.just(()) | st.sampled_from(all_paths))
    return root, path


def named_elements(root: ET.Element, tags: Iterable[str] | None = None) -> list[ET.Element]:
    """The elements of ``root`` (not comments), of ``tags`` if given, in document order."""
    wanted = None if tags is None else set(tags)
    return [
        e for e in root.iter() if isinstance(e.tag, str) and (wanted is None or e.tag in wanted)
    ]
