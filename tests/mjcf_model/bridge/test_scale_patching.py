"""``patched`` writes a scaled variant into the compiled model: MuJoCo compiling it is the referee.

``patched(compiled(m), m, scaled(m, s, mass=...))`` must give what
``compiled(scaled(m, s, mass=...))`` gives, array for array, within the tolerances of
:mod:`tests.support.scaled_patch_oracle` (32-bit mesh vertices are rounded again when a
scaled mesh is compiled); or compile in full and say why, for the cases MuJoCo derives
otherwise (flexes, muscles' length ranges, an offset crossing MuJoCo's "same frame"
tolerance, masses on a surface under ``mass="volume"``, per-axis factors).
"""

from __future__ import annotations

import copy
import warnings
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest
from hypothesis import HealthCheck, given, note, settings
from hypothesis import strategies as st

from mjcf_model import (
    MjcfError,
    MjcfRecompiledWarning,
    compiled,
    map_elements,
    patched,
    scaled,
    with_attributes,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.strategies import models
from tests.conftest import FIXTURES, MUJOCO_VERSION, compiling_corpus, corpus_id
from tests.mjcf_model.bridge.test_patching import variant
from tests.support.scaled_patch_oracle import patched_problems

#: Before MuJoCo 4.0 a scaled variant is always compiled (its mesh frames are derived anew).
OLD = MUJOCO_VERSION < (4, 0)
#: Why a variant may be compiled in full, on any model.
ANY_MODEL = ("MuJoCo before 4.0",) if OLD else ()
#: The factors and mass policies the corpus models take in turn.
DRAWS = ((1.17, "volume"), (0.83, "keep"), (1.3, "keep"), (0.9, "volume"))


def _scaled_and_expected(before: Mujoco, factor: Any, mass: str) -> tuple[Any, Any, list[str]]:
    """``patched``'s scaled variant, MuJoCo's compilation of it, and why it compiled."""
    model = compiled(before)
    after = scaled(before, factor, mass=mass)  # type: ignore[arg-type]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", MjcfRecompiledWarning)
        result = patched(model, before, after)
    reasons = [str(w.message) for w in caught if issubclass(w.category, MjcfRecompiledWarning)]
    return result, compiled(after), reasons


def _corpus() -> list[Path]:
    """The compiling corpus (every 7th file before MuJoCo 4.0, where each compiles anyway)."""
    return compiling_corpus()[:: 7 if OLD else 1]


@pytest.mark.parametrize("path", _corpus(), ids=corpus_id)
def test_scaled_corpus_variants_are_compiled_variants(path: Path) -> None:
    """Each corpus model scaled (factors and policies in turn): patched, not compiled."""
    factor, mass = DRAWS[_corpus().index(path) % len(DRAWS)]
    before = load(path, inline_includes=True)
    result, expected, reasons = _scaled_and_expected(before, factor, mass)
    assert patched_problems(result, expected) == []
    # dm_control's dogs have a body whose centre of mass is 1.1 micrometres from its
    # frame: scaled by 0.9, MuJoCo then takes the frames for one (and compiles faster)
    crossing = ("MuJoCo's 1e-06 tolerance",) if "dog" in path.name else ()
    assert all(any(why in reason for why in (*ANY_MODEL, *crossing)) for reason in reasons)


#: Every fixture MuJoCo compiles (includes inlined), with what it makes compile in full.
FIXTURE_REASONS = {
    "flex.xml": "flexes derive",
    "flexcomp.xml": "flexes derive",
    "rope_kid.xml": "flexes derive",
    "angles.xml": "flexes derive",
    "mechanics.xml": "a muscle's length range",
    "replicate.xml": "cannot tell which compiled actuator",
    "plugins.xml": "plugin",
    "sdf.xml": "plugin",
    "sdf_gear.xml": "plugin",
}


def _fixtures() -> list[Path]:
    """The fixtures MuJoCo compiles and ``scaled`` scales (not an ``<attach>``, a nut's SDF)."""
    found = []
    for path in sorted(FIXTURES.rglob("*.xml")):
        try:
            mujoco.MjModel.from_xml_path(str(path))
            scaled(load(path, inline_includes=True), 1.2)
        except (ValueError, MjcfError):
            continue
        found.append(path)
    return found


@pytest.mark.parametrize("mass", ["keep", "volume"])
@pytest.mark.parametrize("path", _fixtures(), ids=lambda p: str(p.relative_to(FIXTURES)))
def test_scaled_fixture_variants_are_compiled_variants(path: Path, mass: str) -> None:
    """The fixtures hold every length-bearing element: each scaled both ways."""
    before = load(path, inline_includes=True)
    result, expected, reasons = _scaled_and_expected(before, 1.2, mass)
    assert patched_problems(result, expected) == []
    allowed = (*ANY_MODEL, FIXTURE_REASONS.get(path.name, "nothing else"))
    if mass == "volume" and path.name == "mass.xml":
        allowed += ("spreads its mass over its surface",)
    assert all(any(why in reason for why in allowed) for reason in reasons), reasons


@settings(suppress_health_check=[HealthCheck.too_slow])
@given(
    model=models(),
    factor=st.floats(0.5, 2.0),
    mass=st.sampled_from(["keep", "volume"]),
)
def test_scaled_drawn_models_are_compiled_variants(model: Mujoco, factor: float, mass: str) -> None:
    """Any drawn model scaled by any factor: the patched arrays are MuJoCo's."""
    note(dumps(model))
    result, expected, reasons = _scaled_and_expected(model, factor, mass)
    assert patched_problems(result, expected) == []
    allowed = (
        *ANY_MODEL,
        "flexes derive",
        "MuJoCo's 1e-06 tolerance",
        "spreads its mass over its surface",
        "cannot tell which compiled",
    )
    assert all(any(why in reason for why in allowed) for reason in reasons), reasons


@pytest.mark.skipif(OLD, reason="before MuJoCo 4.0 every scaled variant compiles")
def test_scaled_and_physical_variants_take_turns_in_one_scratch_model() -> None:
    """A loop writing scaled and physical variants into one model: each is MuJoCo's."""
    robot = load(FIXTURES / "keyframes.xml")
    base = compiled(robot)
    scratch = copy.copy(base)
    turns: list[Mujoco] = [
        scaled(robot, 1.25, mass="volume"),
        variant(robot, 3)[0],
        scaled(robot, 0.8),
        scaled(robot, 1.1),
        variant(robot, 4)[0],
    ]
    for after in turns:
        with warnings.catch_warnings():
            warnings.simplefilter("error", MjcfRecompiledWarning)
            result = patched(base, robot, after, into=scratch)
        assert result is scratch
        assert patched_problems(result, compiled(after)) == []
    assert model_differences(base, compiled(robot)) == []


def _warned(before: Mujoco, after: Mujoco) -> str:
    with pytest.warns(MjcfRecompiledWarning) as caught:
        result = patched(compiled(before), before, after)
    assert model_differences(result, compiled(after)) == []
    return str(caught[0].message)


_BALL = """<mujoco><worldbody><body name="b" pos="0 0 1"><freejoint/>
<geom size="0.1"/>{inertial}</body></worldbody></mujoco>"""


@pytest.mark.skipif(OLD, reason="before MuJoCo 4.0 every scaled variant compiles")
def test_what_cannot_be_written_is_compiled_and_named() -> None:
    """Per-axis factors; an offset scaling carries across MuJoCo's tolerance; another model."""
    ball = loads(_BALL.format(inertial=""))
    assert "per-axis" in _warned(ball, scaled(ball, [1, 1, 2]))
    near = loads(_BALL.format(inertial='<inertial pos="1.2e-6 0 0" mass="1" diaginertia="1 1 1"/>'))
    message = _warned(near, scaled(near, 0.8))
    assert "body 1 (1.2e-06)" in message and "tolerance" in message
    # a variant scaled from an equal model, not this one, is compared as any other
    assert "changed" in _warned(ball, scaled(loads(_BALL.format(inertial="")), 2))


_SERVO = """<mujoco><worldbody><body name="arm" pos="0 0 0.5">
<joint name="hinge" axis="0 1 0"/><geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.04"/>
<body name="slider" pos="0.3 0 0"><joint name="slide" type="slide" axis="1 0 0" range="-0.1 0.1"/>
<inertial pos="0 0 0" mass="0.4" diaginertia="1e-3 1e-3 1e-3"/>
<geom name="tip" size="0.05"/></body></body></worldbody>
<actuator><position name="turn" joint="hinge" kp="20" dampratio="0.7"/>
<position name="push" joint="slide" kp="100" dampratio="1" ctrlrange="-0.1 0.1"/></actuator>
<keyframe><key qpos="0.2 0.05" ctrl="0.1 0.02"/></keyframe></mujoco>"""


@pytest.mark.parametrize("default", ["position", "general"])
def test_a_class_given_slide_target_range_is_patched_as_scaled_compiles(default: str) -> None:
    """The class's ctrlrange doubles on the slide servo, stays on the hinge servo, as compiled."""
    before = loads(
        f"""<mujoco><default><default class="servo"><{default} ctrlrange="-.5 .5"/>
        </default></default>
        <worldbody><body><joint name="rail" type="slide"/><joint name="pin" axis="0 1 0"/>
          <geom size=".1"/></body></worldbody>
        <actuator><position class="servo" joint="rail" kp="10"/>
          <position class="servo" joint="pin" kp="10"/></actuator></mujoco>"""
    )
    ours, expected, _ = _scaled_and_expected(before, 2.0, "volume")
    assert expected.actuator_ctrlrange.tolist() == [[-1.0, 1.0], [-0.5, 0.5]]
    assert patched_problems(ours, expected) == []


@pytest.mark.skipif(OLD, reason="before MuJoCo 4.0 masses are not patched")
def test_position_servo_damping_ratios_follow_masses_and_scale() -> None:
    """A ``dampratio`` servo's damping follows the masses it moves, scaled or changed."""
    robot = loads(_SERVO)

    def heavy(element: Any, key: str | None, ancestors: Any) -> Any:
        return with_attributes(element, {"mass": 1.2}) if key == "body/inertial" else element

    heavier = map_elements(heavy, robot)
    for after in (heavier, scaled(robot, 1.4, mass="volume"), scaled(robot, 0.7)):
        with warnings.catch_warnings():
            warnings.simplefilter("error", MjcfRecompiledWarning)
            result = patched(compiled(robot), robot, after)
        expected = compiled(after)
        assert np.allclose(result.actuator_biasprm, expected.actuator_biasprm, rtol=1e-12)
        assert patched_problems(result, expected) == []
    assert not np.allclose(compiled(heavier).actuator_biasprm, compiled(robot).actuator_biasprm)
