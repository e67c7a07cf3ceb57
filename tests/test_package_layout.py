"""The packages as imports see them: every module reachable by its dotted name."""

from __future__ import annotations

import ast
import importlib
import importlib.util
import pkgutil
import types
from pathlib import Path

import pytest

import mjcf_model


def _packages() -> list[types.ModuleType]:
    found = [mjcf_model]
    for info in pkgutil.walk_packages(mjcf_model.__path__, "mjcf_model."):
        if info.ispkg:
            found.append(importlib.import_module(info.name))
    return found


@pytest.mark.parametrize("package", _packages(), ids=lambda package: package.__name__)
def test_no_package_hides_a_module_behind_a_name(package: types.ModuleType) -> None:
    """``import a.b.c as m`` gives the module ``c``, not something ``a.b`` re-exports as ``c``.

    A package that re-exports a function under its module's name makes the module
    unreachable as an attribute (``mjcf_model.transforms.scaling.scaled`` was the
    function ``scaled``).
    """
    for module in pkgutil.iter_modules(package.__path__):
        if module.name == "__main__":  # importing it runs the command line
            continue
        value = getattr(package, module.name, None)
        assert value is None or isinstance(value, types.ModuleType), (
            f"{package.__name__}.{module.name} is {value!r}, not the module"
        )
        imported = importlib.import_module(f"{package.__name__}.{module.name}")
        assert getattr(package, module.name) is imported


def _modules_with_code() -> list[str]:
    """The dotted names of the modules that define a function or a class."""
    found = []
    for info in pkgutil.walk_packages(mjcf_model.__path__, "mjcf_model."):
        spec = importlib.util.find_spec(info.name)
        assert spec is not None and spec.origin is not None
        tree = ast.parse(Path(spec.origin).read_text(encoding="utf-8"))
        if any(isinstance(node, (ast.FunctionDef, ast.ClassDef)) for node in tree.body):
            found.append(info.name)
    return found


def test_every_module_with_code_has_a_test_file_named_after_it() -> None:
    """A module ``a/b/c.py`` that defines anything is tested in ``tests/a/b/test_c.py``.

    The tests mirror the source folders: ``mjcf_model.serializers`` lives in the folder
    ``serializers/``, and its tests in ``tests/serializers/``.
    """
    tests = Path(__file__).parent
    modules = _modules_with_code()
    assert len(modules) > 100
    missing = []
    for name in modules:
        *folders, module = name.split(".")
        if folders[:2] == ["mjcf_model", "serializers"]:
            folders = folders[1:]
        if not (tests.joinpath(*folders) / f"test_{module}.py").is_file():
            missing.append(name)
    assert missing == []
