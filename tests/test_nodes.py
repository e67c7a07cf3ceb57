"""Node behaviour: immutability, typed views, attribute order, generic elements, values."""

from __future__ import annotations

import math

import attrs
import numpy as np
import pytest

from mjcf_model import (
    AttributeMap,
    Body,
    Comment,
    FreeJoint,
    GenericElement,
    Geom,
    Joint,
    Mujoco,
    Site,
    Worldbody,
    attribute_items,
    get_attribute,
    with_attributes,
)
from mjcf_model.values import format_float, format_value, to_vec3
from serializers import dumps, loads


def test_nodes_are_frozen_and_hashable() -> None:
    """Assigning to a node fails; equal nodes hash equal."""
    geom = Geom(name="g", size=[0.1])
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        geom.name = "h"  # type: ignore[misc]
    assert hash(geom) == hash(Geom(name="g", size=(0.1,)))
    assert {geom, Geom(name="g", size=(0.1,))} == {geom}


def test_vectors_accept_lists_arrays_and_text() -> None:
    """Sequences, numpy arrays and MJCF text all become tuples of floats."""
    expected = (0.0, 1.5, -2.0)
    assert Geom(pos=[0, 1.5, -2]).pos == expected
    assert Geom(pos=np.array([0, 1.5, -2])).pos == expected
    assert Geom(pos=np.array([0, 1.5, -2], dtype=np.float32)).pos == expected
    assert Geom(pos="0 1.5 -2").pos == expected
    assert all(type(v) is float for v in Geom(pos=np.arange(3)).pos or ())


def test_typed_views_follow_document_order() -> None:
    """``body.geoms``/``joints``/``sites``/``bodies`` list direct children in order."""
    inner = Body(name="inner")
    body = Body(
        name="b",
        children=[
            Geom(name="g1"),
            Comment(text=" x "),
            FreeJoint(name="free"),
            Site(name="s"),
            Geom(name="g2"),
            inner,
            Joint(name="j"),
        ],
    )
    assert [g.name for g in body.geoms] == ["g1", "g2"]
    assert [j.name for j in body.joints] == ["free", "j"]
    assert body.bodies == (inner,)
    assert [s.name for s in body.sites] == ["s"]
    assert len(body.elements) == 6


def test_root_section_properties() -> None:
    """``model.worldbody`` and friends return the first section of that kind or None."""
    world = Worldbody()
    model = Mujoco(children=[Comment(text="c"), world])
    assert model.worldbody is world
    assert model.asset is None and model.actuator is None


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


@pytest.mark.parametrize(
    "value",
    [0.1, 1 / 3, 1e-300, 5e-324, 1.7976931348623157e308, -0.0, 2.0, 1e16, 123456789.125, math.pi],
)
def test_floats_are_written_shortest_and_exact(value: float) -> None:
    """Every float is written as text that reads back to the same double."""
    text = format_float(value)
    assert float(text) == value
    assert math.copysign(1, float(text)) == math.copysign(1, value)
    assert len(text) <= len(repr(value))


def test_value_formatting() -> None:
    """Booleans, ints, tuples and text are written as MJCF spells them."""
    assert format_value(True) == "true" and format_value(False) == "false"
    assert format_value((1.0, -0.5, 3)) == "1 -0.5 3"
    assert format_value("hinge") == "hinge"
    assert to_vec3(" 1\t2\n3 ") == (1.0, 2.0, 3.0)


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

    from mjcf_model import full_repr, walk
    from mjcf_model.nodes.base import FULL_REPR_ELEMENTS
    from serializers import load

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
