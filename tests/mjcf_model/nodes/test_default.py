"""Tests of ``mjcf_model.nodes.default``: default classes and their typed view."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Default, Muscle
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.node_classes import loaded_from, text_round_trip_differences

MECHANICS = FIXTURES / "mechanics.xml"


def test_nested_classes_follow_document_order_and_give_mujoco_their_values() -> None:
    """``defaults`` lists the nested classes in order; MuJoCo applies a class's values."""
    model = load(MECHANICS)
    assert loaded_from(model, "mjcf_model.nodes.default") == {"Default"}
    main = next(c for c in model.children if isinstance(c, Default))
    assert [d.dclass for d in main.defaults] == ["muscle", "wrap"]
    assert main.defaults[1].defaults == ()
    muscle = next(e for e in main.defaults[0].elements if isinstance(e, Muscle))
    compiled = mujoco.MjModel.from_xml_path(str(MECHANICS))
    # triceps_muscle writes no ctrlrange: it has the class's
    assert np.array_equal(muscle.ctrlrange, compiled.actuator("triceps_muscle").ctrlrange)
    assert text_round_trip_differences(MECHANICS.read_text()) == []
