"""Tests of the documentation: the site's hooks (``docs/hooks.py``) and every example.

The ``>>>`` examples of the guide run as doctests (``--doctest-glob``); the ``python``
blocks of the README and of each guide page run here, as a reader runs them.
"""

from __future__ import annotations

import importlib.util
import shutil
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import attrs
import mujoco
import pytest

from mjcf_model.nodes.node_info import BASE_FIELDS, xml_name
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.serializers import load
from mjcf_model.tools.cli.examples import examples_folder
from mjcf_model.tools.lint import RULES, lint
from tests.conftest import MUJOCO_VERSION
from tests.test_packaging import source_tree


def _hooks() -> ModuleType:
    path = source_tree() / "docs" / "hooks.py"
    spec = importlib.util.spec_from_file_location("docs_hooks", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_node_fields_page_lists_every_field_of_every_node_with_its_meaning() -> None:
    """Each node class has a section, and each field a row with its MJCF name and meaning.

    The meaning is the field's ``#:`` comment: a field without one fails here.
    """
    hooks = _hooks()
    page = (source_tree() / "docs" / "reference" / "nodes.md").read_text()
    assert hooks.NODE_FIELDS_MARKER in page
    text = hooks.on_page_markdown(page)
    assert hooks.NODE_FIELDS_MARKER not in text
    sections = {part.split("\n", 1)[0]: part for part in text.split("\n## ")[1:]}
    classes = set(CLASS_BY_KEY.values())
    assert set(sections) == {cls.__name__ for cls in classes}
    for cls in classes:
        rows = {
            line.split(" | ")[0].strip("| `"): line
            for line in sections[cls.__name__].splitlines()
            if line.startswith("| `")
        }
        fields = [f for f in attrs.fields(cls) if f.name not in BASE_FIELDS]
        assert set(rows) == {f.name for f in fields}, cls.__name__
        for field in fields:
            cells = [cell.strip() for cell in rows[field.name].strip("|").split(" | ")]
            assert cells[1] == f"`{xml_name(field)}`", (cls.__name__, field.name)
            assert cells[3], f"{cls.__name__}.{field.name} has no #: comment"


def test_sphinx_roles_in_rendered_docstrings_become_plain_code() -> None:
    """``:func:`` and its kin in front of code are dropped; other colons stay."""
    hooks = _hooks()
    html = "Use :func:<code>attrs.evolve</code>, :py:class:<code>Geom</code>; ratio 1:2."
    plain = "Use <code>attrs.evolve</code>, <code>Geom</code>; ratio 1:2."
    assert hooks.on_page_content(html) == plain


#: What the script of a page runs after its blocks: each test function they define, as
#: pytest would (the property-testing example defines one).
_RUN_DEFINED_TESTS = """
for _name, _function in list(globals().items()):
    if _name.startswith("test_") and callable(_function):
        _function()
"""


def python_blocks(text: str) -> list[str]:
    r"""The page's fenced ``python`` blocks that start a line, in order.

    Examples:
        >>> python_blocks("a\n```python\nx = 1\n```\n```sh\nls\n```\n")
        ['x = 1\n']

    """
    blocks, current = [], None
    for line in text.splitlines(keepends=True):
        if current is None:
            if line.rstrip() == "```python":
                current = []
        elif line.rstrip() == "```":
            blocks.append("".join(current))
            current = None
        else:
            current.append(line)
    return blocks


def _pages() -> list[Path]:
    tree = source_tree()
    pages = [tree / "README.md", *sorted((tree / "docs").rglob("*.md"))]
    return [page for page in pages if python_blocks(page.read_text())]


def test_the_readme_and_the_guide_pages_with_examples_have_them_to_run() -> None:
    """The pages whose ``python`` blocks the next test runs (a lost fence would drop one)."""
    names = {page.name for page in _pages()}
    assert names == {
        "README.md",
        "composition.md",
        "lint.md",
        "load-and-dump.md",
        "robosuite.md",
        "transforms.md",
        "variants.md",
    }


@pytest.mark.skipif(
    MUJOCO_VERSION < (4, 0),
    reason=f"the examples are written for the newest MuJoCo (the variants guide steps "
    f"mujoco.batch, new in 4.0); this is {mujoco.__version__}",
)
@pytest.mark.parametrize("page", _pages(), ids=lambda page: page.name)
def test_every_python_example_on_the_page_runs_beside_the_bundled_models(
    page: Path, tmp_path: Path
) -> None:
    """The page's blocks, one script in order, run in a copy of ``mjcf-model examples``.

    The pages tell the reader to run them there (``arm.xml``, ``workcell/``); a block
    that loads a file that does not exist, uses a name no block defines or raises
    fails here.
    """
    folder = tmp_path / "demo"
    shutil.copytree(examples_folder(), folder, ignore=shutil.ignore_patterns("__pycache__"))
    script = tmp_path / f"example_{page.stem.replace('-', '_')}.py"
    script.write_text("\n\n".join(python_blocks(page.read_text())) + _RUN_DEFINED_TESTS)
    run = subprocess.run(
        [sys.executable, str(script)], cwd=folder, capture_output=True, text=True, timeout=600
    )
    assert run.returncode == 0, f"{page.name}:\n{run.stdout}\n{run.stderr}"


def _lint_examples() -> list[tuple[str, str]]:
    """Each rule section of the linting guide: its code and its example model."""
    page = (source_tree() / "docs" / "guide" / "lint.md").read_text()
    found = []
    for section in page.split("\n### ")[1:]:
        code = section.split(" ", 1)[0]
        example = section.split("```xml\n", 1)[1].split("```", 1)[0]
        found.append((code, example))
    return found


def test_the_linting_guide_has_one_section_for_each_rule() -> None:
    """A rule without its section on the page (or a section without its rule) fails."""
    assert sorted(code for code, _ in _lint_examples()) == sorted(RULES)


@pytest.mark.parametrize("code, example", _lint_examples(), ids=[c for c, _ in _lint_examples()])
def test_each_rules_example_on_the_linting_guide_is_found(
    code: str, example: str, tmp_path: Path
) -> None:
    """Linted as a file beside the bundled examples, the example gives its rule's finding."""
    folder = tmp_path / "demo"
    shutil.copytree(examples_folder(), folder, ignore=shutil.ignore_patterns("__pycache__"))
    path = folder / "example.xml"
    path.write_text(example)
    findings = lint(load(path, inline_includes=True))
    assert code in {finding.rule for finding in findings}, [str(f) for f in findings]
    assert all(f.file == str(path) and f.line for f in findings if f.rule == code)
