"""The benchmark runner keeps working (one tiny run; timings are never asserted)."""

from __future__ import annotations

import json
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import mujoco
import numpy as np
import pytest

from benchmarks import cases_resets
from benchmarks.cases_resets import RESET_CASE, ROBOSUITE_RESETS
from benchmarks.cases_variants import (
    VARIANT_MODELS,
    length_coordinates,
    our_physical_variant,
    scaled_differences,
    spec_physical_variant,
    spec_scaled_variant,
    spec_with_skins_inline,
)
from benchmarks.environments import ROBOSUITE_RUNS, our_objects, our_twin, robosuite_classes
from benchmarks.etree_path import etree_inlined, robosuite_scaled
from benchmarks.harness import OURS, Case, Contender, Row, run_case
from benchmarks.inputs import package_dir, synthetic_xml
from benchmarks.targets import targets
from mjcf_model import compiled, scaled
from mjcf_model.bridge.compare import compile_text_beside, model_differences, path_fields
from mjcf_model.serializers import load, loads
from tests.conftest import compiling_corpus, corpus_id

#: Corpus files with ``<include>`` elements (robosuite's ElementTree path must inline them).
_INCLUDING = [p for p in compiling_corpus() if any(True for _ in ET.parse(p).iter("include"))]

#: The compiled arrays of lengths both uniform-scale rows change.
_LENGTHS = ("body_pos", "body_ipos", "geom_pos", "geom_size", "site_pos", "jnt_pos", "jnt_range")

#: Issue 12's rows: (case, peer contender) pairs measured beside mjcf-model.
_ISSUE_12_ROWS = [
    *(
        (f"synthetic {shape}: uniform scale", "robosuite scale_mjcf_model (on a deepcopy)")
        for shape in ("deep", "wide")
    ),
    *(
        (f"construct {name} + get_obj() + asset (compat layer)", "robosuite")
        for name in ("CanObject", "BoxObject", "CompositeObject")
    ),
    *(
        ("import time", peer)
        for peer in (
            "robosuite (import robosuite.utils.mjcf_utils)",
            "dm_control (import dm_control.mjcf)",
            "xml.etree.ElementTree (floor)",
            "python -c pass (interpreter start-up)",
        )
    ),
]


@pytest.fixture(scope="module")
def tiny_results(tmp_path_factory: pytest.TempPathFactory) -> str:
    """The RESULTS.md text of one ``python -m benchmarks --tiny`` run."""
    output = tmp_path_factory.mktemp("benchmarks") / "RESULTS.md"
    done = subprocess.run(
        [sys.executable, "-m", "benchmarks", "--tiny", "--output", str(output)],
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    return output.read_text(encoding="utf-8")


def _row(results: str, case: str, contender: str) -> list[str] | None:
    """The cells of the table row of ``contender`` in ``case`` (``None`` if absent)."""
    for line in results.split("## All cases")[1].splitlines():
        cells = [cell.strip() for cell in line.strip("|").split(" | ")]
        if len(cells) == 7 and cells[0] == case and cells[2] == contender:
            return cells
    return None


def test_tiny_run_writes_every_case_with_every_contender(tiny_results: str) -> None:
    """``python -m benchmarks --tiny`` runs every case and writes the results table."""
    text = tiny_results
    assert "## Targets" in text and "Machine:" in text and "--tiny" in text
    for case in (
        "corpus: load + prefix + dump",
        "corpus: load + dump",
        "corpus: prefix alone",
        "corpus: uniform scale alone",
        "synthetic deep: load + dump",
        "synthetic wide: hash",
        "scene: load",
        "scene: find a geom by name, asked again",
        "corpus: load",
        "construct CanObject",
        "compose 5 cans + write XML",
        "physical variants: suite/humanoid.xml",
        "variant sweep: panda/robot.xml",
        "batched: panda/robot.xml",
        "compile: ",
        "shared assets: 2 Pandas, compile",
    ):
        assert f"| {case}" in text, case
    assert "| batched: panda/robot.xml: variants per second (4 variants) |" in text
    for contender in ("robosuite", "dm_control.mjcf", "MjSpec", "lxml", "ElementTree"):
        assert contender in text, contender
    assert "failed:" not in text


def test_only_measures_the_chosen_cases_and_peers(tmp_path: Path) -> None:
    """``--only GROUP:WORD`` and ``--peers`` measure those cases and peers, and ours always."""
    output = tmp_path / "only.md"
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "benchmarks",
            "--tiny",
            "--only",
            "synthetic:dump",
            "--peers",
            "ElementTree",
            "--output",
            str(output),
        ],
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    rows = [
        line.strip("|").split(" | ")[:3]
        for line in output.read_text(encoding="utf-8").split("## All cases")[1].splitlines()
        if line.startswith("| synthetic")
    ]
    cases = {case.strip() for case, _, _ in rows}
    assert cases == {
        f"synthetic {shape}: {case}"
        for shape in ("deep", "wide")
        for case in ("load + dump", "dump")
    }
    assert {contender.strip() for _, _, contender in rows} == {
        OURS,
        "ElementTree fromstring + tostring",
    }


def test_an_unknown_group_is_refused_with_the_groups_that_exist() -> None:
    """``--only`` with a group that does not exist names the groups that do."""
    done = subprocess.run(
        [sys.executable, "-m", "benchmarks", "--only", "corpse"],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert done.returncode == 2
    assert "no benchmark group 'corpse'; the groups: corpus, synthetic" in done.stderr


def test_every_target_finds_its_rows(tiny_results: str) -> None:
    """Each target line of the tiny run is measured: its case and contender names exist.

    A line without a target (``batched``'s variants per second) says ``measured``.

    robosuite's hard resets are measured only where robosuite's environments run (MuJoCo
    3.9, this suite's ``oldest`` environment); elsewhere their line says so.
    """
    table = tiny_results.split("## Targets")[1].split("## Sizes")[0]
    lines = [line for line in table.splitlines() if line.startswith("| ") and "---" not in line]
    resets = [line for line in lines if line.startswith("| robosuite hard reset")]
    assert len(resets) == 1
    if not ROBOSUITE_RUNS:
        assert resets[0].endswith("| not measured | |")
        lines.remove(resets[0])
        table = "\n".join(lines)
    assert len(lines) > 15 and "not measured" not in table, table
    assert all(line.endswith(("| met |", "| MISSED |", "| measured |")) for line in lines[1:])


def test_the_reset_rows_run_where_robosuite_runs(tiny_results: str) -> None:
    """Both ways of resetting each tiny environment are timed, or say what they need."""
    for task in ("Lift", "TwoArmPegInHole"):
        for contender in (OURS, ROBOSUITE_RESETS):
            cells = _row(tiny_results, RESET_CASE.format(task=task), contender)
            assert cells is not None, (task, contender)
            if ROBOSUITE_RUNS:
                assert cells[3].endswith(" ms"), cells
            else:
                assert cells[3] == "-" and "MJCF_MODEL_MUJOCO39_PYTHON" in cells[6], cells


def test_our_objects_binds_our_twins_in_the_block_only() -> None:
    """Every robosuite object class a task's module uses is ours inside the block, theirs after."""
    import robosuite.models.arenas.wipe_arena as wipe  # the Wipe task's markers are made there

    before = {name: getattr(wipe, name) for name in robosuite_classes(wipe)}
    assert set(before) == {"CustomMaterial", "CylinderObject"}
    with our_objects("Wipe") as replaced:
        assert replaced == ["CustomMaterial", "CylinderObject"]
        for name in before:
            assert getattr(wipe, name) is our_twin(name)
            assert getattr(wipe, name).__module__.startswith("mjcf_model.compat")
    assert {name: getattr(wipe, name) for name in before} == before


def test_reset_times_measured_by_another_interpreter_are_read_back(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """On a newer MuJoCo the reset cases take the times another interpreter printed."""
    times = {
        "Lift": {OURS: [0.2, 0.3, 0.1], ROBOSUITE_RESETS: [0.4, 0.2, 0.6]},
        "TwoArmPegInHole": {OURS: [1.0], ROBOSUITE_RESETS: [2.0]},
    }
    python = tmp_path / "python"
    python.write_text(f"#!/bin/sh\necho 'robosuite logs'\necho '{json.dumps(times)}'\n")
    python.chmod(0o755)
    monkeypatch.setenv("MJCF_MODEL_MUJOCO39_PYTHON", str(python))
    cases = cases_resets._measured_elsewhere(["Lift", "TwoArmPegInHole"], repeat=3)
    rows = [row for case in cases for row in run_case(case, repeat=3)]
    medians = {(row.case, row.contender): (row.time, row.ratio) for row in rows}
    assert medians == {
        (RESET_CASE.format(task="Lift"), OURS): (0.2, 1.0),
        (RESET_CASE.format(task="Lift"), ROBOSUITE_RESETS): (0.4, 2.0),
        (RESET_CASE.format(task="TwoArmPegInHole"), OURS): (1.0, 1.0),
        (RESET_CASE.format(task="TwoArmPegInHole"), ROBOSUITE_RESETS): (2.0, 2.0),
    }
    assert "robosuite hard reset: mjcf-model time / robosuite time, geometric mean of 2 " in (
        targets(rows)
    )


def test_every_size_is_measured_against_its_target(tiny_results: str) -> None:
    """The size table: the pickled subtrees, the prefixed models' memory, the big number list."""
    table = tiny_results.split("## Sizes")[1].split("## All cases")[0]
    lines = [line for line in table.splitlines() if line.startswith("| ") and "---" not in line]
    measures = [line.split(" | ")[0] for line in lines[1:]]
    assert [m.split(":")[0] for m in measures] == [
        "| pickled Panda geom",
        "| pickled Panda body",
        "| pickled Panda model",
        "| pickled corpus elements within 2x their text + 1,024 bytes",
        "| 20 loaded-then-prefixed corpus models",
        "| load a 1 MB number list",
        "| load a 1 MB number list",
    ], table
    ends = ("| met |", "| MISSED |", "| measured |")
    assert all(line.endswith(ends) for line in lines[1:]), table


@pytest.mark.parametrize(("case", "peer"), _ISSUE_12_ROWS)
def test_issue_12_rows_stand_beside_their_peer(tiny_results: str, case: str, peer: str) -> None:
    """Each row issue 12 adds has a measured mjcf-model side and peer side, with a ratio."""
    for contender in (OURS, peer):
        cells = _row(tiny_results, case, contender)
        assert cells is not None, (case, contender)
        median, ratio, note = cells[3], cells[4], cells[6]
        assert median.endswith(("ms", " s")) and ratio.endswith("x"), cells
        assert case != "import time" or "start-up" in note, cells


@pytest.mark.parametrize("path", _INCLUDING, ids=corpus_id)
def test_robosuite_path_reads_the_included_files_too(path: Path) -> None:
    """The ElementTree path inlines includes as mjcf-model does: MuJoCo compiles the same model."""
    text = ET.tostring(etree_inlined(path), encoding="unicode")
    assert "<include" not in text
    inlined = compile_text_beside(text, path)
    original = mujoco.MjModel.from_xml_path(str(path))
    assert model_differences(inlined, original, ignore=path_fields()) == []


@pytest.mark.parametrize("shape", ["deep", "wide"])
def test_both_scale_rows_scale_the_same_lengths(shape: str) -> None:
    """The two scale rows (robosuite, mjcf-model) compile to the same doubled lengths."""
    text = synthetic_xml(120, shape)
    theirs = mujoco.MjModel.from_xml_string(
        ET.tostring(robosuite_scaled(ET.fromstring(text)), encoding="unicode")
    )
    ours, unscaled = compiled(scaled(loads(text), 2)), compiled(loads(text))
    differences = model_differences(theirs, ours)
    assert set(_LENGTHS).isdisjoint(differences), differences
    assert {"body_pos", "geom_size", "site_pos"} <= set(model_differences(ours, unscaled))


def test_targets_say_met_missed_or_not_measured() -> None:
    """A target is met inside its bound, MISSED outside it, and not measured without rows."""
    case = "construct CanObject + get_obj() + asset (compat layer)"
    faster = [Row(case, OURS, "", 0.1), Row(case, "robosuite", "", 0.2)]
    slower = [Row(case, OURS, "", 0.3), Row(case, "robosuite", "", 0.2)]
    label = "| construct CanObject + get_obj() + asset: mjcf-model time / robosuite time |"
    assert f"{label} 0.50 (target <= 1) | met |" in targets(faster)
    assert f"{label} 1.50 (target <= 1) | MISSED |" in targets(slower)
    assert f"{label} not measured | |" in targets([])


def test_ratios_are_relative_to_this_library() -> None:
    """Each ratio is the contender's median over mjcf-model's; a missing contender has none."""

    def work(n: int) -> None:
        sum(range(n))

    case = Case(
        "demo",
        [
            Contender(OURS, lambda: work(200_000)),
            Contender("slower", lambda: work(400_000)),
            Contender("absent", None, "not installed"),
        ],
    )
    rows = {row.contender: row for row in run_case(case, repeat=5)}
    assert rows[OURS].ratio == 1.0
    slower, ours = rows["slower"].time, rows[OURS].time
    assert slower is not None and ours is not None
    assert rows["slower"].ratio == slower / ours
    assert len(rows["slower"].times) == 5
    assert rows["absent"].time is None and rows["absent"].note == "not installed"


def test_an_interleaved_case_takes_turns_and_can_show_the_least_time() -> None:
    """Contenders run in turns, the order reversed every round, after an untimed round.

    The case's ``least_repeat`` raises the runner's repeat, and ``least`` shows the minimum.
    """
    calls: list[str] = []

    def contender(name: str) -> Contender:
        return Contender(name, lambda: calls.append(name))

    case = Case(
        "turns",
        [contender(OURS), contender("peer")],
        interleaved=True,
        least_repeat=4,
        least=True,
    )
    rows = {row.contender: row for row in run_case(case, repeat=2)}
    assert calls == [OURS, "peer", OURS, "peer", "peer", OURS, OURS, "peer", "peer", OURS]
    for row in rows.values():
        assert len(row.times) == 4 and row.time == min(row.times)


def test_an_interleaved_case_reports_a_failing_contender() -> None:
    """A contender that raises while the case takes turns is timed alone and reported."""

    def fail() -> None:
        raise RuntimeError("broken peer")

    case = Case("turns", [Contender(OURS, lambda: None), Contender("peer", fail)], interleaved=True)
    rows = {row.contender: row for row in run_case(case, repeat=3)}
    assert len(rows[OURS].times) == 3 and rows[OURS].time is not None
    assert rows["peer"].time is None and "broken peer" in rows["peer"].note


def _variant_model(model: tuple[str, str]) -> Path:
    package, relative = model
    folder = package_dir(package)
    assert folder is not None
    return folder / relative


@pytest.mark.parametrize("model", VARIANT_MODELS, ids=lambda m: m[1].rsplit("/", 2)[-2])
def test_both_physical_variant_rows_make_the_same_variants(model: tuple[str, str]) -> None:
    """The physical variants of both rows compile to the same model, changed where drawn."""
    path = _variant_model(model)
    spec, loaded = mujoco.MjSpec.from_file(str(path)), load(path, inline_includes=True)
    original = spec.compile()
    for seed in (0, 1):
        theirs = spec_physical_variant(spec, np.random.default_rng(seed)).compile()
        mine = compiled(our_physical_variant(loaded, np.random.default_rng(seed)))
        assert model_differences(mine, theirs, ignore=path_fields()) == []
    changed = set(model_differences(theirs, original))
    assert {"geom_rgba", "geom_friction"} <= changed
    assert ("body_mass" in changed) == any(body.explicitinertial for body in spec.bodies)


@pytest.mark.parametrize("model", VARIANT_MODELS, ids=lambda m: m[1].rsplit("/", 2)[-2])
def test_both_scaled_variant_rows_make_the_same_variants(model: tuple[str, str]) -> None:
    """The spec side scales every length ``scaled`` does: both compile to the same model."""
    path = _variant_model(model)
    spec = spec_with_skins_inline(mujoco.MjSpec.from_file(str(path)))
    original = spec.copy().compile()  # the spec itself stays uncompiled (see the function)
    loaded = load(path, inline_includes=True)
    for factor in (0.8, 1.17):
        theirs = spec_scaled_variant(spec, factor, length_coordinates(original)).compile()
        assert scaled_differences(compiled(scaled(loaded, factor, mass="volume")), theirs) == []
    changed = set(model_differences(theirs, original, ignore=path_fields()))
    assert {"body_pos", "geom_size", "body_subtreemass"} <= changed
