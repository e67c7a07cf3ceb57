"""Every typed node class, and the references the per-class tests compare with."""

from __future__ import annotations

import attrs
import mujoco

from mjcf_model import (
    Mujoco,
    Node,
    compiled,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.serializers import dumps, loads
from mjcf_model.tree.traversal import walk

#: Every typed node class, by name.
TYPED_CLASSES = sorted(set(CLASS_BY_KEY.values()), key=lambda cls: cls.__name__)


def declared_in(module: str) -> set[str]:
    """The names of the typed node classes ``module`` declares."""
    return {cls.__name__ for cls in TYPED_CLASSES if cls.__module__ == module}


def loaded_from(model: Node, module: str) -> set[str]:
    """The names of ``module``'s classes among the elements of ``model``."""
    return {type(e).__name__ for _, e in walk(model) if type(e).__module__ == module}


def text_round_trip_differences(text: str) -> list[str]:
    """Where MuJoCo's compiles of ``text`` and of its typed nodes written anew differ.

    The canonical form writes every value from its typed field (the kept form would give
    back the text as read).
    """
    written = dumps(loads(text), canonical=True)
    original = mujoco.MjModel.from_xml_string(text)
    return model_differences(original, mujoco.MjModel.from_xml_string(written))


def _reference_equal(a: Node, b: Node) -> bool:
    """Equality as attrs defines it: every ``eq`` field, NaN equal to itself, any depth."""
    stack = [(a, b)]
    while stack:
        left, right = stack.pop()
        if type(left) is not type(right):
            return False
        for field in attrs.fields(type(left)):
            compared = field.eq and field.name != "children"
            if compared and (getattr(left, field.name),) != (getattr(right, field.name),):
                return False
        left_children = getattr(left, "children", ())
        right_children = getattr(right, "children", ())
        if len(left_children) != len(right_children):
            return False
        stack.extend(zip(left_children, right_children, strict=True))
    return True


def _same_compiled(a: Mujoco, b: Mujoco) -> None:
    assert model_differences(compiled(a), compiled(b)) == []
