"""Tests of ``mjcf_model.serializers.open_element``: an element the text reader has begun."""

from __future__ import annotations

from mjcf_model import Body, Default, Geom, Mujoco, Site, Worldbody
from mjcf_model.serializers.open_element import OpenElement, step_of
from tests.conftest import printed_schema


def test_each_step_is_the_schema_key_mujoco_prints_and_its_class() -> None:
    """A tag in its parent's context maps to MuJoCo's schema key and the typed class."""
    cases = [
        (None, "mujoco", "mujoco", Mujoco),
        ("mujoco", "worldbody", "worldbody", Worldbody),
        ("body", "body", "body", Body),
        ("body", "geom", "body/geom", Geom),
        ("default", "geom", "default/geom", Geom),
        ("mujoco", "default", "default", Default),
    ]
    schema = printed_schema()
    for context, tag, key, cls in cases:
        found_key, _, found_class = step_of(context, tag)
        assert (found_key, found_class) == (key, cls), (context, tag)
        assert found_key == "worldbody" or found_key in schema  # MuJoCo prints "(world)body"
    assert step_of("body", "nonsense")[::2] == (None, None)


def test_children_and_attributes_are_kept_per_element() -> None:
    """Attributes pair up in order; children are each element's own, counted by tag."""
    first = OpenElement("body", ["name", "a", "pos", "0 0 1"], "body", Body, "body", 1, 0, 30)
    second = OpenElement("body", [], "body", Body, "body", 2, 31, 37)
    assert first.pairs() == [("name", "a"), ("pos", "0 0 1")] and second.pairs() == []
    first.add_child(Geom())
    first.add_child(Site())
    first.add_child(Geom())
    assert second.children == []  # the empty list every element starts with is not shared
    assert [first.index_of(tag) for tag in ("geom", "site", "body")] == [3, 2, 1]
    assert first.text is None and first.comments is None
