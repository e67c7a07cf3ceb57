"""What users install: the wheel's contents and metadata, the installed command.

``tests/run_installed.py`` hands these tests the wheel it installed
(``MJCF_MODEL_WHEEL``) and the checkout it was built from
(``MJCF_MODEL_SOURCE_TREE``); run from a checkout, they build a wheel themselves.
"""

from __future__ import annotations

import email
import functools
import importlib.metadata
import json
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import tomllib
import zipfile
from email.message import Message
from pathlib import Path

import mujoco
import pytest

import mjcf_model
from tests.conftest import compiling_corpus, corpus_files

#: The folders of the checkout that hold the package, and where each goes in the wheel
#: (``serializers/`` installs as ``mjcf_model.serializers``).
PACKAGE_FOLDERS = {"mjcf_model": "mjcf_model", "serializers": "mjcf_model/serializers"}


@functools.cache
def source_tree() -> Path:
    """The checkout the installed package was built from."""
    given = os.environ.get("MJCF_MODEL_SOURCE_TREE")
    tree = Path(given) if given else Path(__file__).resolve().parents[1]
    assert (tree / "pyproject.toml").is_file(), f"no checkout at {tree}"
    return tree


@functools.cache
def wheel() -> Path:
    """The wheel under test: the one installed, or one built from the checkout now."""
    given = os.environ.get("MJCF_MODEL_WHEEL")
    if given:
        return Path(given)
    dist = Path(tempfile.mkdtemp(prefix="mjcf-model-wheel-"))
    shutil.rmtree(source_tree() / "build" / "lib", ignore_errors=True)  # stale modules
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "-w", str(dist), "."],
        cwd=source_tree(),
        check=True,
    )
    (built,) = dist.glob("*.whl")
    return built


def _wheel_names() -> set[str]:
    with zipfile.ZipFile(wheel()) as archive:
        return set(archive.namelist())


def _metadata() -> Message:
    with zipfile.ZipFile(wheel()) as archive:
        (name,) = (n for n in archive.namelist() if n.endswith(".dist-info/METADATA"))
        return email.message_from_bytes(archive.read(name))


def _pinned(environment: str, package: str) -> str:
    text = (source_tree() / "tests" / "environments" / f"{environment}.txt").read_text()
    (version,) = re.findall(rf"^{package}==(\S+)$", text, flags=re.MULTILINE)
    return version


def test_wheel_holds_every_package_file_and_nothing_else() -> None:
    """Every module and data file under the package folders is in the wheel, and no more."""
    tree = source_tree()
    sources = {
        f"{installed}/{path.relative_to(tree / folder).as_posix()}"
        for folder, installed in PACKAGE_FOLDERS.items()
        for path in (tree / folder).rglob("*")  # links are not followed: serializers/ once
        if path.is_file() and "__pycache__" not in path.parts
    }
    packaged = {name for name in _wheel_names() if ".dist-info/" not in name}
    assert {"mjcf_model/nodes/body.py", "mjcf_model/compat/objects/__init__.py"} <= sources
    assert {
        "mjcf_model/py.typed",
        "mjcf_model/serializers/py.typed",
        "mjcf_model/examples/arm.xml",
    } <= sources
    assert "mjcf_model/examples/workcell/meshes/wedge.obj" in packaged  # the examples' mesh
    assert sorted(sources - packaged) == []
    assert sorted(packaged - sources) == []


def test_wheel_metadata() -> None:
    """SPDX licence with its file, the supported Pythons and MuJoCos, a Markdown description."""
    metadata = _metadata()
    assert metadata["License-Expression"] == "Apache-2.0"
    assert any(name.endswith(".dist-info/licenses/LICENSE") for name in _wheel_names())
    assert metadata["Requires-Python"] == ">=3.11"
    assert metadata["Description-Content-Type"] == "text/markdown"
    assert "Typing :: Typed" in metadata.get_all("Classifier", [])
    requirements = metadata.get_all("Requires-Dist", [])
    # The declared floor is the release the oldest test environment runs.
    oldest = ".".join(_pinned("oldest", "mujoco").split(".")[:2])
    assert f"mujoco>={oldest}" in requirements
    assert not any(r.startswith("mujoco==") and "extra" not in r for r in requirements)
    assert "# mjcf-model" in metadata.get_payload()  # the README is the description


def test_the_robosuite_extra_pins_what_the_suite_runs_robosuite_on() -> None:
    """``[robosuite]`` pins robosuite 1.5.2 and the oldest test environment's MuJoCo.

    That environment is where robosuite's own environments run (the compatibility tests
    prove it there).
    """
    requirements = _metadata().get_all("Requires-Dist", [])
    extra = sorted(
        r.split(";")[0].strip()
        for r in requirements
        if "extra == 'robosuite'" in r.replace('"', "'")
    )
    assert extra == [f"mujoco=={_pinned('oldest', 'mujoco')}", "robosuite==1.5.2"]


def test_the_suite_runs_on_the_package_it_says() -> None:
    """An installed wheel is imported from site-packages, an editable one from the checkout."""
    site = sysconfig.get_paths()["purelib"]  # not the folder pytest runs in (a build's egg-info)
    (distribution,) = importlib.metadata.distributions(name="mjcf-model", path=[site])
    direct = distribution.read_text("direct_url.json")
    editable = bool(direct) and json.loads(direct).get("dir_info", {}).get("editable", False)
    where = Path(mjcf_model.__file__).resolve()
    assert where.is_relative_to(source_tree() / "mjcf_model") == editable
    assert where.is_relative_to(Path(site).resolve()) != editable
    if not editable:
        installed = {str(path) for path in distribution.files or ()}
        assert {n for n in _wheel_names() if not n.endswith("/RECORD")} <= installed


def test_installed_command_checks_the_example() -> None:
    """The ``mjcf-model`` console script is installed beside the interpreter and works."""
    command = Path(sys.executable).parent / "mjcf-model"
    done = subprocess.run(
        [str(command), "check", "--example"], capture_output=True, text=True, check=False
    )
    assert done.returncode == 0, done.stderr
    assert "1 file: 1 identical" in done.stdout


def test_installed_command_checks_robosuites_files() -> None:
    """``mjcf-model check`` over robosuite's XML files: every file MuJoCo compiles is identical.

    The files MuJoCo rejects itself (robosuite ships a few broken ones, and two ROS
    ``package.xml``) are reported as such, and fail the run: exit status 1.
    """
    robosuite_files = [path for path in corpus_files() if "robosuite" in path.parts]
    command = Path(sys.executable).parent / "mjcf-model"
    done = subprocess.run(
        [str(command), "check", *map(str, robosuite_files)],
        capture_output=True,
        text=True,
        check=False,
    )
    compiling = sum("robosuite" in path.parts for path in compiling_corpus())
    assert compiling > 50
    rejected = len(robosuite_files) - compiling  # by MuJoCo itself: fragments, non-MJCF
    assert done.returncode == (1 if rejected else 0), done.stdout + done.stderr
    assert done.stdout.count("not compiled  ") == rejected
    summary = f"{len(robosuite_files)} files: {compiling} identical"
    summary += f", {rejected} not-compiled\n" if rejected else "\n"
    assert summary in done.stdout, done.stdout[-2000:]


def _release(version: str) -> tuple[int, ...]:
    return tuple(int(part) for part in version.split(".")[:3])


def test_mujoco_is_a_tested_release() -> None:
    """The run uses its environment's pinned MuJoCo; a developer's lies between the two ends."""
    installed = _release(importlib.metadata.version("mujoco"))
    assert installed == _release(mujoco.__version__)
    environment = os.environ.get("MJCF_MODEL_ENVIRONMENT")
    if environment:
        assert installed == _release(_pinned(environment, "mujoco"))
        assert importlib.metadata.version("dm-control") == _pinned(environment, "dm-control")
    else:
        assert _release(_pinned("oldest", "mujoco")) <= installed
        assert installed <= _release(_pinned("newest", "mujoco"))


@pytest.mark.parametrize(
    "statement",
    [
        "from mjcf_model.serializers import loads, to_dict",
        "import mjcf_model.serializers.dicts",
        "import mjcf_model",
        "import mjcf_model.compat.objects",
        "from mjcf_model.compat import mjcf_utils",
        "import mjcf_model.strategies",
        "import mjcf_model.tools.cli",
    ],
)
def test_each_public_module_imports_first_in_a_fresh_interpreter(statement: str) -> None:
    """Whatever a program imports first imports: the packages have no import cycle."""
    result = subprocess.run(
        [sys.executable, "-c", statement], capture_output=True, text=True, check=False
    )
    assert result.returncode == 0, result.stderr


def test_pre_commit_hooks_run_the_installed_command() -> None:
    """Each hook in .pre-commit-hooks.yaml runs a verb of the packaged ``mjcf-model`` script."""
    text = (source_tree() / ".pre-commit-hooks.yaml").read_text()
    hooks = [block for block in text.split("- id: ")[1:]]
    assert [block.split()[0] for block in hooks] == [
        "mjcf-model-fmt",
        "mjcf-model-fmt-check",
        "mjcf-model-lint",
    ]
    for block in hooks:
        fields = dict(
            line.strip().split(": ", 1) for line in block.splitlines()[1:] if ": " in line
        )
        assert fields["language"] == "python" and fields["types"] == "[xml]"
        program, *arguments = fields["entry"].split()
        assert program == "mjcf-model"
        done = subprocess.run(
            [sys.executable, "-m", "mjcf_model", *arguments, "--help"],
            capture_output=True,
            text=True,
            check=False,
        )
        option = "--select" if arguments[0] == "lint" else "--check"
        assert done.returncode == 0 and option in done.stdout, done.stderr
    scripts = tomllib.loads((source_tree() / "pyproject.toml").read_text())["project"]["scripts"]
    assert scripts["mjcf-model"] == "mjcf_model.tools.cli:main"
