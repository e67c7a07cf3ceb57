"""Tests of ``mjcf_model.nodes.declaring``."""

from __future__ import annotations

from typing import ClassVar

import attrs
import pytest

from mjcf_model.nodes.base import TypedElement, build_node
from mjcf_model.nodes.declaring import declared_classes, node
from mjcf_model.nodes.fields import text, vec3

# -- The node core: one decorator, sparse storage, and the fast builder as an owned contract. --


def test_declaring_refuses_what_the_builder_cannot_honour() -> None:
    """A node class with __attrs_post_init__ is refused when it is declared."""
    with pytest.raises(TypeError, match="__attrs_post_init__"):

        @node
        class Checked(TypedElement):
            tag: ClassVar[str] = "checked"

            def __attrs_post_init__(self) -> None:
                pass


def test_a_declared_class_gets_sparse_fields_and_its_info() -> None:
    """@node gives keyword-only frozen attrs classes whose info lists their MJCF attributes."""

    @node
    class Thing(TypedElement):
        tag: ClassVar[str] = "thing"
        pos: tuple[float, ...] | None = vec3()
        body: str | None = text(xml="attachedto")

    thing = Thing(pos=[1, 2, 3], body="torso")
    assert thing.pos == (1.0, 2.0, 3.0) and thing.body == "torso"
    assert set(vars(build_node(Thing, {"pos": [1, 2, 3]}))) == {"pos"}
    assert Thing.__node_info__.table == {"pos": "pos", "attachedto": "body"}
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        thing.pos = None  # type: ignore[misc]
    with pytest.raises(TypeError):
        Thing((1, 2, 3))  # type: ignore[misc]
    assert Thing in declared_classes()
