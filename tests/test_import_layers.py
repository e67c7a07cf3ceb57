"""The import contract: every import points down the layer table of ARCHITECTURE.md.

The table is read from ARCHITECTURE.md itself, so the document and the contract cannot
drift apart. Every ``import`` in ``mjcf_model`` (its serializers too) counts: at module
level, inside functions and under ``TYPE_CHECKING``. The modules read are the ones Python
imports (the installed wheel, when ``tests/run_installed.py`` runs the suite).
"""

from __future__ import annotations

import ast
import importlib.util
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("mjcf_model",)


def _modules() -> dict[str, Path]:
    """Every module of the package by dotted name (a package by its own name).

    The folders are walked through links: in a checkout, ``mjcf_model/serializers`` is a
    link to the folder ``serializers/``.
    """
    found = {}
    for package in PACKAGES:
        spec = importlib.util.find_spec(package)
        assert spec is not None and spec.origin is not None, f"{package} is not importable"
        top = Path(spec.origin).parent.parent
        for folder, _, files in os.walk(top / package, followlinks=True):
            for file in sorted(files):
                if not file.endswith(".py"):
                    continue
                path = Path(folder) / file
                parts = list(path.relative_to(top).with_suffix("").parts)
                if parts[-1] == "__init__":
                    parts.pop()
                found[".".join(parts)] = path
    return dict(sorted(found.items()))


MODULES = _modules()


def _layers() -> list[tuple[str, tuple[str, ...]]]:
    """The rows of ARCHITECTURE.md's layer table, bottom first: name and module prefixes."""
    text = (ROOT / "ARCHITECTURE.md").read_text(encoding="utf-8")
    section = text.split("## Layers", 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("| ")]
    layers = []
    for row in rows[1:]:  # the first row is the header
        cells = [cell.strip() for cell in row.strip("|").split("|")]
        prefixes = tuple(name.strip().strip("`") for name in cells[1].split(","))
        layers.append((cells[0], prefixes))
    return layers


LAYERS = _layers()


def layer_of(module: str) -> int:
    """The index of the layer whose longest prefix names ``module``."""
    best, length = -1, -1
    for index, (_, prefixes) in enumerate(LAYERS):
        for prefix in prefixes:
            if (module == prefix or module.startswith(prefix + ".")) and len(prefix) > length:
                best, length = index, len(prefix)
    return best


def _targets(module: str, node: ast.Import | ast.ImportFrom) -> Iterator[str]:
    """The modules of ours an import statement loads (``from p import m`` loads ``p.m``)."""
    if isinstance(node, ast.Import):
        names = [alias.name for alias in node.names]
    else:
        if node.level:
            base = module.split(".")
            if MODULES[module].name != "__init__.py":
                base.pop()
            base = base[: len(base) - (node.level - 1)]
            prefix = ".".join([*base, *([node.module] if node.module else [])])
        else:
            prefix = node.module or ""
        names = [
            f"{prefix}.{alias.name}" if f"{prefix}.{alias.name}" in MODULES else prefix
            for alias in node.names
        ]
    for name in names:
        while name and name not in MODULES:
            name = name.rpartition(".")[0]
        if name and name != module:
            yield name


def _imports() -> dict[str, set[str]]:
    """Each module's imports of our modules, every ``import`` statement in it counted."""
    graph = {}
    for module, path in MODULES.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
        graph[module] = {
            target
            for node in ast.walk(tree)
            if isinstance(node, (ast.Import, ast.ImportFrom))
            for target in _targets(module, node)
        }
    return graph


IMPORTS = _imports()


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected groups of more than one node (Tarjan's, without recursion)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found = []
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            advanced = False
            for successor in successors:
                if successor not in index:
                    index[successor] = low[successor] = len(index)
                    stack.append(successor)
                    on_stack.add(successor)
                    work.append((successor, iter(sorted(graph.get(successor, ())))))
                    advanced = True
                    break
                if successor in on_stack:
                    low[node] = min(low[node], index[successor])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                group = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    group.append(member)
                    if member == node:
                        break
                if len(group) > 1:
                    found.append(sorted(group))
    return found


def test_the_layer_table_names_every_module() -> None:
    """A new package gets a row (or joins one) before it can import anything."""
    assert [module for module in MODULES if layer_of(module) < 0] == []


def test_the_layer_table_names_only_modules_that_exist() -> None:
    """A renamed or removed module takes its row in ARCHITECTURE.md with it."""
    for _, prefixes in LAYERS:
        for prefix in prefixes:
            assert prefix in MODULES, f"ARCHITECTURE.md names {prefix!r}, which is no module"


def test_every_import_points_down_the_layer_table() -> None:
    """A module imports only from its own layer and the layers below it."""
    upward = [
        f"{module} ({LAYERS[layer_of(module)][0]}) imports {target} ({LAYERS[layer_of(target)][0]})"
        for module, targets in sorted(IMPORTS.items())
        for target in sorted(targets)
        if layer_of(target) > layer_of(module)
    ]
    assert upward == []


def test_no_modules_import_each_other() -> None:
    """No module reaches itself through its imports, directly or around a loop."""
    assert cycles(IMPORTS) == []


def package_of(module: str, depth: int) -> str:
    """The package ``module`` belongs to, at most ``depth`` names deep.

    The modules right under ``mjcf_model`` (the facade, ``errors``, ``__main__``) each
    stand alone: they sit at opposite ends of the layer table.
    """
    parts = module.split(".")
    if MODULES[module].name != "__init__.py":
        parts.pop()
    if parts == ["mjcf_model"]:
        return module
    return ".".join(parts[:depth])


@pytest.mark.parametrize("depth", [2, 3], ids=["packages", "sub-packages"])
def test_no_packages_import_each_other(depth: int) -> None:
    """``mjcf_model.transforms`` and ``.serializers``; ``transforms.naming`` and ``.scaling``.

    A package's own modules importing each other (``nodes/sensor`` from ``nodes/base``,
    ``nodes/__init__`` gathering ``nodes/sensor``) is one package at that depth.
    """
    between: dict[str, set[str]] = {}
    for module, targets in IMPORTS.items():
        for target in targets:
            source, goal = package_of(module, depth), package_of(target, depth)
            if source == goal or source.startswith(goal + ".") or goal.startswith(source + "."):
                continue
            between.setdefault(source, set()).add(goal)
    assert cycles(between) == []


@pytest.mark.parametrize(
    ("graph", "expected"),
    [
        ({"a": {"b"}, "b": {"c"}, "c": set()}, []),
        ({"a": {"b"}, "b": {"a"}}, [["a", "b"]]),
        ({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}, [["a", "b", "c"]]),
    ],
)
def test_cycles_finds_every_loop(graph: dict[str, set[str]], expected: list[list[str]]) -> None:
    """The cycle finder the contract relies on finds loops of two and of three."""
    assert cycles(graph) == expected


def test_an_import_inside_a_function_counts(tmp_path: Path) -> None:
    """The contract reads every import statement, not only those at module level."""
    tree = ast.parse("def f():\n    from mjcf_model.serializers.loading import loads\n")
    statement = tree.body[0].body[0]  # type: ignore[attr-defined]
    assert list(_targets("mjcf_model.nodes.base", statement)) == ["mjcf_model.serializers.loading"]
    assert layer_of("mjcf_model.serializers.loading") > layer_of("mjcf_model.nodes.base")


#: What a function may import where it runs, and why: MuJoCo is imported on first use, so
#: that reading and writing never load it (a third of a second) and the command line can
#: choose MuJoCo's OpenGL backend before MuJoCo is imported (it reads ``MUJOCO_GL`` then).
LAZY_IMPORTS = frozenset({"mujoco"})


def _imports_inside_functions() -> list[str]:
    """Every import statement inside a function, as ``module:line imported-name``."""
    found = []
    for module, path in MODULES.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
        for function in ast.walk(tree):
            if not isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
                continue
            for node in ast.walk(function):
                if isinstance(node, ast.Import):
                    found += [f"{module}:{node.lineno} {alias.name}" for alias in node.names]
                elif isinstance(node, ast.ImportFrom):
                    found.append(f"{module}:{node.lineno} {'.' * node.level}{node.module or ''}")
    return found


def test_functions_import_only_what_is_imported_on_first_use() -> None:
    """Imports stand at the top of their module, but MuJoCo's (see :data:`LAZY_IMPORTS`).

    An import inside a function hides a module's dependencies and, for our own modules,
    usually dodges an import cycle the layers should not have.
    """
    hidden = [
        found
        for found in _imports_inside_functions()
        if found.split(" ", 1)[1].split(".")[0] not in LAZY_IMPORTS
    ]
    assert hidden == []


def test_importing_a_low_layer_loads_only_that_layer() -> None:
    """``import mjcf_model.errors`` loads the facade and the errors, nothing more.

    The facade imports its names when first asked for them (``mjcf_model.load``).
    """
    code = (
        "import sys, mjcf_model.errors; "
        "print(sorted(m for m in sys.modules if m.startswith('mjcf_model')))"
    )
    loaded = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    assert loaded.strip() == "['mjcf_model', 'mjcf_model.errors']"


def test_the_facade_gives_every_public_name() -> None:
    """Every name of ``mjcf_model.__all__`` is there, from the module that defines it."""
    import mjcf_model
    from mjcf_model.serializers import loading

    assert {"load", "loads", "dump", "dumps", "to_dict", "from_dict", "Geom"} <= set(
        mjcf_model.__all__
    )
    for name in mjcf_model.__all__:
        assert getattr(mjcf_model, name) is not None, name
    assert mjcf_model.load is loading.load
    assert set(mjcf_model.__all__) <= set(dir(mjcf_model))


def test_an_unknown_name_of_the_facade_is_an_attribute_error() -> None:
    """``mjcf_model.nothing`` raises ``AttributeError``, as any module does."""
    import mjcf_model

    with pytest.raises(AttributeError, match="no attribute 'nothing'"):
        _ = mjcf_model.nothing  # type: ignore[attr-defined]


def test_importing_mjcf_model_loads_no_robosuite_layer() -> None:
    """``import mjcf_model`` leaves robosuite's layer unloaded until it is asked for."""
    code = "import sys, mjcf_model; print([m for m in sys.modules if 'mjcf_model.compat' in m])"
    loaded = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    assert loaded.strip() == "[]"
