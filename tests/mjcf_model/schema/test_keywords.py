"""Tests of ``mjcf_model.schema.keywords``."""

from __future__ import annotations

import attrs
import mujoco
import pytest

from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.schema import keywords
from mjcf_model.values import OneOf

# -- The namespace table and the node classes agree with the installed MuJoCo. -----------------


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


def test_keyword_validators_expose_their_keywords() -> None:
    """Strategies can read the allowed keywords off every keyword field."""
    for cls in set(CLASS_BY_KEY.values()):
        for field in attrs.fields(cls):
            if isinstance(field.validator, OneOf):
                assert field.validator.allowed
