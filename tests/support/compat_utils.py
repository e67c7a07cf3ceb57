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
import inspect
import json
import math
import os
import xml.etree.ElementTree as ET
from collections import Counter
from collections.abc import Callable, Iterable
from typing import Any

import numpy as np
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from robosuite.utils import mjcf_utils as rs

from mjcf_model.compat import mjcf_utils as ours
from mjcf_model.serializers import to_etree
from mjcf_model.strategies import models

__all__ = [
    "CASES",
    "DEFAULT_MATERIAL_TEXTURE",
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

#: The texture attributes robosuite's ``add_material`` gives its default material
#: (``CustomMaterial(None, "default_tex", "default_mat", tex_attrib=...)``, as it writes it).
DEFAULT_MATERIAL_TEXTURE: dict[str, Any] = {
    "type": "cube",
    "builtin": "flat",
    "width": 100,
    "height": 100,
    "rgb1": np.ones(3),
    "rgb2": np.ones(3),
}

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


RS_CONSTANTS = sorted(
    name for name, value in vars(rs).items() if name.isupper() and not inspect.ismodule(value)
)


E2 = (
    '<body name="b" childclass="c"><geom name="g" material="m" mesh="p_mesh" class="k"/>'
    '<joint name="j"/><site name="s" type="sphere"/><weld body1="b" body2="x"/>'
    '<camera name="cam" mode="fixed"/><light name="l"/>'
    '<foo name="f" rgba="1 0 0 1" texture="t"/><exclude body1="a" body2="b"/>'
    '<pair geom1="g" geom2="h"/><motor joint="j" name="mot"/>'
    '<fixed name="fx"><joint joint="j" coef="1"/></fixed></body>'
)


TAGS = ["geom", "body", "joint", "site", "material", "texture", "motor", "default", "worldbody"]


TAGS += ["mujoco", "camera", "light", "tendon", "fixed", "position", "touch", "freejoint"]


prefixes = st.sampled_from(["p_", "", "body", "geom0", "b", "class", "mat", "p"]) | st.text(
    "abgp_0", max_size=4
)


name_sets = st.frozensets(
    st.sampled_from(["body0", "geom0", "geom1", "joint0", "material0", "class0", "p_x", ""]),
    max_size=3,
)


def prefix_twice(prefix: str, **options: Any) -> Any:
    """``add_prefix`` applied twice with the same arguments."""

    def operation(module: Any, root: ET.Element) -> Any:
        return [module.add_prefix(root, prefix, **options) for _ in range(2)]

    return operation


def prefix_logging(prefix: str, names: frozenset[str], tags: Any, attribs: Any) -> Any:
    """``add_prefix`` with an ``exclude`` that logs its calls; the result is the log.

    Each element call is followed by the values asked about on that element,
    sorted: robosuite asks in the iteration order of a set, which depends on
    how the interpreter built the set (and on the hash seed).
    """

    def operation(module: Any, root: ET.Element) -> Any:
        positions = paths(root)
        log: list[Any] = []

        def exclude(item: Any) -> bool:
            if isinstance(item, str):
                log[-1][1].append(item)
                return item in names
            log.append((positions[id(item)], []))
            return item.get("name") in names

        module.add_prefix(root, prefix, tags=tags, attribs=attribs, exclude=exclude)
        return [(position, sorted(values)) for position, values in log]

    return operation


def _substring_oracle(root: ET.Element, tags: Any, substrings: list[str]) -> list[ET.Element]:
    found = rs.find_elements(root, tags, return_first=False) or []
    return [
        e
        for e in found
        if e.get("name") is not None and any(s in e.get("name") for s in substrings)
    ]


def check_by_substring(root: ET.Element, tags: Any, substrings: list[str]) -> None:
    """Compare ``find_elements_by_substring`` in both modes with robosuite.

    Where robosuite crashes (unnamed elements) or errs (``return_first``), the
    expected result is robosuite's ``find_elements`` list without unnamed elements.
    """
    theirs_root, our_root = copy.deepcopy(root), copy.deepcopy(root)
    theirs, their_error = run(rs.find_elements_by_substring, theirs_root, tags, substrings)
    mine = ours.find_elements_by_substring(our_root, tags, substrings)
    CASES["find_elements_by_substring"] += 1
    oracle = _substring_oracle(theirs_root, tags, substrings)
    if their_error is TypeError:
        CASES["find_elements_by_substring (robosuite crashes on unnamed)"] += 1
        theirs = oracle or None
    mine_first = ours.find_elements_by_substring(our_root, tags, substrings, return_first=True)
    CASES["find_elements_by_substring (return_first)"] += 1
    ours_pos, theirs_pos = paths(our_root), paths(theirs_root)
    assert comparable(mine, ours_pos) == comparable(theirs, theirs_pos)
    first = oracle[0] if oracle else None
    assert comparable(mine_first, ours_pos) == comparable(first, theirs_pos)


def _parts(root: ET.Element) -> tuple[ET.Element, ET.Element]:
    """The worldbody (or the root) and the asset section (or an empty one) of a tree."""
    worldbody = root.find("worldbody")
    asset = root.find("asset")
    return (root if worldbody is None else worldbody), (
        ET.Element("asset") if asset is None else asset
    )


def scale_model(scale: Any, sites: bool, slide: bool) -> Any:
    """``scale_mjcf_model`` on the tree's worldbody and assets."""

    def operation(module: Any, root: ET.Element) -> Any:
        worldbody, asset = _parts(root)
        return module.scale_mjcf_model(
            worldbody,
            asset,
            scale,
            module.get_elements,
            worldbody=worldbody if sites else None,
            scale_slide_joints=slide,
        )

    return operation


def scale_each(function: str, tag: str, scale: Any, *extra: Any) -> Any:
    """``scale_<x>_element`` on every element of ``tag`` in the tree, in document order."""

    def operation(module: Any, root: ET.Element) -> Any:
        array = module.normalize_scale_array(scale)
        return [getattr(module, function)(e, array, *extra) for e in root.iter(tag)]

    return operation


def element_filters(module: Any, root: ET.Element) -> Any:
    """``_element_filter`` on every (element, parent) pair, and on the root without parent."""
    return [module._element_filter(root, None)] + [
        module._element_filter(child, parent) for parent in root.iter() for child in parent
    ]


def tag_filter(element: ET.Element, parent: ET.Element | None) -> Any:
    """A custom ``sort_elements`` filter: the tag, for elements that have a parent."""
    return element.tag if parent is not None and isinstance(element.tag, str) else None


def find_parents(module: Any, root: ET.Element) -> Any:
    """``find_parent`` for up to 25 elements of the tree, the root and a foreign element."""
    every = list(root.iter())
    targets = [*every[:: max(1, len(every) // 25)], root, ET.Element("geom")]
    return [module.find_parent(root, target) for target in targets]


finite = st.floats(allow_nan=False, allow_infinity=False)


scalars = (
    st.integers(-(10**6), 10**6) | st.floats() | st.booleans() | st.text(max_size=4) | st.none()
)


numpy_scalars = (
    st.floats(width=32).map(np.float32)
    | st.floats().map(np.float64)
    | st.integers(-1000, 1000).map(np.int64)
    | st.booleans().map(np.bool_)
    | st.text(max_size=3).map(np.str_)
)


arrays = hnp.arrays(
    dtype=st.sampled_from([np.float64, np.float32, np.int64, np.bool_]),
    shape=hnp.array_shapes(min_dims=1, max_dims=2, min_side=0, max_side=4),
)


sequences = (
    st.lists(scalars | numpy_scalars, max_size=5) | st.lists(finite, max_size=4).map(tuple) | arrays
)


values = (
    scalars
    | numpy_scalars
    | sequences
    | st.dictionaries(st.text(max_size=2), finite, max_size=2)
    | st.sets(st.integers(0, 5), max_size=3)
)
