"""Run the test suite against the built wheel, installed as users install it.

The README's test command ends with this script. It

1. builds the wheel from this checkout (``pip wheel``, an isolated build);
2. for each environment in ``tests/environments/`` (``newest``: MuJoCo 4.0.0;
   ``oldest``: MuJoCo 3.9.0, where robosuite 1.5.2's own environments run),
   creates a fresh virtual environment and installs the wheel with its ``test``
   extra under that file's pip constraints (all environments at once: the later
   ones install while the first suite runs);
3. copies ``tests/`` (with its sub-folders: ``support/`` and the test folders
   ``mjcf_model/`` and ``serializers/`` that mirror the packages) and ``benchmarks/``
   (which the tests run) into a folder of their own, so that the source folders are
   not importable from where pytest runs, and checks that ``mjcf_model`` (with its
   ``mjcf_model.serializers``) imports from the environment's site-packages;
4. runs pytest there: the tests, and the doctests of the installed modules.

It ends with one line ``total: N passed, N failed`` and exits non-zero when
anything failed, or when a test that must run in an environment (:data:`MUST_RUN`)
was skipped there or not collected: each such module counts as one failure. Usage::

    python tests/run_installed.py [ENVIRONMENT ...] [-- PYTEST-ARGUMENTS]

Without pytest arguments, ``-n 2 --dist worksteal`` is used (a worker that runs out of
tests takes some of the other's, so the last long tests do not leave a core idle). The
folders live in ``build/installed/`` and are made anew on every run.
"""

from __future__ import annotations

import concurrent.futures
import os
import shutil
import subprocess
import sys
import venv
import xml.etree.ElementTree as ET
from pathlib import Path

#: The checkout this script belongs to.
SOURCE_TREE = Path(__file__).resolve().parents[1]
#: The constraint files, one per environment, named ``<environment>.txt``.
ENVIRONMENTS = SOURCE_TREE / "tests" / "environments"
#: Where wheels, virtual environments and suite copies are made.
WORK = SOURCE_TREE / "build" / "installed"
#: The folders copied beside each other to form the suite (tests import both).
SUITE_FOLDERS = ("tests", "benchmarks")
#: The installed packages whose doctests run too.
PACKAGES = ("mjcf_model",)
#: Hypothesis profiles by environment (``tests/conftest.py`` defines them); the others
#: keep the caller's (``ci`` under ``CI=true``). The oldest runs every property at the
#: ``compat`` profile's 25 examples: it checks that the library works on MuJoCo 3.9; the
#: newest searches with the ``ci`` profile's 100.
HYPOTHESIS_PROFILES = {"oldest": "compat"}
#: Which share of the corpus the corpus-wide tests run on, by environment (the others run
#: on every file): the oldest checks MuJoCo 3.9 on every third file (``tests/conftest.py``).
CORPUS_SHARES = {"oldest": 3}
#: Test modules whose every test must run (none skipped) in an environment: robosuite's
#: own environments run only up to MuJoCo 3.9, so only ``oldest`` can run them. Named as
#: pytest's junit report names them: the dotted path of the file under ``tests/``.
MUST_RUN: dict[str, tuple[str, ...]] = {"oldest": ("tests.mjcf_model.test_compat",)}


def run(command: list[str], **kwargs: object) -> None:
    """Run ``command``, echoing it first; a failure ends the script."""
    print("+", " ".join(command), flush=True)
    subprocess.run(command, check=True, **kwargs)  # type: ignore[call-overload]


def build_wheel() -> Path:
    """Build the wheel of this checkout into ``WORK/dist`` and return its path."""
    dist = WORK / "dist"
    shutil.rmtree(dist, ignore_errors=True)
    # setuptools builds in build/lib and keeps what an earlier build left there: a
    # module since moved or deleted would still be packed into the wheel
    shutil.rmtree(SOURCE_TREE / "build" / "lib", ignore_errors=True)
    run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "-w", str(dist), "."],
        cwd=SOURCE_TREE,
    )
    (wheel,) = dist.glob("*.whl")
    return wheel


def environment_python(name: str, wheel: Path) -> Path:
    """A fresh virtual environment with the wheel and its test extra installed."""
    home = WORK / name / "venv"
    shutil.rmtree(home, ignore_errors=True)
    venv.create(home, with_pip=True)
    python = home / "bin" / "python"
    constraints = ENVIRONMENTS / f"{name}.txt"
    run(
        [
            str(python),
            "-m",
            "pip",
            "install",
            "--quiet",
            "--disable-pip-version-check",
            f"{wheel}[test]",
            "-c",
            str(constraints),
        ]
    )
    return python


def suite_folder(name: str) -> Path:
    """A copy of the tests and benchmarks, in a folder holding no package source.

    The suite folder is what pytest puts on ``sys.path``: ``tests/mjcf_model`` and
    ``tests/serializers`` are ``tests.mjcf_model`` and ``tests.serializers`` there, and
    cannot shadow the installed packages.
    """
    suite = WORK / name / "suite"
    shutil.rmtree(suite, ignore_errors=True)
    suite.mkdir(parents=True)
    for folder in SUITE_FOLDERS:
        shutil.copytree(
            SOURCE_TREE / folder, suite / folder, ignore=shutil.ignore_patterns("__pycache__")
        )
    shutil.copy(SOURCE_TREE / "pyproject.toml", suite)  # pytest's settings
    shutil.copy(SOURCE_TREE / "ARCHITECTURE.md", suite)  # the layer table the import contract reads
    return suite


#: Run by the environment's interpreter: where each package imports from.
_WHERE_FROM = """
import importlib, pathlib, sys, sysconfig
site = pathlib.Path(sysconfig.get_paths()["purelib"]).resolve()
outside = []
for name in sys.argv[1:]:
    where = pathlib.Path(importlib.import_module(name).__file__).resolve()
    print(name, "imports from", where)
    outside += [] if where.is_relative_to(site) else [f"{where} is not in {site}"]
sys.exit("; ".join(outside) or None)
"""


def check_installed_imports(python: Path, suite: Path, environment: dict[str, str]) -> None:
    """Fail unless the packages import from the environment, not from the checkout."""
    print(f"+ check that {', '.join(PACKAGES)} import from site-packages", flush=True)
    subprocess.run(
        [str(python), "-c", _WHERE_FROM, *PACKAGES], cwd=suite, env=environment, check=True
    )


def run_suite(
    name: str,
    python: Path,
    wheel: Path,
    pytest_arguments: list[str],
    *,
    whole_suite: bool = True,
) -> tuple[int, int]:
    """Copy, check and run the suite in one installed environment: (passed, failed)."""
    print(f"\n=== environment {name!r}: {ENVIRONMENTS / f'{name}.txt'}", flush=True)
    suite = suite_folder(name)
    environment = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    if name in HYPOTHESIS_PROFILES:
        environment["HYPOTHESIS_PROFILE"] = HYPOTHESIS_PROFILES[name]
    if name in CORPUS_SHARES:
        environment["MJCF_MODEL_CORPUS_SHARE"] = str(CORPUS_SHARES[name])
    environment.update(
        MJCF_MODEL_SOURCE_TREE=str(SOURCE_TREE),
        MJCF_MODEL_WHEEL=str(wheel),
        MJCF_MODEL_ENVIRONMENT=name,
    )
    check_installed_imports(python, suite, environment)
    report = suite / "junit.xml"
    command = [
        str(python),
        "-m",
        "pytest",
        "-p",
        "no:cacheprovider",
        f"--junitxml={report}",
        *pytest_arguments,
        "tests",
        "--pyargs",
        *PACKAGES,
    ]
    print("+", " ".join(command), flush=True)
    status = subprocess.run(command, cwd=suite, env=environment, check=False).returncode
    totals = ET.parse(report).getroot().find("testsuite") if report.exists() else None
    if totals is None:
        print(f"pytest exited {status} and wrote no report", flush=True)
        return 0, 1
    tests, failures, errors, skipped = (
        int(totals.get(key, "0")) for key in ("tests", "failures", "errors", "skipped")
    )
    failed = failures + errors
    unrun = skipped_must_run(
        ET.parse(report).getroot(), MUST_RUN.get(name, ()), whole_suite=whole_suite
    )
    for problem in unrun:
        print(f"must run in {name!r}: {problem}", flush=True)
    failed += len({problem.split("::")[0].split(" ")[0] for problem in unrun})
    if status != 0 and failed == 0:
        print(f"pytest exited {status} with no failed test: counted as one failure", flush=True)
        failed = 1
    return tests - failures - errors - skipped, failed


def skipped_must_run(
    report: ET.Element, modules: tuple[str, ...], *, whole_suite: bool = True
) -> list[str]:
    """What keeps every test of ``modules`` from having run, read from pytest's junit report.

    A test of such a module that was skipped is named with its reason; when the whole
    suite ran (no ``-k`` or other selection of the caller's), a module with no test in
    the report at all (not collected) is named too.
    """
    problems, seen = [], set()
    for case in report.iter("testcase"):
        module = case.get("classname", "")
        owner = next((m for m in modules if module == m or module.startswith(m + ".")), None)
        if owner is None:
            continue
        seen.add(owner)
        skipped = case.find("skipped")
        if skipped is not None:
            reason = skipped.get("message", "")
            problems.append(f"{module}::{case.get('name')} was skipped: {reason}")
    if whole_suite:
        problems += [f"{module} ran no test" for module in modules if module not in seen]
    return problems


def main(arguments: list[str]) -> int:
    """Build, install and test; return the exit status."""
    split = arguments.index("--") if "--" in arguments else len(arguments)
    names, pytest_arguments = arguments[:split], arguments[split + 1 :]
    available = sorted(path.stem for path in ENVIRONMENTS.glob("*.txt"))
    unknown = sorted(set(names) - set(available))
    if unknown:
        print(f"unknown environments {unknown}; there are {available}", file=sys.stderr)
        return 2
    WORK.mkdir(parents=True, exist_ok=True)
    wheel = build_wheel()
    # every environment installs at once, the later ones while the first suite runs
    with concurrent.futures.ThreadPoolExecutor() as pool:
        installing = {
            name: pool.submit(environment_python, name, wheel) for name in names or available
        }
        results = {
            name: run_suite(
                name,
                future.result(),
                wheel,
                pytest_arguments or ["-n", "2", "--dist", "worksteal"],
                whole_suite=not pytest_arguments,
            )
            for name, future in installing.items()
        }
    print()
    for name, (passed, failed) in results.items():
        print(f"environment {name}: {passed} passed, {failed} failed")
    passed = sum(p for p, _ in results.values())
    failed = sum(f for _, f in results.values())
    print(f"total: {passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
