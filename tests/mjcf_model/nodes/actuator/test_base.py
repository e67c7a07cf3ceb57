"""Tests of ``mjcf_model.nodes.actuator.base``: the ``<actuator>`` section and ``<general>``."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Actuator, General
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

MECHANICS = FIXTURES / "mechanics.xml"


def test_general_actuators_load_typed_and_compile_as_written() -> None:
    """``<general>`` holds the parameters MuJoCo compiles; the section lists every actuator."""
    model = load(MECHANICS)
    assert (
        loaded_from(model, "mjcf_model.nodes.actuator.base")
        == declared_in("mjcf_model.nodes.actuator.base")
        == {"Actuator", "General"}
    )
    compiled = mujoco.MjModel.from_xml_path(str(MECHANICS))
    section = next(c for c in model.children if isinstance(c, Actuator))
    assert len(section.elements) == compiled.nu
    general = next(a for a in section.elements if isinstance(a, General))
    assert general.name == "wrist_general"
    assert np.array_equal(general.gainprm, compiled.actuator("wrist_general").gainprm[:1])
    assert np.array_equal(general.biasprm, compiled.actuator("wrist_general").biasprm[:3])
    assert np.array_equal(general.actrange, compiled.actuator("wrist_general").actrange)
    assert text_round_trip_differences(MECHANICS.read_text()) == []
