"""Tests of ``mjcf_model.nodes.comparing``."""

from __future__ import annotations

import json
import math
from typing import Any

import attrs
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import (
    AttributeMap,
    Body,
    Comment,
    GenericElement,
    Geom,
    Joint,
    Mujoco,
    Node,
    TypedElement,
    Worldbody,
    compiled,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.serializers import dumps, from_dict, loads, to_dict
from mjcf_model.strategies import element_values, models
from tests.conftest import PER_CLASS
from tests.support.node_classes import TYPED_CLASSES, _reference_equal, _same_compiled

# -- The fast paths of ``==``, ``hash``, ``to_dict`` and ``from_dict`` give the plain answers. -
#
# ``==`` and ``hash`` compare two nodes storing the same fields in the same order
# as two tuples, and every other pair field by field; ``to_dict`` and
# ``from_dict`` work on the fields a node stores with the converter's hooks. Each
# test sets a fast path against the slow answer it stands for: equality field by
# field as attrs defines it, the converter's own dicts, and MuJoCo compiling the
# models that compare equal to the same arrays.


def _world(*children: Node) -> Mujoco:
    return Mujoco(children=[Worldbody(children=list(children))])


def test_stored_default_equals_absent_field() -> None:
    """A node storing a field at its default equals and hashes like one leaving it out."""
    plain = Geom(name="g", size=[0.1])
    stored = [
        Geom(name="g", size=[0.1], extra={}),
        Geom(name="g", size=[0.1], extra=AttributeMap.unchecked({})),  # equal, not the same map
        attrs.evolve(Geom(name="g", size=[0.1], pos=[1, 2, 3]), pos=None),
        Geom(size=[0.1], name="g", attribute_order=("size", "name")),
    ]
    for node in stored:
        assert node == plain and plain == node
        assert hash(node) == hash(plain)
        assert Body(children=[node]) == Body(children=[plain])
        assert hash(Body(children=[node])) == hash(Body(children=[plain]))
    assert GenericElement(tag="flag", attributes={}) == GenericElement(tag="flag")
    assert hash(GenericElement(tag="flag", attributes={})) == hash(GenericElement(tag="flag"))
    assert Geom(name="g", size=[0.1], extra={"foo": "1"}) != plain
    one, two = (GenericElement(tag="flag", attributes={"a": text}) for text in "12")
    assert one != two and hash(one) != hash(two)  # ``attributes`` is hashed, not only compared
    _same_compiled(_world(stored[0]), _world(plain))


def test_loaded_values_equal_built_ones() -> None:
    """``size="1.0"`` read from text equals ``size=[1]`` built in code, and compiles the same."""
    loaded = loads(
        "<mujoco><worldbody><body pos='0 0 1.0'><joint type='hinge' range='-1 1.0'/>"
        "<geom size='1.0' rgba='1 0 0 1'/></body></worldbody></mujoco>"
    )
    built = _world(
        Body(
            pos=[0, 0, 1],
            children=[Joint(type="hinge", range=(-1, 1)), Geom(size=[1], rgba=[1, 0, 0, 1])],
        )
    )
    assert loaded == built and built == loaded
    assert hash(loaded) == hash(built)
    _same_compiled(loaded, built)
    moved = _world(attrs.evolve(built.worldbody.bodies[0], pos=[0, 0, 2]))
    assert loaded != moved
    assert model_differences(compiled(loaded), compiled(moved)) != []


def test_attribute_order_and_layout_are_ignored() -> None:
    """Elements written with their attributes in another order are equal and compile the same."""
    first = loads("<mujoco><worldbody><geom name='a' size='1' pos='0 0 1'/></worldbody></mujoco>")
    second = loads(
        "<mujoco><worldbody>\n  <geom pos='0 0 1' size='1.0' name='a' />\n</worldbody></mujoco>"
    )
    assert first == second and hash(first) == hash(second)
    _same_compiled(first, second)
    third = loads("<mujoco><worldbody><geom name='a' size='2' pos='0 0 1'/></worldbody></mujoco>")
    assert first != third


def test_nan_equals_nan() -> None:
    """NaN, in a single number or in a vector, equals NaN however it was written."""
    nan = float("nan")
    assert Joint(armature=nan) == Joint(armature=math.nan)
    assert hash(Joint(armature=nan)) == hash(Joint(armature=math.nan))
    assert Joint(armature=nan, name="j") == Joint(name="j", armature=math.nan)  # one NaN field
    loaded = loads("<mujoco><worldbody><geom size='nan 1'/></worldbody></mujoco>")
    built = _world(Geom(size=[nan, 1]))
    assert loaded == built and hash(loaded) == hash(built)
    reordered = Geom(rgba=[1, 1, 1, 1], size=[nan, 1])
    assert reordered == Geom(size=[nan, 1], rgba=[1, 1, 1, 1])
    assert Joint(armature=nan) != Joint(armature=1.0)
    assert Geom(size=[nan, 1]) != Geom(size=[nan, 2])


def _chain(depth: int, last_size: str) -> str:
    opening = "".join(f"<body name='b{i}'><geom size='0.1'/>" for i in range(depth))
    closing = "</body>" * depth
    geom = f"<geom name='last' size='{last_size}'/>"
    return f"<mujoco><worldbody>{opening}{geom}{closing}</worldbody></mujoco>"


def test_deep_trees_compare_and_hash() -> None:
    """Chains far deeper than Python's recursion limit compare and hash, down to the last leaf."""
    depth = 5000
    first, second = loads(_chain(depth, "0.1")), loads(_chain(depth, "0.1"))
    assert first == second and hash(first) == hash(second)
    changed = loads(_chain(depth, "0.2"))
    assert first != changed and hash(first) != hash(changed)
    built: Node = Geom(name="last", size=[0.1])
    for i in reversed(range(depth)):
        built = Body(name=f"b{i}", children=[Geom(size=[0.1]), built])
    assert first == _world(built) and hash(first) == hash(_world(built))


def test_shared_subtrees_are_skipped_not_misread() -> None:
    """A subtree shared by both sides is equal by identity; a changed leaf beside it is seen."""
    shared = loads(_chain(50, "0.1")).worldbody
    leaf = Geom(name="x", size=[float("nan")])
    left = Mujoco(children=[shared, Comment(text=" c "), Worldbody(children=[leaf])])
    right = Mujoco(children=[shared, Comment(text=" c "), Worldbody(children=[leaf])])
    assert left == right and hash(left) == hash(right)
    other = Mujoco(children=[shared, Comment(text=" d "), Worldbody(children=[leaf])])
    assert left != other


@pytest.mark.parametrize("cls", TYPED_CLASSES, ids=lambda c: c.__name__)
def test_equality_matches_attrs_for_every_class(cls: type[TypedElement]) -> None:
    """``==`` agrees with attrs' field-by-field equality, and equal nodes hash alike."""

    @PER_CLASS
    @given(element_values(cls), element_values(cls), st.randoms())
    def check(values: dict[str, Any], others: dict[str, Any], random: Any) -> None:
        node = cls(**values)
        shuffled = list(values.items())
        random.shuffle(shuffled)
        again = cls(**dict(shuffled))  # the same fields, stored in another order
        assert node == again and hash(node) == hash(again)
        rebuilt = from_dict(json.loads(json.dumps(to_dict(node))))
        assert rebuilt == node and hash(rebuilt) == hash(node)
        for changes in (others, {**values, **others}):
            other = cls(**changes)
            assert (node == other) == _reference_equal(node, other)
            assert (Body(children=[node]) == Body(children=[other])) == (node == other)
            if node == other:
                assert hash(node) == hash(other)

    check()


@given(models())
def test_models_equal_after_every_route(model: Mujoco) -> None:
    """A model equals itself read back from text and from dicts, hashes alike, compiles alike."""
    text = dumps(model)
    loaded = loads(text)
    rebuilt = from_dict(to_dict(loaded))
    for twin in (loaded, rebuilt):
        assert twin == model and model == twin
        assert hash(twin) == hash(model)
        assert _reference_equal(twin, model)
    assert len({model, loaded, rebuilt}) == 1
    _same_compiled(rebuilt, model)
