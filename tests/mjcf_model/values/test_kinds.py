"""Tests of ``mjcf_model.values.kinds``."""

from __future__ import annotations

import re

import pytest

from mjcf_model import (
    Body,
    Comment,
    GenericElement,
    Geom,
    MjcfValueError,
    Unparsed,
    prefixed,
    scaled,
)
from mjcf_model.serializers import from_dict, from_etree, loads, to_dict, to_etree
from tests.support.oracles import _round_trips_like_mujoco

# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


# -- numbers ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("attribute", "spelling"),
    [("size", "0x10"), ("pos", ""), ("friction", ""), ("size", "0x1p-2 1")],
)
def test_spellings_mujoco_reads_are_kept_verbatim(attribute: str, spelling: str) -> None:
    """MuJoCo reads ``0x10`` (16) and empty values; the text is kept and compiles the same."""
    text = (
        f'<mujoco><worldbody><geom size="0.1" {attribute}="{spelling}"/></worldbody></mujoco>'
        if attribute != "size"
        else f'<mujoco><worldbody><geom {attribute}="{spelling}"/></worldbody></mujoco>'
    )
    _round_trips_like_mujoco(text)
    geom = loads(text).worldbody.geoms[0]
    value = getattr(geom, attribute)
    assert value == Unparsed(spelling)
    with pytest.raises(MjcfValueError, match="kept verbatim") as caught:
        value[0]
    assert caught.value.path == "/mujoco/worldbody/geom" and caught.value.line == 1


def test_unparsed_values_survive_dicts_and_element_tree() -> None:
    """Every serializer carries the verbatim text; transforms that read it raise MjcfValueError."""
    model = loads('<mujoco><worldbody><geom name="g" size="0x10"/></worldbody></mujoco>')
    assert from_dict(to_dict(model)) == model
    assert from_etree(to_etree(model)) == model
    assert prefixed(model, "p_").worldbody.geoms[0].size == Unparsed("0x10")
    with pytest.raises(MjcfValueError, match="kept verbatim"):
        scaled(model, 2.0)


def test_large_values_are_shortened_in_errors() -> None:
    """An error about a huge attribute quotes its start, not all of it."""
    with pytest.raises(MjcfValueError) as caught:
        Geom(size="1 " * 100_000 + "x")
    assert len(str(caught.value)) < 300


# -- nodes that cannot be written cannot be built --------------------------------------


@pytest.mark.parametrize("bad", ["a\x00b", "a\x01", "\ud800", "x\x1f", "\ufffe"])
def test_text_xml_cannot_carry_is_refused_when_the_node_is_made(bad: str) -> None:
    """Names, comments, attribute values and text refuse what could not be read back."""
    for build in (
        lambda: Geom(name=bad),
        lambda: Comment(text=bad),
        lambda: GenericElement(tag="x", attributes={"a": bad}),
        lambda: Body(text=bad),
    ):
        with pytest.raises(MjcfValueError, match="XML cannot carry"):
            build()


@pytest.mark.parametrize("tag", ["", "1a", "a b", "a<", "-x", "a=b"])
def test_tags_and_attribute_names_must_be_xml_names(tag: str) -> None:
    """A tag or attribute name that is not an XML name could not be written."""
    with pytest.raises(MjcfValueError, match="not an XML name"):
        GenericElement(tag=tag)
    with pytest.raises(MjcfValueError, match="not an XML name"):
        GenericElement(tag="x", attributes={tag: "1"})


# -- only MjcfError escapes ------------------------------------------------------------


def test_errors_from_bad_attributes_never_quote_megabytes() -> None:
    """A 2 MB attribute loads; the error on use quotes its start and its length."""
    text = "<mujoco><worldbody><geom size='" + "1 " * 1_000_000 + "'/></worldbody></mujoco>"
    geom = loads(text).worldbody.geoms[0]
    with pytest.raises(MjcfValueError) as caught:
        geom.size[0]
    assert len(str(caught.value)) < 400
    assert re.search(r"\(\d+ characters\)", str(caught.value))
    assert str(caught.value).startswith("<string>:1: /mujoco/worldbody/geom: attribute 'size'")
