"""Shared test setup: hypothesis profiles and the real-world corpus.

The profile comes from ``HYPOTHESIS_PROFILE``: ``ci`` (the default under
``CI=true``; 100 examples per property), ``dev`` (50, for quick local runs),
``compat`` (25: the MuJoCo 3.9 environment, which checks compatibility, not search) or
``mutation`` (30 fixed examples, no shrinking: the mutation tests run the suite
once per mutant and need the same verdict each time, fast).
"""

from __future__ import annotations

import functools
import importlib.util
import os
import re
from pathlib import Path

import mujoco
import pytest
from hypothesis import HealthCheck, Phase, settings

from tests.support.plan_counting import plan_calls  # noqa: F401  (a fixture)

settings.register_profile(
    "ci",
    max_examples=100,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
    print_blob=True,
)
settings.register_profile(
    "dev", max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.register_profile(  # the second environment: MuJoCo 3.9 compatibility, not search
    "compat", max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.register_profile(
    "mutation",
    max_examples=30,
    derandomize=True,
    database=None,
    deadline=None,
    phases=[Phase.explicit, Phase.generate],
    suppress_health_check=list(HealthCheck),
)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev"))

#: For a property run once per node class (about 140 runs, one property over every class):
#: a quarter of the profile's examples each (at least 10), 3,500 in all under ``ci``.
PER_CLASS = settings(max_examples=max(10, settings.default.max_examples // 4))


#: MuJoCo's asset cache per test process: room for every mesh and texture of the corpus
#: decoded (1.4 GB with MuJoCo 4.0), so a robot's meshes are decoded once per process,
#: not once per test (a cold compile of robosuite's Panda takes 1.3 s, a warm one 0.12 s).
ASSET_CACHE_BYTES = 2_000_000_000


# Before collection, which compiles every corpus file (:func:`compiling_corpus`): what it
# decodes is then in the cache for the tests.
mujoco.mj_setCacheCapacity(mujoco.mj_getCache(), ASSET_CACHE_BYTES)


@pytest.fixture(autouse=True)
def _room_in_mujocos_asset_cache() -> None:
    """Empty MuJoCo's asset cache before a test when it is nine tenths full.

    Once the cache is full MuJoCo keeps no new asset: every later compile of a robot
    decodes its meshes again (robosuite's environments ran three times slower late in a
    run than alone). What a test checks never depends on the cache, only how long it
    takes.
    """
    cache = mujoco.mj_getCache()
    if mujoco.mj_getCacheSize(cache) > mujoco.mj_getCacheCapacity(cache) * 9 // 10:
        mujoco.mj_clearCache(cache)


FIXTURES = Path(__file__).parent / "fixtures"
#: The MuJoCo release this process runs, as (major, minor).
MUJOCO_VERSION = tuple(int(part) for part in mujoco.__version__.split(".")[:2])


def _package_dir(name: str) -> Path:
    spec = importlib.util.find_spec(name)
    assert spec is not None and spec.origin is not None, f"{name} is a test dependency"
    return Path(spec.origin).parent


def corpus_files() -> list[Path]:
    """Every XML file shipped in the installed robosuite and dm_control wheels.

    Hidden files are left out: ``compile_text_beside`` writes its temporary
    ``.mjcf-model-*.xml`` files there while other test workers run.
    """
    files: list[Path] = []
    for package in ("robosuite", "dm_control"):
        found = _package_dir(package).rglob("*.xml")
        files.extend(sorted(p for p in found if not p.name.startswith(".")))
    return files


@functools.cache
def compiling_corpus() -> list[Path]:
    """The corpus files that MuJoCo compiles as shipped."""
    compiling = []
    for path in corpus_files():
        try:
            mujoco.MjModel.from_xml_path(str(path))
        except ValueError:
            continue
        compiling.append(path)
    return compiling


@functools.cache
def loading_corpus() -> list[Path]:
    """The corpus files mjcf-model loads (the non-MJCF ones are left out)."""
    from mjcf_model.errors import MjcfError
    from mjcf_model.serializers import load

    loading = []
    for path in corpus_files():
        try:
            load(path)
        except MjcfError:
            continue
        loading.append(path)
    return loading


#: Which share of the corpus each corpus-wide test runs on: every Nth file (in path
#: order) from ``MJCF_MODEL_CORPUS_SHARE`` (default 1, every file). ``run_installed.py``
#: gives the oldest environment a third: its run checks that the library works on MuJoCo
#: 3.9, on a third of the real files spread over both packages, while the newest
#: environment runs every test on every file.
CORPUS_SHARE = int(os.environ.get("MJCF_MODEL_CORPUS_SHARE", "1"))


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Deselect the corpus-wide test cases outside this run's share of the corpus."""
    if CORPUS_SHARE == 1:
        return
    place = {path: index for index, path in enumerate(corpus_files())}
    kept: list[pytest.Item] = []
    dropped: list[pytest.Item] = []
    for item in items:
        callspec = getattr(item, "callspec", None)
        values = callspec.params.values() if callspec is not None else ()
        files = [place[value] for value in values if isinstance(value, Path) and value in place]
        outside = bool(files) and all(index % CORPUS_SHARE for index in files)
        (dropped if outside else kept).append(item)
    if dropped:
        config.hook.pytest_deselected(items=dropped)
        items[:] = kept


def corpus_id(path: Path) -> str:
    """A short test id: the package and the path inside it."""
    parts = path.parts
    for package in ("robosuite", "dm_control"):
        if package in parts:
            index = len(parts) - 1 - parts[::-1].index(package)
            return "/".join(parts[index:])
    return path.name


@functools.cache
def printed_schema() -> dict[str, set[str]]:
    """The installed MuJoCo's ``mj_printSchema``, as schema keys and attribute sets."""
    entries: list[tuple[int, str, list[str]]] = []
    for line in mujoco.mj_printSchema(False, False).splitlines():
        match = re.match(r"^(\s*)(\S+) \((.)\)\s*(.*)$", line)
        if match:
            entries.append((len(match.group(1)) // 3, match.group(2), match.group(4).split()))
        elif entries:
            entries[-1][2].extend(line.split())
    schema: dict[str, set[str]] = {}
    stack: list[str] = []
    for depth, tag, attributes in entries:
        stack = [*stack[:depth], tag.replace("(world)", "")]
        key = "/".join(stack[1:]) or "mujoco"
        schema[key] = set(attributes)
    return schema


@pytest.fixture
def robot(tmp_path: Path) -> Path:
    """A robot in a folder of its own, its mesh under ``assets/``."""
    # Imported here: tests.support.model_files imports this module.
    from tests.support.model_files import ROBOT, obj_mesh, write_tree

    folder = write_tree(
        tmp_path / "robots" / "arm", {"robot.xml": ROBOT, "assets/link.obj": obj_mesh(6)}
    )
    return folder / "robot.xml"
