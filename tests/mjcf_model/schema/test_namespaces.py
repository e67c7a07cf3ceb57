"""Tests of ``mjcf_model.schema.namespaces``."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import mujoco
import pytest

from mjcf_model import compiled, prefixed
from mjcf_model.nodes.base import AnyElement, field_table, get_attribute, with_attributes
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema.namespaces import (
    NAMESPACES,
    OBJTYPE_NAMESPACES,
    SCHEMA,
    SCHEMA_RELEASE,
    child_key,
    reference_namespace,
)
from mjcf_model.serializers import dumps, loads
from mjcf_model.tree.traversal import keyed_walk, map_elements
from tests.conftest import printed_schema
from tests.support.oracles import prefix_problems
from tests.support.schema_cases import UNUSABLE, known, reference_cases, reference_rows
from tests.support.schema_model import Case

# -- The namespace table and the node classes agree with the installed MuJoCo. -----------------


#: Elements MuJoCo reads outside the schema it prints.
_OUTSIDE_PRINTED_SCHEMA = {"include", "body/frame", "body/replicate", "worldbody"}


PRINTED = printed_schema()
#: Whether the installed MuJoCo is the release the table mirrors; an older one
#: (down to the oldest supported) prints a subset of it.
TABLE_RELEASE_INSTALLED = mujoco.__version__ == SCHEMA_RELEASE


#: Elements the oldest supported MuJoCo (3.9) prints that ``SCHEMA_RELEASE`` removed;
#: they load, round-trip and pass through transforms as generic elements.
_REMOVED_SINCE_OLDEST = {
    "body/composite",
    "body/composite/geom",
    "body/composite/joint",
    "body/composite/plugin",
    "body/composite/plugin/config",
    "body/composite/site",
    "body/composite/skin",
    "equality/flexvert",
}
#: Attributes MuJoCo 3.9 prints that ``SCHEMA_RELEASE`` removed; they load and
#: round-trip as attributes the typed class does not model.
_ATTRIBUTES_REMOVED_SINCE_OLDEST = {
    "body/flexcomp/contact": {"internal"},
    "deformable/flex/contact": {"internal"},
}


def test_every_printed_element_is_in_the_table() -> None:
    """Each element MuJoCo prints has a table entry (a new element fails here)."""
    missing = set(PRINTED) - set(SCHEMA)
    new = sorted(missing - (set() if TABLE_RELEASE_INSTALLED else _REMOVED_SINCE_OLDEST))
    assert new == [], f"add rows for {new} to mjcf_model/schema/namespaces.py"


@pytest.mark.parametrize("key", sorted(set(PRINTED) & set(SCHEMA)))
def test_every_printed_attribute_is_in_the_table(key: str) -> None:
    """The table lists the attributes MuJoCo prints: exactly those of ``SCHEMA_RELEASE``."""
    if TABLE_RELEASE_INSTALLED:
        assert SCHEMA[key].attributes == PRINTED[key]
    else:
        removed = _ATTRIBUTES_REMOVED_SINCE_OLDEST.get(key, set())
        assert sorted(PRINTED[key] - SCHEMA[key].attributes - removed) == []


def test_table_has_nothing_mujoco_lacks() -> None:
    """Beyond MuJoCo ``SCHEMA_RELEASE``'s printed schema, only what MuJoCo handles specially."""
    beyond = set(SCHEMA) - set(PRINTED)
    if TABLE_RELEASE_INSTALLED:
        assert beyond == _OUTSIDE_PRINTED_SCHEMA
    else:  # an older MuJoCo lacks elements added since
        assert beyond >= _OUTSIDE_PRINTED_SCHEMA


def test_every_name_attribute_declares_a_namespace() -> None:
    """Every element with a ``name`` attribute says which namespace the name lives in."""
    missing = [k for k, s in SCHEMA.items() if "name" in s.attributes and "name" not in s.declares]
    assert missing == []


def test_references_point_to_declared_namespaces() -> None:
    """Every referenced namespace is one some element declares names in."""
    declared = {ns for spec in SCHEMA.values() for ns in spec.declares.values()}
    referenced = {
        ns for spec in SCHEMA.values() for ns in spec.references.values() if not ns.startswith("@")
    }
    assert referenced <= declared
    assert declared | referenced == NAMESPACES


def test_class_and_childclass_always_refer_to_default_classes() -> None:
    """``class`` and ``childclass`` are class references wherever they appear (but on <default>)."""
    for key, spec in SCHEMA.items():
        for attribute in ("class", "childclass"):
            if attribute in spec.attributes and key != "default":
                assert spec.references[attribute] == "class", key


def test_objtype_namespaces_cover_mujoco_object_types() -> None:
    """Every object type keyword a sensor can name maps to a namespace."""
    names = {
        m[len("mjOBJ_") :].lower() for m in mujoco.mjtObj.__members__ if m.startswith("mjOBJ_")
    }
    unmapped = names - set(OBJTYPE_NAMESPACES) - {"unknown", "dof", "default", "model"}
    assert unmapped == set()


@pytest.mark.parametrize("key", sorted(CLASS_BY_KEY))
def test_class_fields_are_attributes_of_their_element(key: str) -> None:
    """A typed class models only attributes MuJoCo accepts on its elements, and all of them."""
    cls = CLASS_BY_KEY[key]
    assert cls.tag == SCHEMA[key].tag
    served = set().union(*(SCHEMA[k].attributes for k, c in CLASS_BY_KEY.items() if c is cls))
    assert set(field_table(cls)) == served


def test_child_keys_follow_the_tree() -> None:
    """Context-dependent tags resolve to the right schema entry."""
    assert child_key("equality", "joint") == "equality/joint"
    assert child_key("tendon/fixed", "joint") == "tendon/fixed/joint"
    assert child_key("body/frame", "joint") == "body/joint"
    assert child_key("body/replicate", "body") == "body"
    assert child_key("default", "default") == "default"
    assert child_key("sensor", "contact") == "sensor/contact"
    assert child_key("body", "composite") is None


def test_a_section_mujoco_does_not_define_has_no_key_and_passes_through_prefixing() -> None:
    """A future top-level section is unknown: it keeps its name while known names are prefixed."""
    assert child_key("mujoco", "wheel") is None
    model = loads(
        '<mujoco><wheel name="w" radius="1"/><worldbody><body name="b"><geom size="1"/>'
        "</body></worldbody></mujoco>"
    )
    assert dumps(prefixed(model, "p_")) == dumps(model).replace('name="b"', 'name="p_b"')


# -- Every reference row of the namespace table, prefixed and refereed by MuJoCo. --------------
#
# Each row has a model of its own (``tests/support/schema_cases.py``). MuJoCo must compile
# the prefixed model to the original's arrays with every name prefixed, and must
# reject the model when that one reference names nothing: so the row's reference
# is one MuJoCo reads, and a prefix that skips it fails here.


CASES = reference_cases()
ROWS = sorted(CASES)
row_ids = [f"{key} {attribute}" for key, attribute in ROWS]
#: A name no case declares.
_NOWHERE = "nowhere"


def compile_text(case: Case, text: str) -> Any:
    """MuJoCo's model of ``text``, with the case's files."""
    return mujoco.MjModel.from_xml_string(text, dict(case.assets))


def with_reference(case: Case, value: str) -> AnyElement:
    """The case's model with the first use of its row's reference set to ``value``.

    In a list of references, only the first name is replaced.
    """
    used: list[AnyElement] = []

    def visit(element: AnyElement, key: str | None, _: Sequence[AnyElement]) -> AnyElement:
        old = get_attribute(element, case.attribute)
        if used or key != case.key or not isinstance(old, str):
            return element
        used.append(element)
        rest = old.split()[1:] if case.attribute in SCHEMA[key].list_references else []
        return with_attributes(element, {case.attribute: " ".join([value, *rest])})

    changed = map_elements(visit, loads(case.xml))
    assert used, f"the case has no {case.key} element with {case.attribute}"
    return changed


def test_every_reference_row_has_a_case_or_a_reason() -> None:
    """Each (key, reference) row of the table has a generated case, or a listed reason."""
    rows = {f"{key} {attribute}" for key, attribute in reference_rows()}
    covered = {f"{key} {attribute}" for key, attribute in CASES}
    assert sorted(rows - covered - UNUSABLE.keys()) == []
    assert sorted(covered & UNUSABLE.keys()) == []
    assert sorted(UNUSABLE.keys() - rows) == []


def test_unusable_rows_are_still_rejected_by_mujoco() -> None:
    """Each row listed as unusable (none on MuJoCo 3.9, whose plugins serve them) is rejected."""
    for row, unusable in UNUSABLE.items():
        with pytest.raises(ValueError, match=unusable.error):
            mujoco.MjModel.from_xml_string(unusable.xml)
        assert row in {f"{key} {attribute}" for key, attribute in reference_rows()}


@pytest.mark.parametrize("row", ROWS, ids=row_ids)
def test_prefixed_case_passes_the_prefix_oracle(row: tuple[str, str]) -> None:
    """The prefixed case compiles to the original's arrays with every name prefixed.

    A row the installed MuJoCo does not read (MuJoCo 3.9 lacks a few) must be refused.
    """
    case = CASES[row]
    if not known(*row):
        with pytest.raises(ValueError, match="unrecognized"):
            compile_text(case, case.xml)
        return
    original = compile_text(case, case.xml)
    changed = compiled(prefixed(loads(case.xml), "p_"), assets=case.assets)
    assert prefix_problems(original, changed, "p_") == []


@pytest.mark.parametrize("row", [r for r in ROWS if known(*r)], ids=lambda r: " ".join(r))
def test_case_uses_its_reference(row: tuple[str, str]) -> None:
    """MuJoCo rejects the case when its row's reference names nothing: MuJoCo reads it."""
    case = CASES[row]
    with pytest.raises(ValueError, match=f"{_NOWHERE}|unknown"):
        compiled(with_reference(case, _NOWHERE), assets=case.assets)


def test_actuator_site_transmission_is_prefixed() -> None:
    """An actuator's ``site`` transmission (and its ``refsite``) follows the prefixed sites."""
    case = CASES["actuator/motor", "refsite"]
    motors = [
        e for e, key, _ in keyed_walk(prefixed(loads(case.xml), "p_")) if key == "actuator/motor"
    ]
    assert [(get_attribute(m, "site"), get_attribute(m, "refsite")) for m in motors] == [
        ("p_shoulder", "p_elbow")
    ]
    original = compile_text(case, case.xml)
    changed = compiled(prefixed(loads(case.xml), "p_"))
    assert prefix_problems(original, changed, "p_") == []


# -- The namespace each reference attribute points to, read from the namespace table. ----------
#
# Expected values are the MJCF rules, checked against MuJoCo: a geom's ``material``
# names a material (MuJoCo rejects an unknown one as a material), and ``size``
# names nothing.


def test_a_plain_reference_points_to_its_namespace() -> None:
    """A geom's material is a material reference; MuJoCo looks the name up among materials."""
    with pytest.raises(ValueError, match="material 'red' not found"):
        mujoco.MjModel.from_xml_string(
            '<mujoco><worldbody><geom size="1" material="red"/></worldbody></mujoco>'
        )
    assert reference_namespace(SCHEMA["body/geom"], "material", {}) == "material"
    assert reference_namespace(SCHEMA["body/geom"], "size", {}) is None
