"""Every typed node class, and the references the per-class tests compare with."""

from __future__ import annotations

import attrs

from mjcf_model import (
    Mujoco,
    Node,
    compiled,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.nodes.registry import CLASS_BY_KEY

TYPED_CLASSES = sorted(set(CLASS_BY_KEY.values()), key=lambda cls: cls.__name__)


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
