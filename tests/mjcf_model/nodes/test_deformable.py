"""Tests of ``mjcf_model.nodes.deformable``: ``<flexcomp>`` and the ``<deformable>`` section."""

from __future__ import annotations

import mujoco

from mjcf_model import Flex, Flexcomp, FlexcompEdge, FlexEdge
from mjcf_model.bridge.compare import compiled_names
from mjcf_model.serializers import load
from mjcf_model.tree.traversal import walk
from tests.conftest import FIXTURES
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

FLEX = FIXTURES / "flex.xml"
MODULE = "mjcf_model.nodes.deformable"


def test_flexes_load_typed_and_are_the_flexes_mujoco_builds() -> None:
    """Every flexcomp and flex is one of MuJoCo's flexes, with its dimension, radius, damping."""
    model = load(FLEX)
    assert loaded_from(model, MODULE) == declared_in(MODULE)
    compiled = mujoco.MjModel.from_xml_path(str(FLEX))
    flexes = [e for _, e in walk(model) if isinstance(e, (Flex, Flexcomp))]
    assert sorted(f.name for f in flexes) == sorted(compiled_names(compiled)["flex"])
    index = {name: i for i, name in enumerate(compiled_names(compiled)["flex"])}
    for flex in flexes:
        assert flex.dim == compiled.flex_dim[index[flex.name]], flex.name
        assert flex.radius == compiled.flex_radius[index[flex.name]], flex.name
        edges = [e for e in flex.children if isinstance(e, (FlexEdge, FlexcompEdge))]
        for edge in edges:
            assert edge.damping == compiled.flex_edgedamping[index[flex.name]], flex.name
    assert text_round_trip_differences(FLEX.read_text()) == []
