"""Tests of ``mjcf_model.strategies.registry``: the names a model being drawn declares."""

from __future__ import annotations

from mjcf_model.strategies.registry import _Names, _Registry


def test_names_are_unique_per_namespace_and_counted() -> None:
    """Each namespace numbers its own names from 0; ``most`` is the longest count."""
    issued = _Names()
    assert [issued("body"), issued("geom"), issued("body"), issued("body")] == [
        "body0",
        "geom0",
        "body1",
        "body2",
    ]
    assert issued.most() == 3
    assert _Names().most() == 0


def test_a_fresh_registry_declares_nothing_and_reads_degrees() -> None:
    """A new registry holds no names, MuJoCo's default angle unit, and no replicate."""
    registry = _Registry()
    assert registry.angle == "degree" and registry.replicates is False
    assert registry.bodies == [] and registry.scalar_joints == [] and registry.tendons == []
    assert _Registry().bodies is not registry.bodies  # each registry its own lists
