"""Tests of ``mjcf_model.nodes.root``."""

from __future__ import annotations

from mjcf_model import (
    Actuator,
    Comment,
    Compiler,
    Contact,
    Default,
    Equality,
    Mujoco,
    Option,
    Sensor,
    Tendon,
    Worldbody,
)
from mjcf_model.serializers import load
from tests.conftest import FIXTURES
from tests.support.fixture_checks import section

# -- Round trips of hand-written MJCF fixtures for features the robosuite/dm_control corpus
#    lacks.
#
# Every fixture under ``tests/fixtures`` compiles in MuJoCo as written. Each must
# survive every serializer (text, file, ElementTree, dict) unchanged and compile,
# after the round trip, to a model identical field by field to the original.


# -- the fixture set ----------------------------------------------------------------------


def test_root_section_accessors() -> None:
    """Each section property of the root returns the first child of that section type."""
    model = load(FIXTURES / "mechanics.xml")
    expected = {
        "compiler": Compiler,
        "option": Option,
        "default": Default,
        "worldbody": Worldbody,
        "contact": Contact,
        "tendon": Tendon,
        "equality": Equality,
        "actuator": Actuator,
        "sensor": Sensor,
    }
    for attribute, cls in expected.items():
        assert getattr(model, attribute) is section(model, cls)
    absent = ("size", "statistic", "visual", "asset", "deformable", "keyframe", "custom")
    for attribute in (*absent, "extension"):
        assert getattr(model, attribute) is None


# -- Node behaviour: immutability, typed views, attribute order, generic elements, values. -----


def test_root_section_properties() -> None:
    """``model.worldbody`` and friends return the first section of that kind or None."""
    world = Worldbody()
    model = Mujoco(children=[Comment(text="c"), world])
    assert model.worldbody is world
    assert model.asset is None and model.actuator is None
