"""Tests of ``mjcf_model.nodes.equality``: constraints that connect, weld or couple objects."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Connect, EqualityJoint, EqualityTendon, Weld
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

MECHANICS = FIXTURES / "mechanics.xml"
MODULE = "mjcf_model.nodes.equality"

#: MuJoCo's type of each equality class.
TYPES = {
    Connect: mujoco.mjtEq.mjEQ_CONNECT,
    Weld: mujoco.mjtEq.mjEQ_WELD,
    EqualityJoint: mujoco.mjtEq.mjEQ_JOINT,
    EqualityTendon: mujoco.mjtEq.mjEQ_TENDON,
}


def test_equalities_load_typed_and_are_the_constraints_mujoco_compiles() -> None:
    """Each element is a constraint of its class's type, active as written, with its data."""
    model = load(MECHANICS)
    found = loaded_from(model, MODULE)
    assert found == {"Equality", "Connect", "Weld", "EqualityJoint", "EqualityTendon"}
    assert found <= declared_in(MODULE)
    assert {"EqualityFlex"} <= loaded_from(load(FIXTURES / "flex.xml"), MODULE)
    compiled = mujoco.MjModel.from_xml_path(str(MECHANICS))
    constraints = model.equality.elements
    assert [TYPES[type(e)] for e in constraints] == compiled.eq_type.tolist()
    assert [e.active is not False for e in constraints] == compiled.eq_active0.tolist()
    couple = next(e for e in constraints if e.name == "couple_pulleys")
    assert isinstance(couple, EqualityJoint)
    assert np.array_equal(
        couple.polycoef, compiled.eq_data[compiled.equality("couple_pulleys").id][:5]
    )
    assert text_round_trip_differences(MECHANICS.read_text()) == []
