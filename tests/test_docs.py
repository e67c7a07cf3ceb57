"""Tests of the documentation site's hooks (``docs/hooks.py``): the node fields page."""

from __future__ import annotations

import importlib.util
from types import ModuleType

import attrs

from mjcf_model.nodes.node_info import BASE_FIELDS, xml_name
from mjcf_model.nodes.registry import CLASS_BY_KEY
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
