"""The checklist for adding an MJCF element: three files, and a failure that names the one missed.

A new element (say MuJoCo adds ``<sensor><jointcurrent joint="..."/>``) takes:

1. its row in ``mjcf_model/schema/namespaces.py`` (attributes, names it declares,
   references and their namespaces);
2. its class in the section module under ``mjcf_model/nodes/`` (``@node``, a
   field helper per attribute, ``reference(namespace)`` for each reference);
3. its name in ``mjcf_model/nodes/__init__.py``.

Everything else is derived: the registry, scaling (no lengths unless a rule
says so; ``tests/test_scaling.py`` flags length-sounding attributes), prefixing
and reference checks (the table), the strategies (the field helpers). Each test
here fails with the file to edit; step 1 is checked against the installed MuJoCo's
schema by ``tests/test_schema.py``, which names the table too.
"""

from __future__ import annotations

import attrs
import pytest

import mjcf_model
from mjcf_model import nodes
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema.namespaces import SCHEMA

_TABLE = "mjcf_model/schema/namespaces.py"
_INIT = "mjcf_model/nodes/__init__.py"


def _section_module(key: str) -> str:
    return f"the section module under mjcf_model/nodes/ for {key.split('/')[0]!r}"


def test_every_row_has_a_declared_class() -> None:
    """Step 2: a class declares each row's key in its ``schema_keys``."""
    missing = sorted(set(SCHEMA) - set(CLASS_BY_KEY))
    assert not missing, "\n".join(
        f"declare a class with schema_keys containing {key!r} in {_section_module(key)}"
        for key in missing
    )


def test_every_declared_class_is_exported() -> None:
    """Step 3: each class is importable from ``mjcf_model`` (its name in the nodes facade)."""
    missing = sorted(
        {cls.__name__ for cls in CLASS_BY_KEY.values() if cls.__name__ not in nodes.__all__}
    )
    assert not missing, f"add {missing} to __all__ and the imports of {_INIT}"
    assert all(getattr(mjcf_model, name) is getattr(nodes, name) for name in nodes.__all__)


@pytest.mark.parametrize("key", sorted(CLASS_BY_KEY))
def test_each_reference_is_declared_in_both_places(key: str) -> None:
    """Steps 1 and 2 agree: a table reference is a ``reference(namespace)`` field, and back."""
    cls, spec = CLASS_BY_KEY[key], SCHEMA[key]
    fields = {f.name: f for f in attrs.fields(cls)}
    for xml, field_name in cls.__node_info__.table.items():
        if xml not in spec.attributes:
            continue
        declared = fields[field_name].metadata.get("namespace")
        expected = spec.references.get(xml)
        assert declared == expected, (
            f"{key} {xml!r}: the table ({_TABLE}) says {expected!r}, the class "
            f"{cls.__name__} ({cls.__module__}) says {declared!r}; make them agree"
        )
