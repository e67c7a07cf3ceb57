"""Tests of ``mjcf_model.nodes.node_info``: what the library knows about one node class."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model import Body, Comment, Geom, Joint
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.node_info import BASE_FIELDS, tuple_getter


def test_the_table_maps_mjcf_names_to_fields_name_first() -> None:
    """``class`` is the field ``dclass``; ``name`` leads; ``getter`` reads in ``names`` order."""
    info = Geom.__node_info__
    assert info.tag == "geom" and info.cls is Geom
    assert info.table["class"] == "dclass" and info.names[0] == "name"
    assert info.names == tuple(info.table)
    assert not BASE_FIELDS & set(info.table.values())
    geom = Geom(name="g", size=(0.1, 0.2), rgba=(1, 0, 0, 1))
    assert info.getter(geom) == tuple(getattr(geom, info.table[n]) for n in info.names)
    assert all(info.names[info.rank[field]] == name for name, field in info.table.items())


def test_readers_read_text_as_mujoco_compiles_it() -> None:
    """A reader's value is what MuJoCo compiles from the same text; what it refuses, MuJoCo does."""
    info = Geom.__node_info__
    text = '<mujoco><worldbody><geom type="box" size="0.1 0.2 0.3"/></worldbody></mujoco>'
    model = mujoco.MjModel.from_xml_string(text)
    field, read = info.readers["size"]
    assert field == "size" and np.array_equal(read("0.1 0.2 0.3"), model.geom_size[0])
    assert info.readers["type"][1]("box") == "box"
    with pytest.raises(ValueError):
        mujoco.MjModel.from_xml_string(text.replace("box", "cube"))
    with pytest.raises(MjcfValueError):
        info.readers["type"][1]("cube")


def test_defaults_are_what_an_absent_field_reads_and_the_rest_is_required() -> None:
    """Each default is what a node built without the field holds; a comment needs its text."""
    for cls in (Geom, Joint, Body):
        info = cls.__node_info__
        empty = cls()
        assert all(getattr(empty, name) == value for name, value in info.defaults.items())
        assert info.required == frozenset()
    assert Comment.__node_info__.required == {"text"} and Comment.__node_info__.tag is None


def test_names_and_references_are_plain_text_and_numbers_are_not() -> None:
    """Text a parser gave is kept as it is for names and references only."""
    info = Geom.__node_info__
    assert {"name", "material", "mesh", "dclass"} <= info.plain_text
    assert not {"size", "type", "group", "rgba"} & info.plain_text
    assert info.plain_names["class"] == "dclass" and "size" not in info.plain_names


def test_tuple_getter_always_gives_a_tuple() -> None:
    """No field, one field, or several: always a tuple, in the order asked."""
    geom = Geom(name="g", group=2)
    assert tuple_getter(())(geom) == ()
    assert tuple_getter(("name",))(geom) == ("g",)
    assert tuple_getter(("group", "name"))(geom) == (2, "g")
