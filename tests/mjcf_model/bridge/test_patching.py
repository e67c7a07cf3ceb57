"""``patched`` gives, array for array, what ``compiled`` gives for a variant.

Every mapped attribute written in a model is changed (colours drawn, the other values
scaled by drawn factors, so they stay valid); MuJoCo compiling the variant in full is
the referee, over the shipped strategies' models and over the corpus. A change it
cannot map falls back to a full compile and says so.
"""

from __future__ import annotations

import copy
import re
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from mjcf_model import (
    MjcfRecompiledWarning,
    compiled,
    map_elements,
    map_tree,
    patched,
    with_attributes,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.bridge.patching import FIELDS
from mjcf_model.nodes.base import AnyElement, attribute_items, attribute_text, get_attribute
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers import load, loads
from mjcf_model.strategies import models
from mjcf_model.values import numbers_of
from tests.conftest import MUJOCO_VERSION, PER_CLASS, compiling_corpus, corpus_id

#: MuJoCo before 4.0 patches fewer fields (``patching._BEFORE_4``).
OLD = MUJOCO_VERSION < (4, 0)


def _changed_value(attribute: str, numbers: tuple[float, ...], rng: np.random.Generator) -> Any:
    """A valid new value of as many numbers: colours drawn, the rest scaled."""
    if attribute == "rgba":
        return tuple(float(v) for v in rng.uniform(0, 1, len(numbers)))
    if attribute == "solimp":
        d0 = float(rng.uniform(0.5, 0.9))
        drawn = (d0, float(rng.uniform(d0, 0.99)), float(rng.uniform(1e-4, 0.01)), 0.5, 2.0)
        return drawn[: len(numbers)]
    factor = float(rng.uniform(0.5, 2.0))
    return tuple(v * factor for v in numbers)


def _default_fields(key: str) -> dict[str, str]:
    """The mapped attributes of a default element (``default/geom`` sets ``body/geom``'s)."""
    tag = key.rpartition("/")[2]
    return FIELDS.get(f"body/{tag}") or FIELDS.get(f"actuator/{tag}") or {}


def variant(model: Mujoco, seed: int, *, classes: bool = True) -> tuple[Mujoco, int]:
    """``model`` with every mapped attribute it writes changed; how many were changed.

    With ``classes``, the default classes' mapped values are changed too.
    """
    rng = np.random.default_rng(seed)
    count = 0

    def change(element: AnyElement, key: str | None, ancestors: Any) -> AnyElement:
        nonlocal count
        in_class = classes and (key or "").startswith("default/")
        fields = _default_fields(key or "") if in_class else FIELDS.get(key or "", {})
        values = {}
        for name, value in attribute_items(element):
            numbers = numbers_of(value)
            if name in fields and numbers:
                values[name] = " ".join(repr(v) for v in _changed_value(name, numbers, rng))
        count += len(values)
        return with_attributes(element, values) if values else element

    return map_elements(change, model), count


def _patched_and_expected(before: Mujoco, after: Mujoco) -> tuple[Any, Any, list[str]]:
    model = compiled(before)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", MjcfRecompiledWarning)
        result = patched(model, before, after)
    reasons = [str(w.message) for w in caught if issubclass(w.category, MjcfRecompiledWarning)]
    return result, compiled(after), reasons


@settings(PER_CLASS, suppress_health_check=[HealthCheck.too_slow])
@given(model=models(), seed=st.integers(0, 2**32 - 1))
def test_patched_drawn_models_are_compiled_variants(model: Mujoco, seed: int) -> None:
    """Any drawn model, every mapped value changed: the patched arrays are MuJoCo's."""
    after, _ = variant(model, seed)
    result, expected, _ = _patched_and_expected(model, after)
    assert model_differences(result, expected) == []


@pytest.mark.parametrize("path", compiling_corpus(), ids=corpus_id)
def test_patched_corpus_variants_are_compiled_variants(path: Path) -> None:
    """Each corpus model with its mapped values changed: patched without recompiling."""
    before = load(path, inline_includes=True)
    after, _ = variant(before, 0)
    result, expected, reasons = _patched_and_expected(before, after)
    assert model_differences(result, expected) == []
    allowed = ("the compiler's", *(("MuJoCo before 4.0",) if OLD else ()))
    assert all(any(why in reason for why in allowed) for reason in reasons), reasons


def _recolored_everywhere(model: Mujoco) -> Mujoco:
    """Every geom recoloured, its default classes' ``<geom>`` included (a user's ``map_tree``)."""

    def recolor(node: Any) -> Any:
        if getattr(node, "tag", None) == "geom":
            return with_attributes(node, {"rgba": (0.2, 0.4, 0.6, 1.0)})
        return node

    return map_tree(recolor, model)


@pytest.mark.parametrize(
    "name", ["robots/panda/robot.xml", "suite/humanoid.xml", "suite/dog.xml", "suite/quadruped.xml"]
)
def test_recolouring_every_geom_and_class_is_patched_in_a_loop(name: str) -> None:
    """A user's loop: every geom and class recoloured, then physics varied, into one model.

    Nothing compiles again (the classes' changes reach exactly the geoms that take them), and
    each result is what MuJoCo compiles from that variant. The dog's joints have
    ``springdamper``: their stiffness and damping follow its changed masses.
    """
    (path,) = [p for p in compiling_corpus() if p.as_posix().endswith(name)]
    before = load(path, inline_includes=True)
    model = compiled(before)
    scratch = copy.copy(model)
    for after in (_recolored_everywhere(before), variant(before, 5)[0], before):
        with warnings.catch_warnings():
            if not OLD:
                warnings.simplefilter("error", MjcfRecompiledWarning)
            result = patched(model, before, after, into=scratch)
        assert model_differences(result, compiled(after)) == []


def _recolored(model: Mujoco, seed: int) -> Mujoco:
    """``model`` with only its geoms' written colours drawn again."""
    rng = np.random.default_rng(seed)

    def recolor(element: AnyElement, key: str | None, ancestors: Any) -> AnyElement:
        if key != "body/geom" or get_attribute(element, "rgba") is None:
            return element
        return with_attributes(element, {"rgba": _changed_value("rgba", (0,) * 4, rng)})

    return map_elements(recolor, model)


def _patched_in_turn(before: Mujoco, seed: int) -> None:
    """Every value changed, then only colours, then nothing: each patched into one scratch model."""
    model = compiled(before)
    scratch = copy.copy(model)
    for after in (variant(before, seed)[0], _recolored(before, seed + 1), before):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", MjcfRecompiledWarning)
            result = patched(model, before, after, into=scratch)
        recompiled = any(issubclass(w.category, MjcfRecompiledWarning) for w in caught)
        assert (result is scratch) != recompiled
        assert model_differences(result, compiled(after)) == []
    assert model_differences(model, compiled(before)) == []


@settings(PER_CLASS, suppress_health_check=[HealthCheck.too_slow])
@given(model=models(), seed=st.integers(0, 2**32 - 1))
def test_variants_patched_in_turn_into_one_model_are_compiled_variants(
    model: Mujoco, seed: int
) -> None:
    """``into``: what a variant wrote and derived is gone when the next is patched in."""
    _patched_in_turn(model, seed)


@pytest.mark.parametrize("path", compiling_corpus()[::5], ids=corpus_id)
def test_corpus_variants_patched_in_turn_into_one_model_are_compiled_variants(path: Path) -> None:
    """The same on the corpus: every mapped value, then colours alone, then the model itself."""
    _patched_in_turn(load(path, inline_includes=True), 7)


def test_a_model_with_a_replicated_geom_patches_colors_elsewhere() -> None:
    """The copy that numbers the rows labels nothing a ``<replicate>`` copies (found by CI).

    MuJoCo names a replicated ``g1`` ``g10`` and ``g11``: with a dozen geoms, labels clashed.
    """
    geoms = '<geom type="box" size="1 1 1" rgba="1 0 0 1"/>' * 12
    before = loads(
        '<mujoco><worldbody><body name="a"><freejoint/><geom type="box" size="1 1 1"/>'
        '<replicate count="2" offset="0 0 0"><geom type="box" size="1 1 1"/></replicate>'
        '</body><body name="b"><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>'
        f"{geoms}</body></worldbody></mujoco>"
    )
    after = _recolored(before, 0)  # colours: patched on every MuJoCo release
    result, expected, reasons = _patched_and_expected(before, after)
    assert reasons == [] and model_differences(result, expected) == []


def test_a_change_without_an_array_compiles_again_and_says_which() -> None:
    """A geom size has no one-for-one array: a full compile, with a warning naming it."""
    before = loads(
        '<mujoco><worldbody><!-- floor --><geom size="1"/><geom name="g" size="0.1"/>'
        "</worldbody></mujoco>"
    )

    def bigger(element: AnyElement, key: str | None, ancestors: Any) -> AnyElement:
        named = key == "body/geom" and attribute_text(element, "name") == "g"
        return with_attributes(element, {"size": (0.2,)}) if named else element

    after = map_elements(bigger, before)
    where = re.escape("<geom> size at /mujoco/worldbody/geom[@name='g']: ")
    with pytest.warns(MjcfRecompiledWarning, match=where):
        result = patched(compiled(before), before, after)
    assert result.geom_size[1][0] == pytest.approx(0.2)


def test_unchanged_models_and_the_input_model_are_left_alone() -> None:
    """Patching a model against itself copies it; the given compiled model never changes."""
    before = loads('<mujoco><worldbody><geom size="0.1" rgba="1 0 0 1"/></worldbody></mujoco>')
    model = compiled(before)
    same = patched(model, before, before)
    assert same is not model and model_differences(same, model) == []
    after, _ = variant(before, 3)
    patched(model, before, after)
    assert model.geom_rgba.tolist() == [[1.0, 0.0, 0.0, 1.0]]


def test_readme_variant_example_runs_on_a_robot(monkeypatch: pytest.MonkeyPatch) -> None:
    """The README's variant loop, from the installed package's description, on robosuite's Panda.

    It patches every variant into one scratch model (no full compile, no copy), and one more
    into a copy of its own.
    """
    from importlib import metadata

    import robosuite

    readme = metadata.metadata("mjcf-model").get_payload()
    assert isinstance(readme, str)
    section = readme.split("### Variants: domain randomisation", 1)[1]
    code = section.split("```python\n", 1)[1].split("```", 1)[0]
    panda = Path(robosuite.__file__).parent / "models/assets/robots/panda/robot.xml"
    assert 'load("arm.xml")' in code
    namespace: dict[str, Any] = {}
    with warnings.catch_warnings():
        warnings.simplefilter("error", MjcfRecompiledWarning)
        exec(code.replace('"arm.xml"', repr(str(panda))), namespace)
    colours, base = namespace["colours"], namespace["base"]
    assert len(colours) == 100
    assert not np.array_equal(colours[0], colours[1])
    assert not np.array_equal(colours[0], base.geom_rgba)
    assert namespace["physics"] is namespace["scratch"]
    assert namespace["kept"] is not namespace["scratch"]
    assert not np.array_equal(namespace["kept"].geom_rgba, base.geom_rgba)


def test_readme_process_pool_sweep_runs_as_a_script(tmp_path: Path) -> None:
    """The README's process-pool sweep, saved as a script (8 seeds), runs on robosuite's Panda."""
    import subprocess
    import sys
    from importlib import metadata

    import robosuite

    readme = metadata.metadata("mjcf-model").get_payload()
    assert isinstance(readme, str)
    section = readme.split("### Variants: domain randomisation", 1)[1].split("\n### ", 1)[0]
    code = section.split("```python\n")[2].split("```", 1)[0]
    panda = Path(robosuite.__file__).parent / "models/assets/robots/panda/robot.xml"
    script = tmp_path / "sweep.py"
    assert "range(100)" in code and 'load("arm.xml")' in code
    script.write_text(code.replace('"arm.xml"', repr(str(panda))).replace("range(100)", "range(8)"))
    import os

    import mjcf_model
    from mjcf_model import serializers

    # The script imports the same library this test does (installed, or the checkout).
    roots = {str(Path(m.__file__).parents[1]) for m in (mjcf_model, serializers)}
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(sorted(roots))}
    done = subprocess.run(
        [sys.executable, str(script)],
        capture_output=True,
        text=True,
        check=False,
        timeout=600,
        env=env,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.startswith("8 rollouts, second joint from ")
    low, high = (float(v) for v in done.stdout.split("from ")[1].split(" to "))
    assert low < high  # the variants differ


#: Classes as MuJoCo layers them: a main class written in two top-level sections (one
#: element each), a nested class writing part of a row, ``childclass``, an element's own
#: partial value, and actuators reading one shared default from ``<general>`` and ``<motor>``.
_CLASSES = """
<mujoco>
  <default><geom solref="0.02 1" friction="0.8 0.01 0.001"/></default>
  <default>
    <geom rgba="0.5 0.5 0.5 1"/>
    <general ctrlrange="-1 1"/>
    <default class="soft">
      <geom friction="0.4" margin="0.01"/>
      <joint damping="2" armature="0.1"/>
      <motor gear="3"/>
      <default class="softer"><geom solref="0.05"/></default>
    </default>
  </default>
  <worldbody>
    <body name="a" childclass="soft">
      <joint name="ja"/>
      <geom name="ga" size="0.1"/>
      <geom name="gb" size="0.1" class="softer" friction="0.3 0.02"/>
      <body name="b" pos="0 0 1">
        <joint name="jb" class="main" damping="1"/>
        <geom name="gc" size="0.1" class="main"/>
      </body>
    </body>
  </worldbody>
  <actuator>
    <motor name="m" joint="ja" class="soft"/>
    <general name="g" joint="jb"/>
  </actuator>
</mujoco>
"""


def _with_class_values(
    model: Mujoco, values: dict[tuple[str | None, str], dict[str, Any]]
) -> Mujoco:
    """``model`` with the default element ``(class, tag)`` of ``values`` given new values.

    ``None`` names the top-level ``<default>`` sections (each of their elements of the tag).
    """

    def change(element: AnyElement, key: str | None, ancestors: Any) -> AnyElement:
        if not (key or "").startswith("default/") or not ancestors:
            return element
        owner = get_attribute(ancestors[-1], "class")
        new = values.get((owner if isinstance(owner, str) else None, element.tag))
        return with_attributes(element, new) if new else element

    return map_elements(change, model)


@pytest.mark.parametrize(
    "values",
    [
        {(None, "geom"): {"friction": (0.9, 0.02, 0.002), "rgba": (1, 0, 0, 1)}},
        {("soft", "geom"): {"friction": (0.6,), "margin": 0.02}},
        {("softer", "geom"): {"solref": (0.07,)}, (None, "geom"): {"solref": (0.03, 0.9)}},
        {("soft", "joint"): {"damping": 5, "armature": 0.3}},
        {("soft", "motor"): {"gear": (4,)}, (None, "general"): {"ctrlrange": (-2, 2)}},
    ],
    ids=[
        "main-both-sections",
        "nested-partial",
        "partial-over-changed-parent",
        "joint",
        "actuator",
    ],
)
def test_a_changed_class_is_patched_into_the_elements_that_take_it(
    values: dict[tuple[str | None, str], dict[str, Any]],
) -> None:
    """Each class change reaches the elements MuJoCo gives it to, and only those: no compile."""
    before = loads(_CLASSES)
    after = _with_class_values(before, values)
    assert after != before
    result, expected, reasons = _patched_and_expected(before, after)
    assert model_differences(result, expected) == []
    assert model_differences(result, compiled(before)) != []  # the change arrived
    if not OLD:
        assert reasons == []


def test_a_class_change_without_an_array_compiles_again_and_names_it() -> None:
    """A class's geom size reaches geoms through no one-for-one array: compiled, and said."""
    before = loads(_CLASSES)
    after = _with_class_values(before, {("soft", "geom"): {"size": (0.2,)}})
    with pytest.warns(MjcfRecompiledWarning, match=r"<geom> size of default class 'soft'"):
        result = patched(compiled(before), before, after)
    assert model_differences(result, compiled(after)) == []


def test_an_added_class_compiles_again() -> None:
    """A class added changes which class elements read: compiled again."""
    before = loads(_CLASSES)
    after = loads(
        _CLASSES.replace(
            '<default class="softer">', '<default class="new"/><default class="softer">'
        )
    )
    with pytest.warns(MjcfRecompiledWarning, match="a default class"):
        patched(compiled(before), before, after)


_SPRINGS = """
<mujoco>
  <default><default class="sprung"><joint springdamper="0.2 0.7"/></default></default>
  <worldbody>
    <body name="hinged"><joint name="h" springdamper="0.1 0.5" damping="9"/>
      <geom size="0.1 0.3" type="capsule" mass="2"/>
      <body name="slid" pos="0 0 1"><joint name="s" type="slide" class="sprung" armature="0.2"/>
        <geom size="0.1" mass="3"/>
        <body name="balled" pos="0 0 1"><joint name="b" type="ball" class="sprung"/>
          <inertial pos="0 0 0" mass="1.5" diaginertia="0.1 0.2 0.3"/>
        </body>
      </body>
    </body>
    <body name="free" pos="2 0 0"><joint name="f" type="free" class="sprung"/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.1 0.1 0.1"/></body>
    <body name="unsprung" pos="4 0 0"><joint name="u" damping="0.5"/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.1 0.1 0.1"/></body>
  </worldbody>
</mujoco>
"""


def test_springdamper_joints_follow_changed_masses_inertias_and_armatures() -> None:
    """``springdamper`` sets stiffness and damping from the joints' inertia: patched as compiled.

    Hinge, slide, ball and free joints, set on the joint or by its class; the written damping
    of a sprung joint is overridden, as MuJoCo overrides it.
    """
    before = loads(_SPRINGS)
    after, count = variant(before, 11)
    assert count >= 5
    result, expected, reasons = _patched_and_expected(before, after)
    assert model_differences(result, expected) == []
    assert not np.array_equal(result.jnt_stiffness, compiled(before).jnt_stiffness)
    if not OLD:
        assert reasons == []
