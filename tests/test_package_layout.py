"""The packages as imports see them: every module reachable by its dotted name."""

from __future__ import annotations

import importlib
import pkgutil
import types

import pytest

import mjcf_model
import serializers


def _packages() -> list[types.ModuleType]:
    found = [mjcf_model, serializers]
    for root in (mjcf_model, serializers):
        for info in pkgutil.walk_packages(root.__path__, root.__name__ + "."):
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
