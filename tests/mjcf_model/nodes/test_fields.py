"""Vector attributes accept exactly the value counts MuJoCo accepts (MuJoCo is the referee).

For each vector field of a set of common elements, one value fewer than our
minimum and one more than our maximum are given to both MuJoCo and our reader:
we must reject exactly when MuJoCo rejects, or valid models would fail to load.
"""

from __future__ import annotations

import attrs
import mujoco
import pytest

from mjcf_model import MjcfValueError
from mjcf_model.nodes.base import build_node, field_table, get_attribute
from mjcf_model.nodes.registry import CLASS_BY_KEY
from mjcf_model.serializers import loads
from mjcf_model.tree.traversal import keyed_walk
from mjcf_model.values import Unparsed
from tests.conftest import printed_schema

#: A model that holds one element of each key, with ``{a}`` where the attribute goes.
HOSTS = {
    "body": '<mujoco><worldbody><body {a}><geom size="0.1"/></body></worldbody></mujoco>',
    "body/geom": (
        '<mujoco><worldbody><body><freejoint/><geom size="0.1" {a}/></body></worldbody></mujoco>'
    ),
    "body/site": '<mujoco><worldbody><site size="0.1" {a}/></worldbody></mujoco>',
    "body/joint": (
        '<mujoco><worldbody><body><joint {a}/><geom size="0.1"/></body></worldbody></mujoco>'
    ),
    "body/camera": "<mujoco><worldbody><camera {a}/></worldbody></mujoco>",
    "body/light": "<mujoco><worldbody><light {a}/></worldbody></mujoco>",
    "asset/material": '<mujoco><asset><material name="m" {a}/></asset></mujoco>',
    "actuator/general": (
        '<mujoco><worldbody><body><joint name="j"/><geom size="0.1"/></body></worldbody>'
        '<actuator><general joint="j" {a}/></actuator></mujoco>'
    ),
    "actuator/position": (
        '<mujoco><worldbody><body><joint name="j"/><geom size="0.1"/></body></worldbody>'
        '<actuator><position joint="j" {a}/></actuator></mujoco>'
    ),
    "option": "<mujoco><option {a}/></mujoco>",
    "equality/weld": (
        '<mujoco><worldbody><body name="a"><freejoint/><geom size="0.1"/></body></worldbody>'
        '<equality><weld body1="a" {a}/></equality></mujoco>'
    ),
    "contact/pair": (
        '<mujoco><worldbody><geom name="a" size="1"/><body><freejoint/><geom name="b" size="1"/>'
        '</body></worldbody><contact><pair geom1="a" geom2="b" {a}/></contact></mujoco>'
    ),
    "tendon/fixed": (
        '<mujoco><worldbody><body><joint name="j"/><geom size="0.1"/></body></worldbody>'
        '<tendon><fixed {a}><joint joint="j" coef="1"/></fixed></tendon></mujoco>'
    ),
}

#: Value counts each converter accepts: (fewest, most).
COUNTS = {
    "to_vec1to2": (1, 2),
    "to_vec1to3": (1, 3),
    "to_vec1to5": (1, 5),
    "to_vec2": (2, 2),
    "to_vec3": (3, 3),
    "to_vec4": (4, 4),
    "to_vec6": (6, 6),
    "to_float": (1, 1),
}

#: Attributes whose value MuJoCo checks for more than the count (so "0.5"s are not valid);
#: attributes the host itself sets are skipped too.
SKIP = {"name", "class", "childclass", "type", "mode", "target", "joint", "body1", "geom1", "geom2"}


def _cases() -> list[tuple[str, str, int]]:
    cases = []
    for key in HOSTS:
        cls = CLASS_BY_KEY[key]
        converters = {f.name: getattr(f.converter, "__name__", "") for f in attrs.fields(cls)}
        for xml, field in field_table(cls).items():
            counts = COUNTS.get(converters[field])
            if xml in SKIP or counts is None or f' {xml}="' in HOSTS[key]:
                continue
            if xml not in printed_schema()[key]:  # added after the installed MuJoCo
                continue
            fewest, most = counts
            if fewest > 1:
                cases.append((key, xml, fewest - 1))
            cases.append((key, xml, most + 1))
    return cases


def _mujoco_accepts(text: str) -> bool:
    try:
        mujoco.MjModel.from_xml_string(text)
    except ValueError as error:
        assert "data" in str(error) or "format" in str(error), str(error)
        return False
    return True


@pytest.mark.parametrize(("key", "attribute", "count"), _cases())
def test_count_limits_match_mujoco(key: str, attribute: str, count: int) -> None:
    """A typed field reads a value count exactly when MuJoCo does.

    A count it cannot read loads as :class:`Unparsed` text (kept for MuJoCo to
    judge), and the typed field refuses it when a node is built in Python.
    """
    value = " ".join(["0.5"] * count)
    text = HOSTS[key].format(a=f'{attribute}="{value}"')
    element = next(e for e, k, _ in keyed_walk(loads(text)) if k == key)
    ours = not isinstance(get_attribute(element, attribute), Unparsed)
    assert ours == _mujoco_accepts(text)
    cls = CLASS_BY_KEY[key]
    try:
        build_node(cls, {field_table(cls)[attribute]: value})
        built = True
    except MjcfValueError:
        built = False
    assert built == ours
