"""Tests of ``mjcf_model.nodes.base``."""

from __future__ import annotations

import attrs
import pytest

from mjcf_model import (
    AttributeMap,
    Body,
    Comment,
    GenericElement,
    Geom,
    MjcfValueError,
    Site,
    attribute_items,
    full_repr,
    get_attribute,
    with_attributes,
)
from mjcf_model.serializers import dumps, load, loads

# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


# -- nodes that cannot be written cannot be built --------------------------------------


def test_carriage_return_in_a_comment_is_refused() -> None:
    """XML reads a carriage return in a comment as a line feed; comments have no references."""
    with pytest.raises(MjcfValueError, match="carriage return"):
        Comment(text="a\rb")


# -- Node behaviour: immutability, typed views, attribute order, generic elements, values. -----


def test_nodes_are_frozen_and_hashable() -> None:
    """Assigning to a node fails; equal nodes hash equal."""
    geom = Geom(name="g", size=[0.1])
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        geom.name = "h"  # type: ignore[misc]
    assert hash(geom) == hash(Geom(name="g", size=(0.1,)))
    assert {geom, Geom(name="g", size=(0.1,))} == {geom}


def test_attribute_order_is_kept_but_not_compared() -> None:
    """Source attribute order comes back on write; equality ignores it."""
    first = loads('<mujoco><worldbody><geom size="1" name="a" pos="0 0 1"/></worldbody></mujoco>')
    second = loads('<mujoco><worldbody><geom name="a" pos="0 0 1" size="1"/></worldbody></mujoco>')
    assert first == second
    assert '<geom size="1" name="a" pos="0 0 1"/>' in dumps(first)
    assert '<geom name="a" pos="0 0 1" size="1"/>' in dumps(second)


def test_unknown_elements_and_attributes_pass_through() -> None:
    """A future element stays generic, its known children stay typed, nothing is lost."""
    text = (
        '<mujoco><worldbody><hologram beam="3" mode="x"><geom size="0.1" glow="2"/>'
        "</hologram></worldbody></mujoco>"
    )
    model = loads(text)
    hologram = model.worldbody.children[0]  # type: ignore[union-attr]
    assert isinstance(hologram, GenericElement)
    assert hologram.tag == "hologram"
    assert hologram.attributes == AttributeMap({"beam": "3", "mode": "x"})
    geom = hologram.children[0]
    assert isinstance(geom, Geom)
    assert geom.size == (0.1,) and geom.extra == {"glow": "2"}
    assert loads(dumps(model)) == model
    assert '<hologram beam="3" mode="x">' in dumps(model)
    assert '<geom size="0.1" glow="2"/>' in dumps(model)


def test_with_attributes_sets_typed_and_extra_attributes() -> None:
    """``with_attributes`` converts typed values, keeps text for unknown ones, removes None."""
    site = Site(name="s", pos=(0, 0, 0))
    changed = with_attributes(site, {"name": "p_s", "pos": [1, 2, 3], "halo": "1", "size": None})
    assert changed.name == "p_s" and changed.pos == (1.0, 2.0, 3.0)
    assert get_attribute(changed, "halo") == "1"
    assert site.name == "s"  # the input is untouched
    assert with_attributes(site, {}) is site
    assert attribute_items(with_attributes(changed, {"halo": None})) == [
        ("name", "p_s"),
        ("pos", (1.0, 2.0, 3.0)),
    ]


def test_with_attributes_takes_keywords_as_evolve_does() -> None:
    """Keywords set attributes as the mapping does; both forms combine; a clash is refused."""
    site = Site(name="s", pos=(0, 0, 0))
    by_keyword = with_attributes(site, name="p_s", pos=[1, 2, 3], halo="1", size=None)
    by_mapping = with_attributes(site, {"name": "p_s", "pos": [1, 2, 3], "halo": "1"})
    assert by_keyword == by_mapping and attribute_items(by_keyword) == attribute_items(by_mapping)
    both = with_attributes(site, {"class": "c"}, rgba=(1, 0, 0, 1))
    assert both.dclass == "c" and both.rgba == (1.0, 0.0, 0.0, 1.0)
    assert with_attributes(site) is site
    with pytest.raises(TypeError, match="pos both in changes and as keywords"):
        with_attributes(site, {"pos": (1, 1, 1)}, pos=(2, 2, 2))


def test_generic_with_attributes_formats_values() -> None:
    """Typed values given to a generic element are written as MJCF text."""
    element = GenericElement(tag="thing", attributes={"a": "1"})
    assert with_attributes(element, {"b": (1.0, 0.5)}).attributes == {"a": "1", "b": "1 0.5"}


def test_comment_text_is_checked() -> None:
    """A comment that XML cannot hold is refused when built."""
    with pytest.raises(ValueError, match="cannot contain '--'"):
        Comment(text="a -- b")


def test_repr_shows_only_written_attributes() -> None:
    """The repr of a node lists what is set, not the 40 fields that are not."""
    assert repr(Geom(name="g", size=[1])) == "Geom(name='g', size=(1.0,))"


def test_a_large_subtree_shows_as_one_line() -> None:
    """``repr`` of a model or large subtree is a line: class, name, count, file and line."""
    import importlib.resources

    from mjcf_model import walk
    from mjcf_model.nodes.base import FULL_REPR_ELEMENTS

    path = importlib.resources.files("robosuite") / "models/assets/robots/panda/robot.xml"
    model = load(str(path))
    count = sum(1 for _ in walk(model))
    text = repr(model)
    assert "\n" not in text and len(text) < 200 + len(str(path))
    assert text == f"<Mujoco model='panda': {count:,} elements from {str(path)!r}, line 2>"
    base = model.worldbody.bodies[0]
    assert repr(base).startswith("<Body name='base': ") and "line " in repr(base)
    assert len(full_repr(model)) > 10_000 and full_repr(model).startswith("Mujoco(model='panda'")
    small = Body(name="b", children=[Geom(name=f"g{i}") for i in range(FULL_REPR_ELEMENTS - 1)])
    assert repr(small) == full_repr(small) and repr(small).startswith("Body(name='b', children=")
    large = Body(name="b", children=[Geom(name=f"g{i}") for i in range(FULL_REPR_ELEMENTS)])
    assert repr(large) == f"<Body name='b': {FULL_REPR_ELEMENTS + 1} elements>"
