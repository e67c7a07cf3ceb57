"""Tests of ``mjcf_model.nodes.building``."""

from __future__ import annotations

from typing import Any

import attrs
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import Geom, Joint
from mjcf_model.nodes.base import TypedElement, build_node
from mjcf_model.strategies import element_values, elements
from tests.conftest import PER_CLASS
from tests.support.node_classes import TYPED_CLASSES

# -- The node core: one decorator, sparse storage, and the fast builder as an owned contract. --


def _expected(cls: type[TypedElement], values: dict[str, Any], base: Any = None) -> dict[str, Any]:
    """Every field's value by attrs' rules, computed without build_node or the constructor.

    The field's converter on what is given; the base's value (or the default) for the rest.
    """
    expected: dict[str, Any] = {}
    for field in attrs.fields(cls):
        if field.name in values:
            value = values[field.name]
            expected[field.name] = value if field.converter is None else field.converter(value)
        elif base is not None:
            expected[field.name] = getattr(base, field.name)
        else:
            default = field.default
            if field.converter is not None and default is not None:
                default = field.converter(default)
            expected[field.name] = default
    return expected


@pytest.mark.parametrize("cls", TYPED_CLASSES, ids=lambda cls: cls.__name__)
@PER_CLASS
@given(data=st.data())
def test_building_from_values_gives_what_attrs_converters_give(
    cls: type[TypedElement], data: st.DataObject
) -> None:
    """build_node and cls(**values) hold, field by field, what attrs' converters make."""
    values = data.draw(element_values(cls))
    built, constructed = build_node(cls, values), cls(**values)
    expected = _expected(cls, values)
    assert attrs.asdict(built, recurse=False) == expected
    assert attrs.asdict(constructed, recurse=False) == expected
    assert built == constructed and hash(built) == hash(constructed)


@pytest.mark.parametrize("cls", TYPED_CLASSES, ids=lambda cls: cls.__name__)
@PER_CLASS
@given(data=st.data())
def test_building_on_a_base_gives_what_attrs_evolve_means(
    cls: type[TypedElement], data: st.DataObject
) -> None:
    """build_node on a base holds what attrs.evolve(base, **values) means, field by field."""
    base = data.draw(elements(cls))
    values = data.draw(element_values(cls))
    expected = _expected(cls, values, base)
    assert attrs.asdict(build_node(cls, values, base), recurse=False) == expected
    assert attrs.asdict(attrs.evolve(base, **values), recurse=False) == expected


def test_the_builder_contract_test_can_fail() -> None:
    """A builder that skipped a converter would store text where the field holds numbers."""
    values = {"size": "1 2"}
    expected = _expected(Geom, values)
    assert expected["size"] == (1.0, 2.0)
    unconverted = {**expected, "size": "1 2"}
    assert attrs.asdict(build_node(Geom, values), recurse=False) != unconverted


def test_only_the_fields_given_are_stored() -> None:
    """A built node stores the fields it was given (None removes one); the rest read defaults."""
    geom = build_node(Geom, {"size": "0.1", "name": "g"})
    assert set(vars(geom)) == {"size", "name"}
    assert geom.mass is None and geom.children == () and not geom.extra
    cleared = build_node(Geom, {"name": None}, geom)
    assert set(vars(cleared)) == {"size"} and cleared.name is None


def test_building_an_unknown_field_raises_like_the_constructor() -> None:
    """An unknown field name is a TypeError, as attrs' constructor makes it."""
    with pytest.raises(TypeError, match="Geom has no field 'colour'"):
        build_node(Geom, {"colour": "red"})
    with pytest.raises(TypeError):
        Geom(color="red")  # type: ignore[call-arg]


def test_building_converts_and_validates_like_the_constructor() -> None:
    """Converters and validators run on the given values, with the constructor's errors."""
    assert build_node(Joint, {"range": "0 1"}).range == (0.0, 1.0)
    with pytest.raises(ValueError, match="expected 2 numbers"):
        build_node(Joint, {"range": "0"})
    with pytest.raises(ValueError, match="hinge"):
        build_node(Joint, {"type": "hinges"})
