"""Tests of ``mjcf_model.nodes.contact``: explicit contact pairs and exclusions."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Contact, Pair
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

MECHANICS = FIXTURES / "mechanics.xml"
MODULE = "mjcf_model.nodes.contact"


def test_pairs_and_exclusions_load_typed_and_are_mujocos() -> None:
    """A pair's settings are MuJoCo's pair arrays; every exclusion is one MuJoCo excludes."""
    model = load(MECHANICS)
    assert loaded_from(model, MODULE) == declared_in(MODULE) == {"Contact", "Pair", "Exclude"}
    compiled = mujoco.MjModel.from_xml_path(str(MECHANICS))
    contact = next(c for c in model.children if isinstance(c, Contact))
    pairs = [p for p in contact.elements if isinstance(p, Pair)]
    assert len(pairs) == compiled.npair and len(contact.elements) - len(pairs) == compiled.nexclude
    assert pairs[0].condim == compiled.pair_dim[0]
    assert np.array_equal(pairs[0].friction, compiled.pair_friction[0])
    assert pairs[1].margin == compiled.pair_margin[1] and pairs[1].gap == compiled.pair_gap[1]
    assert text_round_trip_differences(MECHANICS.read_text()) == []
