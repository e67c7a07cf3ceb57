"""Cases on a generated scene of 20,000 bodies: what a new user's big file costs.

Each body holds a joint, a capsule and a site (``synthetic_xml``, all in the world):
loading it, finding one geom by name (the first query of a loaded tree, of a tree a
transform returned, of a tree built in code, and asked again), and prefixing and
writing it, each beside ElementTree doing the same.
"""

from __future__ import annotations

import copy
import xml.etree.ElementTree as ET
from typing import Any

from benchmarks.etree_path import MISSING_ROBOSUITE, robosuite_utils
from benchmarks.harness import OURS, Case, Contender
from benchmarks.inputs import synthetic_xml

__all__ = ["SCENE_BODIES", "scene_cases"]

#: The bodies of the scene a whole run measures.
SCENE_BODIES = 20_000


def scene_cases(bodies: int) -> list[Case]:
    """Load, find by name (first and repeated query), prefix + write a ``bodies``-body scene."""
    from mjcf_model import find, prefixed
    from mjcf_model.serializers import dumps, loads

    try:
        from mjcf_model.tree import indexes
    except ImportError:  # a library before the index (measuring a change against it)
        indexes = None

    utils = robosuite_utils()
    text = synthetic_xml(bodies, "wide")
    model, twin = loads(text), loads(text)
    transformed = prefixed(model, "t_")
    built = type(model)(children=model.children)  # a tree made in code: nothing noted
    tree = ET.fromstring(text)
    last = f"g{bodies - 1}"
    path = f".//geom[@name='{last}']"
    inputs = f"{bodies:,} bodies (a joint, a capsule, a site each)"

    def noted(tree: object) -> object:
        """The index noted when ``tree`` was read or made, before any query (or ``None``)."""
        entry = indexes._INDEXES.get(id(tree)) if indexes is not None else None
        index = entry[1] if entry is not None else None
        return index if hasattr(index, "places") else None

    read, made = noted(model), noted(transformed)

    def first_query(tree: Any, index: Any, name: str) -> object:
        if index is not None:  # as just read or made: the noted index, never queried
            indexes.indexed(tree, indexes.TagIndex.from_reading(index.order, index.places))
        elif indexes is not None:  # a library that notes none (measuring a change against it)
            indexes._INDEXES.pop(id(tree), None)
        return find(tree, "geom", name=name)

    for _ in range(2):  # the second query builds the twin's index
        find(twin, "geom", name=last)

    def robosuite_path() -> str:
        copied = copy.deepcopy(tree)
        utils.add_prefix(copied, "p_")  # type: ignore[union-attr]
        return ET.tostring(copied, encoding="unicode")

    return [
        Case(
            "scene: load",
            [
                Contender(OURS, lambda: loads(text)),
                Contender("ElementTree fromstring", lambda: ET.fromstring(text)),
            ],
            inputs,
        ),
        Case(
            "scene: find a geom by name, first query of a loaded tree",
            [
                Contender(
                    OURS,
                    lambda: first_query(model, read, last),
                    note="find(model, 'geom', name=...), the last geom, on the index the reader "
                    "noted",
                ),
                Contender("ElementTree find", lambda: tree.find(path), note=path),
            ],
            inputs,
        ),
        Case(
            "scene: find a geom by name, first query of a transformed tree",
            [
                Contender(
                    OURS,
                    lambda: first_query(transformed, made, f"t_{last}"),
                    note="the same on prefixed(model, 't_'), on the index the transform noted",
                ),
                Contender("ElementTree find", lambda: tree.find(path), note=path),
            ],
            inputs,
        ),
        Case(
            "scene: find a geom by name, first query of a built tree",
            [
                Contender(
                    OURS,
                    lambda: first_query(built, None, last),
                    note="the same on Mujoco(children=model.children): a walk of the whole tree",
                ),
                Contender("ElementTree find", lambda: tree.find(path), note=path),
            ],
            inputs,
        ),
        Case(
            "scene: find a geom by name, asked again",
            [
                Contender(OURS, lambda: find(twin, "geom", name=last), note="from the index"),
                Contender("ElementTree find", lambda: tree.find(path), note=path),
            ],
            inputs,
        ),
        Case(
            "scene: prefix + write",
            [
                Contender(OURS, lambda: dumps(prefixed(model, "p_"))),
                Contender(
                    "robosuite (deepcopy + add_prefix + tostring)",
                    robosuite_path if utils else None,
                    MISSING_ROBOSUITE,
                ),
            ],
            inputs,
        ),
    ]
