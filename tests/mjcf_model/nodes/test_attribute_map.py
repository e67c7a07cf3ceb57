"""Tests of ``mjcf_model.nodes.attribute_map``: the text attributes an element does not model."""

from __future__ import annotations

from typing import Any

import pytest

from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.attribute_map import EMPTY_ATTRIBUTES, AttributeMap, to_attribute_map


def test_order_is_kept_and_ignored_by_equality_and_hash() -> None:
    """Iteration follows insertion; maps equal as XML attributes do, whatever the order."""
    forward, backward = AttributeMap({"b": "1", "a": "2"}), AttributeMap([("a", "2"), ("b", "1")])
    assert list(forward) == ["b", "a"] and list(forward.items()) == [("b", "1"), ("a", "2")]
    assert list(backward.keys()) == ["a", "b"] and list(backward.values()) == ["2", "1"]
    assert forward == backward == {"a": "2", "b": "1"}
    assert hash(forward) == hash(backward)
    assert len({forward, backward}) == 1
    assert forward != AttributeMap({"b": "1", "a": "3"})
    assert forward.get("a") == "2" and forward.get("c") is None and forward.get("c", "-") == "-"
    assert "a" in forward and "c" not in forward and len(forward) == 2


def test_a_map_cannot_be_changed() -> None:
    """No item assignment, no new attribute: a changed map is a new one."""
    attributes: Any = AttributeMap({"a": "1"})
    with pytest.raises(TypeError):
        attributes["a"] = "2"
    with pytest.raises(AttributeError):
        attributes.extra = 1
    assert attributes == {"a": "1"}


@pytest.mark.parametrize(
    "items",
    [{"a": 1}, {1: "a"}, {"two words": "x"}, {"1a": "x"}, {"a": "nul \x00 inside"}, {"a": "\x1f"}],
    ids=["number value", "number name", "space in name", "digit first", "nul", "control"],
)
def test_what_xml_cannot_carry_is_refused(items: Any) -> None:
    """Names must be XML names and values text XML can hold; anything else is a value error."""
    with pytest.raises(MjcfValueError):
        AttributeMap(items)


def test_replaced_removes_changes_and_appends() -> None:
    """``None`` removes, a known name keeps its place, a new one goes last; the original stays."""
    original = AttributeMap({"a": "1", "b": "2", "c": "3"})
    changed = original.replaced({"b": None, "a": "9", "d": "4"})
    assert list(changed.items()) == [("a", "9"), ("c", "3"), ("d", "4")]
    assert list(original.items()) == [("a", "1"), ("b", "2"), ("c", "3")]
    with pytest.raises(MjcfValueError):
        original.replaced({"not a name": "1"})
    with pytest.raises(MjcfValueError):
        original.replaced({"a": 1})  # type: ignore[dict-item]


def test_the_converter_shares_maps_and_the_empty_map() -> None:
    """A map passes through as itself; nothing becomes the one shared empty map."""
    attributes = AttributeMap({"x": "1"})
    assert to_attribute_map(attributes) is attributes
    assert to_attribute_map(None) is EMPTY_ATTRIBUTES
    assert to_attribute_map({}) is EMPTY_ATTRIBUTES
    assert to_attribute_map([("x", "1")]) == attributes
