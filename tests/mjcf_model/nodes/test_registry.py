"""Tests of ``mjcf_model.nodes.registry``."""

from __future__ import annotations

import pytest

import mjcf_model
from mjcf_model import nodes
from mjcf_model.nodes.declaring import _set_tag, declared_classes
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema.namespaces import SCHEMA

# -- The node core: one decorator, sparse storage, and the fast builder as an owned contract. --


def test_registry_is_every_declared_schema_key() -> None:
    """CLASS_BY_KEY holds exactly the schema keys the classes declare, all in the table."""
    declared = {
        key: cls
        for cls in declared_classes()
        for key in cls.__node_info__.keys  # type: ignore[attr-defined]
    }
    assert dict(CLASS_BY_KEY) == declared
    assert set(CLASS_BY_KEY) <= set(SCHEMA)
    assert all(cls.__node_info__.tag == key.rsplit("/", 1)[-1] for key, cls in CLASS_BY_KEY.items())


# -- The checklist for adding an MJCF element: two files, and a failure that names the one
#    missed.
#
# A new element (say MuJoCo adds ``<sensor><jointcurrent joint="..."/>``) takes:
#
# 1. its row in ``mjcf_model/schema/namespaces.py`` (attributes, names it declares,
#    references and their namespaces);
# 2. its class in the section module under ``mjcf_model/nodes/`` (``@node``,
#    ``schema_keys`` naming its rows, a field helper per attribute: ``text()`` for
#    names and references; the tag and the namespaces come from the table), and its
#    name in that module's ``__all__``, which ``mjcf_model.nodes`` and ``mjcf_model``
#    gather.
#
# Everything else is derived: the registry, scaling (no lengths unless a rule
# says so; ``scaling/test_rules.py`` flags length-sounding attributes), prefixing
# and reference checks (the table), the strategies (the field helpers). Each test
# here fails with the file to edit; step 1 is checked against the installed MuJoCo's
# schema by ``schema/test_namespaces.py``, which names the table too.


_TABLE = "mjcf_model/schema/namespaces.py"


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
    """Step 2 ends with the class's name in its module's ``__all__``: then it is everywhere."""
    missing = sorted(
        f"add {cls.__name__!r} to the __all__ of {cls.__module__}"
        for cls in CLASS_BY_KEY.values()
        if cls.__name__ not in nodes.__all__
    )
    assert not missing, "\n".join(missing)
    assert set(nodes.__all__) <= set(mjcf_model.__all__)
    assert all(getattr(mjcf_model, name) is getattr(nodes, name) for name in nodes.__all__)


@pytest.mark.parametrize("key", sorted(CLASS_BY_KEY))
def test_each_name_and_reference_is_held_as_text(key: str) -> None:
    """Step 2 follows step 1: an attribute the table says names something holds any text.

    The table is the one source of what declares and what refers: the class does not
    repeat it, but a reference field that converted or checked its value (a number, a
    keyword) would refuse names MuJoCo takes.
    """
    cls, spec = CLASS_BY_KEY[key], SCHEMA[key]
    info = cls.__node_info__
    named = {*spec.references, *spec.declares}
    wrong = sorted(
        xml for xml in named if xml in info.table and info.table[xml] not in info.plain_text
    )
    assert not wrong, (
        f"{key}: the table ({_TABLE}) says {wrong} name elements; declare them with text() "
        f"in {cls.__name__} ({cls.__module__})"
    )


def test_a_class_takes_its_tag_from_its_schema_keys() -> None:
    """Step 2 writes no tag: ``@node`` reads it from the keys, which must agree.

    The classes here only go through the tag step, so no test class joins the
    declared classes the registry and the dict form read.
    """
    assert all(cls.tag == key.rsplit("/", 1)[-1] for key, cls in CLASS_BY_KEY.items())
    assert all(cls.__node_info__.tag == cls.tag for cls in CLASS_BY_KEY.values())
    gizmo = type("Gizmo", (), {"schema_keys": ("body/gizmo", "default/gizmo")})
    _set_tag(gizmo)
    assert gizmo.tag == "gizmo"  # type: ignore[attr-defined]
    with pytest.raises(TypeError, match="more than one tag"):
        _set_tag(type("Muddle", (), {"schema_keys": ("body/gizmo", "body/widget")}))
    with pytest.raises(TypeError, match="comes from schema_keys"):
        _set_tag(type("Twice", (), {"tag": "gizmo", "schema_keys": ("body/gizmo",)}))
