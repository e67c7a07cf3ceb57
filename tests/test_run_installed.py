"""tests/run_installed.py's check that the tests an environment must run did run there."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from tests.run_installed import ENVIRONMENTS, MUST_RUN, skipped_must_run

MODULE = "tests.mjcf_model.test_compat"


def _report(*cases: str) -> ET.Element:
    """A junit report as pytest writes it, with the given ``<testcase>`` elements."""
    return ET.fromstring(
        f'<testsuites><testsuite name="pytest" tests="{len(cases)}">{"".join(cases)}'
        "</testsuite></testsuites>"
    )


def test_a_skipped_robosuite_environment_test_fails_the_oldest_run() -> None:
    """A must-run test that was skipped is named with its module, test and skip reason."""
    report = _report(
        f'<testcase classname="{MODULE}" name="test_lift"><skipped type="pytest.skip" '
        'message="robosuite 1.5.2 does not run on MuJoCo 4.0.0"/></testcase>',
        f'<testcase classname="{MODULE}" name="test_stack"/>',
    )
    problems = skipped_must_run(report, (MODULE,))
    assert problems == [
        f"{MODULE}::test_lift was skipped: robosuite 1.5.2 does not run on MuJoCo 4.0.0"
    ]


def test_a_must_run_module_with_no_test_in_the_report_fails() -> None:
    """A module not collected in a whole-suite run counts as not run; under -k it may be left."""
    report = _report('<testcase classname="tests.test_corpus" name="test_x"/>')
    assert skipped_must_run(report, (MODULE,)) == [f"{MODULE} ran no test"]
    assert skipped_must_run(report, (MODULE,), whole_suite=False) == []


def test_skips_elsewhere_and_runs_of_every_test_pass() -> None:
    """Skips in other modules and a must-run module whose tests all ran give no problem."""
    report = _report(
        '<testcase classname="tests.test_corpus" name="test_x"><skipped message="no"/></testcase>',
        f'<testcase classname="{MODULE}.TestTasks" name="test_lift"/>',
    )
    assert skipped_must_run(report, (MODULE,)) == []


def test_must_run_names_real_environments_and_modules() -> None:
    """The oldest environment must run robosuite's environments; each name is real."""
    assert MODULE in MUST_RUN["oldest"]
    assert set(MUST_RUN) <= {path.stem for path in ENVIRONMENTS.glob("*.txt")}
    for modules in MUST_RUN.values():
        for module in modules:
            assert (ENVIRONMENTS.parents[1] / (module.replace(".", "/") + ".py")).is_file()
