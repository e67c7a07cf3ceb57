"""MkDocs hooks: the node fields page, and docstrings' Sphinx roles shown as plain code.

* A page holding :data:`NODE_FIELDS_MARKER` gets, in its place, every node class with
  its fields: the MJCF attribute, the type and the field's ``#:`` comment, read from the
  source (mkdocstrings shows attrs fields only where they carry a docstring).
* The docstrings cross-reference in Sphinx's words (``:func:`attrs.evolve```), which
  mkdocstrings prints as they are; the role is dropped, the code stays.

``mkdocs.yml`` names this file under ``hooks:``; ``tests/test_docs.py`` tests it.
"""

from __future__ import annotations

import inspect
import re
from typing import Any

import attrs

#: Where the node fields page puts the generated reference.
NODE_FIELDS_MARKER = "<!-- node fields -->"

#: A Sphinx role before code in rendered HTML (``:func:<code>...``) or in Markdown.
_ROLE = re.compile(r":(?:py:)?(?:func|class|mod|meth|attr|data|exc|obj|const|ref):(?=<code>|`)")


def without_roles(html: str) -> str:
    """``html`` with the Sphinx roles in front of code removed.

    Examples:
        >>> without_roles("see :func:<code>attrs.evolve</code> and :class:`Geom`")
        'see <code>attrs.evolve</code> and `Geom`'

    """
    return _ROLE.sub("", html)


def field_comments(cls: type) -> dict[str, str]:
    """The ``#:`` comment of each field ``cls`` declares in its own body, by field name.

    Examples:
        >>> from mjcf_model import Body
        >>> field_comments(Body)["mocap"]
        'Whether this is a mocap body.'

    """
    lines, _ = inspect.getsourcelines(cls)
    found: dict[str, str] = {}
    pending: list[str] = []
    for line in lines:
        stripped = line.strip()
        if stripped.startswith("#:"):
            pending.append(stripped[2:].strip())
            continue
        declared = re.match(r"([A-Za-z_]\w*)\s*:", stripped)
        if declared and pending:
            found[declared.group(1)] = " ".join(pending)
        pending = []
    return found


def node_fields_markdown() -> str:
    """Every node class, its docstring's first line and a table of its MJCF fields."""
    from mjcf_model.nodes.node_info import BASE_FIELDS, xml_name
    from mjcf_model.nodes.registry import CLASS_BY_KEY

    classes = sorted(set(CLASS_BY_KEY.values()), key=lambda cls: cls.__name__)
    sections = []
    for cls in classes:
        comments: dict[str, str] = {}
        for klass in reversed(cls.__mro__):
            if attrs.has(klass):
                comments.update(field_comments(klass))
        rows = [
            f"| `{field.name}` | `{xml_name(field)}` | `{_type_text(field.type)}` | "
            f"{comments.get(field.name, '')} |"
            for field in attrs.fields(cls)
            if field.name not in BASE_FIELDS
        ]
        summary = (inspect.getdoc(cls) or "").split("\n\n")[0].replace("\n", " ")
        keys = ", ".join(f"`{key}`" for key in cls.__node_info__.keys)
        table = ["| field | MJCF attribute | type | meaning |", "|---|---|---|---|", *rows]
        body = "\n".join(table) if rows else "No attributes."
        sections.append(f"## {cls.__name__}\n\n{summary} (schema keys: {keys})\n\n{body}\n")
    return "\n".join(sections)


def _type_text(annotation: Any) -> str:
    """The annotation as text a table cell can hold (``Floats or None``)."""
    return str(annotation).replace(" | ", " or ")


def on_page_markdown(markdown: str, **_: Any) -> str:
    """MkDocs: the node fields page's tables, in place of its marker."""
    if NODE_FIELDS_MARKER in markdown:
        return markdown.replace(NODE_FIELDS_MARKER, node_fields_markdown())
    return markdown


def on_page_content(html: str, **_: Any) -> str:
    """MkDocs: every page's HTML without Sphinx roles in front of code."""
    return without_roles(html)
