"""Round-trip properties over models drawn by the shipped strategies."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import mujoco
import pytest
from hypothesis import given

from mjcf_model import Mujoco, TypedElement
from mjcf_model.bridge.compare import model_differences
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.serializers import dumps, from_dict, from_etree, loads, to_dict, to_etree
from mjcf_model.strategies import elements, models
from tests.conftest import PER_CLASS
from tests.support.node_classes import TYPED_CLASSES


@given(models())
def test_text_round_trip(model: Mujoco) -> None:
    """``loads(dumps(m)) == m`` and writing is idempotent."""
    text = dumps(model)
    again = loads(text)
    assert again == model
    assert dumps(again) == text


@given(models())
def test_dict_round_trip(model: Mujoco) -> None:
    """``from_dict(to_dict(m)) == m`` through strict JSON."""
    data = json.loads(json.dumps(to_dict(model), allow_nan=False))
    assert from_dict(data) == model


@given(models())
def test_etree_round_trip(model: Mujoco) -> None:
    """``from_etree(to_etree(m)) == m``, also after ElementTree's own text round trip."""
    element = to_etree(model)
    assert from_etree(element) == model
    parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))
    text = ET.tostring(element, encoding="unicode")  # us-ascii would garble comments
    assert from_etree(ET.fromstring(text, parser=parser)) == model


@given(models())
def test_generated_models_compile_and_survive(model: Mujoco) -> None:
    """MuJoCo compiles every generated model, and the round trip compiles identically."""
    text = dumps(model)
    original = mujoco.MjModel.from_xml_string(text)
    again = mujoco.MjModel.from_xml_string(dumps(loads(text)))
    assert model_differences(original, again) == []


@pytest.mark.parametrize("cls", TYPED_CLASSES, ids=lambda c: c.__name__)
def test_every_element_type_round_trips(cls: type[TypedElement]) -> None:
    """Arbitrary values of every typed class survive dicts, ElementTree and text."""

    @PER_CLASS
    @given(elements(cls))
    def check(node: TypedElement) -> None:
        assert from_dict(to_dict(node)) == node
        key = next(k for k, c in CLASS_BY_KEY.items() if c is cls)
        context = key.rsplit("/", 1)[0] if "/" in key else "mujoco"
        if key in {"mujoco", "include"}:
            context = None if key == "mujoco" else "mujoco"
        assert from_etree(to_etree(node), context=context) == node
        assert from_etree(ET.fromstring(dumps(node)), context=context) == node

    check()
