"""Tests of ``mjcf_model.serializers.dict_codec``."""

from __future__ import annotations

import json
from typing import Any

import pytest
from hypothesis import given

from mjcf_model import (
    AttributeMap,
    Body,
    GenericElement,
    Geom,
    Node,
    TypedElement,
)
from mjcf_model.errors import MjcfValueError
from mjcf_model.serializers import dicts, dumps, from_dict, loads, to_dict
from mjcf_model.strategies import elements
from mjcf_model.tree.traversal import with_children
from mjcf_model.values import Unparsed
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


def _converter_dict(node: Node) -> dict[str, Any]:
    """``to_dict`` as the converter alone writes it: each node unstructured, then its children."""
    shallow = with_children(node, ()) if getattr(node, "children", ()) else node
    out: dict[str, Any] = dicts.default_converter().unstructure(shallow, Node)
    out.pop("layout", None)
    for key, value in out.items():
        if type(value) is Unparsed:
            out[key] = {"_unparsed": value.text}
    if shallow is not node:
        out["children"] = [_converter_dict(child) for child in node.children]  # type: ignore[attr-defined]
    return out


def _ordered(data: Any) -> Any:
    """``data`` with every dict as its list of items, so that key order is compared too."""
    if isinstance(data, dict):
        return [(key, _ordered(value)) for key, value in data.items()]
    if isinstance(data, list):
        return [_ordered(item) for item in data]
    return data


@pytest.mark.parametrize("cls", TYPED_CLASSES, ids=lambda c: c.__name__)
def test_dicts_are_the_converters_own(cls: type[TypedElement]) -> None:
    """``to_dict`` writes the converter's dict, key order included; ``from_dict`` reads it back."""

    @PER_CLASS
    @given(elements(cls))
    def check(node: TypedElement) -> None:
        data = to_dict(node)
        assert _ordered(data) == _ordered(_converter_dict(node))
        json.dumps(data, allow_nan=False)
        rebuilt = from_dict(data)
        through_converter = dicts.default_converter().structure(
            {k: v for k, v in data.items() if not _is_unparsed(v)}, Node
        )
        assert list(vars(rebuilt)) == [k for k in vars(through_converter)] + [
            k for k, v in data.items() if _is_unparsed(v)
        ]
        assert rebuilt == node and _reference_equal(rebuilt, node)

    check()


def test_stored_defaults_are_left_out_of_dicts() -> None:
    """A field stored at its default is left out of the dict, as the converter leaves it out."""
    for node in (
        Geom(name="g", extra=AttributeMap.unchecked({})),
        GenericElement(tag="flag", attributes=AttributeMap.unchecked({})),
        Body(name="b", attribute_order=()),
    ):
        assert _ordered(to_dict(node)) == _ordered(_converter_dict(node))
        assert set(to_dict(node)) == {"name" if "name" in vars(node) else "tag", "_node"}


@pytest.mark.parametrize(
    "data",
    [
        {"_node": "Geom", "name": 5},
        {"_node": "Geom", "condim": 1.5, "density": 2},
        {"_node": "Geom", "attribute_order": "ab", "size": [1, 2]},
        {"_node": "Mujoco", "base_dir": "/robots"},
        {"_node": "Geom", "size": None, "extra": {"foo": "bar"}},
        {"_node": "Joint", "range": ["-inf", "inf"], "armature": "nan"},
        {"_node": "Comment", "text": " c ", "children": []},
        {"_node": "Geom", "extra": None},
        {"_node": "Comment", "text": None},
    ],
)
def test_from_dict_reads_values_as_the_converter_does(data: dict[str, Any]) -> None:
    """Each value goes through the converter's hook for its field: ``5`` as a name is ``"5"``."""
    try:
        expected = dicts.default_converter().structure(
            {k: v for k, v in data.items() if k != "children"}, Node
        )
    except Exception:  # the converter refuses it: so does from_dict
        with pytest.raises(MjcfValueError, match="not a node dict"):
            from_dict(data)
        return
    rebuilt = from_dict(data)
    assert type(rebuilt) is type(expected)
    assert list(vars(rebuilt).items()) == list(vars(expected).items())


def _is_unparsed(value: Any) -> bool:
    return isinstance(value, dict) and set(value) == {"_unparsed"}


def test_loaded_model_dicts_round_trip_and_compile() -> None:
    """A loaded model's dicts are the converter's, and read back to a model compiling the same."""
    text = (
        "<mujoco model='m'><!-- kept --><compiler angle='radian'/>"
        "<default><default class='c'><geom rgba='1 0 0 1'/></default></default>"
        "<worldbody><body name='b' pos='0 0 1'><freejoint/>"
        "<geom class='c' size='0.1'/><site name='s' pos='0 0 inf'/></body>"
        "</worldbody><visual><global offwidth='800'/></visual></mujoco>"
    )
    model = loads(text.replace(" pos='0 0 inf'", ""))
    data = to_dict(model)
    assert _ordered(data) == _ordered(_converter_dict(model))
    rebuilt = from_dict(json.loads(json.dumps(data, allow_nan=False)))
    assert rebuilt == model and hash(rebuilt) == hash(model)
    _same_compiled(rebuilt, model)
    with_inf = loads(text)
    assert to_dict(with_inf)["children"][3]["children"][0]["children"][2]["pos"] == [
        0.0,
        0.0,
        "inf",
    ]
    assert from_dict(to_dict(with_inf)) == with_inf


def test_unparsed_text_round_trips_through_dicts() -> None:
    """Text a typed field cannot read, numbers and integers alike, comes back verbatim."""
    text = (
        "<mujoco><asset><mesh name='m' vertex='0 0 0 1 0 0 0 1 0' face='0 1 x'/></asset>"
        "<worldbody><geom size='0x10' condim='q'/></worldbody></mujoco>"
    )
    model = loads(text)
    data = to_dict(model)
    mesh, geom = data["children"][0]["children"][0], data["children"][1]["children"][0]
    assert mesh["face"] == {"_unparsed": "0 1 x"}
    assert geom["size"] == {"_unparsed": "0x10"} and geom["condim"] == {"_unparsed": "q"}
    rebuilt = from_dict(json.loads(json.dumps(data)))
    assert rebuilt == model and dumps(rebuilt) == dumps(model, canonical=True)


@pytest.mark.parametrize(
    ("data", "message"),
    [
        ({"_node": "NoSuchNode"}, "NoSuchNode"),
        ({"_node": "Geom", "colour": "red"}, r"extra fields found \(colour\) @ \$"),
        ({"_node": "Geom", "size": "abc"}, r"@ \$\.size"),
        ({"_node": "Geom", "layout": {"start": "<geom/>"}}, "layout"),
        ({"_node": "Comment"}, r"required field missing @ \$\.text"),
        ({"_node": "Comment", "text": "a", "children": [{"_node": "Geom"}]}, "has no children"),
        ({"_node": "GenericElement", "tag": "x", "text": {"_unparsed": "1"}}, "only typed"),
        (
            {"_node": "Body", "children": [{"_node": "Geom"}, {"_node": "Geom", "condim": "q"}]},
            r"@ \$\.children\[1\]\.condim",
        ),
        ({"_node": "Body", "children": [{"_node": "Geom", "children": None}]}, "must be a list"),
        ({"_node": "Geom", "type": "blob"}, r"invalid value @ \$"),
    ],
)
def test_bad_dicts_are_explained(data: dict[str, Any], message: str) -> None:
    """A dict the fast path cannot build still fails with the converter's message and path."""
    with pytest.raises(MjcfValueError, match=message):
        from_dict(data)


def test_a_node_class_whose_types_do_not_resolve_leaves_dicts_working() -> None:
    """A subclass declared where its annotations cannot resolve does not break ``to_dict``.

    Such a class (declared in a function or a doctest, its types imported only for
    type checkers) used to make the converter fail for every node.
    """
    namespace: dict[str, Any] = {}
    exec(  # a class whose annotation names a type nothing defines
        "from __future__ import annotations\n"
        "import attrs\n"
        "from mjcf_model.nodes.base import TypedElement\n"
        "@attrs.frozen(kw_only=True)\n"
        "class Unresolvable(TypedElement):\n"
        "    thing: NowhereDefined | None = None\n",
        namespace,
    )
    dicts._default_for.cache_clear()
    try:
        geom = Geom(name="g", size=[0.1])
        assert from_dict(to_dict(geom)) == geom
    finally:
        dicts._default_for.cache_clear()
