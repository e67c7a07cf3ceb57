"""The namespace table and the node classes agree with the installed MuJoCo."""

from __future__ import annotations

import attrs
import mujoco
import pytest

from mjcf_model import prefixed
from mjcf_model.nodes.base import field_table
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema import keywords
from mjcf_model.schema.namespaces import (
    NAMESPACES,
    OBJTYPE_NAMESPACES,
    SCHEMA,
    SCHEMA_RELEASE,
    child_key,
)
from mjcf_model.values import OneOf
from serializers import dumps, loads
from tests.conftest import printed_schema

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


@pytest.mark.parametrize(
    ("keyword_set", "enum", "prefix", "exclude"),
    [
        (keywords.GEOM_TYPES, mujoco.mjtGeom, "mjGEOM_", None),
        (keywords.JOINT_TYPES, mujoco.mjtJoint, "mjJNT_", None),
        (keywords.LIGHT_TYPES, mujoco.mjtLightType, "mjLIGHT_", None),
        (keywords.TRACKING_MODES, mujoco.mjtCamLight, "mjCAMLIGHT_", None),
        (keywords.LIMITED, mujoco.mjtLimited, "mjLIMITED_", None),
    ],
)
def test_keyword_sets_match_mujoco_enums(
    keyword_set: frozenset[str], enum: type, prefix: str, exclude: None
) -> None:
    """Each validated keyword set is exactly the MuJoCo enum it stands for."""
    members = list(enum.__members__)  # type: ignore[attr-defined]
    if "mjNGEOMTYPES" in members:  # geom types stop at the count; the rest are decor
        members = members[: members.index("mjNGEOMTYPES")]
    assert {m[len(prefix) :].lower() for m in members} == set(keyword_set)


def test_validated_keywords_compile() -> None:
    """Every geom type keyword we accept is one MuJoCo's parser accepts."""
    for geom_type in sorted(keywords.GEOM_TYPES - {"mesh", "hfield", "sdf"}):
        xml = f'<mujoco><worldbody><geom type="{geom_type}" size="1 1 1"/></worldbody></mujoco>'
        mujoco.MjModel.from_xml_string(xml)


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


def test_keyword_validators_expose_their_keywords() -> None:
    """Strategies can read the allowed keywords off every keyword field."""
    for cls in set(CLASS_BY_KEY.values()):
        for field in attrs.fields(cls):
            if isinstance(field.validator, OneOf):
                assert field.validator.allowed
