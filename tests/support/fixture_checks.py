"""Reading the fixture models: sections, names, comments, and compiled round trips."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import TypeVar

import mujoco

from mjcf_model import (
    Comment,
    Element,
    Mujoco,
    Node,
    TypedElement,
)
from mjcf_model.bridge.compare import compile_text_beside
from mjcf_model.serializers import dumps

T = TypeVar("T", bound=TypedElement)


def walk(node: Node) -> Iterator[Node]:
    """Yield a node and all its descendants, in document order."""
    yield node
    if isinstance(node, Element):
        for child in node.children:
            yield from walk(child)


def comments(node: Node) -> list[str]:
    """Return the texts of all comments under a node, in document order."""
    return [n.text for n in walk(node) if isinstance(n, Comment)]


def names(model: mujoco.MjModel, objtype: mujoco.mjtObj, count: int) -> list[str]:
    """Return the names of ``count`` compiled objects of one type, by id."""
    return [mujoco.mj_id2name(model, objtype, i) for i in range(count)]


def section(model: Mujoco, cls: type[T]) -> T:
    """Return the first root child of a section type, without the section properties."""
    found = [c for c in model.children if isinstance(c, cls)]
    assert found, f"no <{cls.tag}> section"
    return found[0]


def compile_round_trip(model: Mujoco, beside: Path) -> mujoco.MjModel:
    """Compile the written text of a loaded model as if it stood beside ``beside``."""
    return compile_text_beside(dumps(model), beside)
