"""Every length attribute the scaling rules scale, set on a small model and refereed by MuJoCo.

Each case (``tests/support/scale_cases.py``) sets one attribute; scaling the model by 2 must
multiply the value MuJoCo compiles from it by 2 (an area by 4). Every attribute that
:func:`scaled` changes on these models must have a case of its own.
"""

from __future__ import annotations

from collections import Counter

import mujoco
import numpy as np
import pytest

from mjcf_model import compiled
from mjcf_model.nodes.base import AnyElement, attribute_items
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.transforms.scaling.pieces import NO_LENGTHS
from mjcf_model.transforms.scaling.rules import RULES
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.traversal import keyed_walk
from serializers import loads
from tests.support.scale_cases import UNCHECKED, scale_cases
from tests.support.scale_elements import ScaleCase
from tests.support.schema_cases import known, reference_cases

CASES = scale_cases()
FACTOR = 3.0  # not 2, where doubling, squaring and adding agree


def changed_attributes(xml: str) -> set[tuple[str, str]]:
    """The ``(key, attribute)`` pairs with a value that scaling the model by ``FACTOR`` writes."""

    def values(node: AnyElement) -> Counter[tuple[str, str, object]]:
        return Counter(
            (str(key), attribute, value)
            for element, key, _ in keyed_walk(node)
            for attribute, value in attribute_items(element)
        )

    written = values(scaled(loads(xml), FACTOR)) - values(loads(xml))
    return {(key, attribute) for key, attribute, _ in written}


@pytest.mark.parametrize("case", CASES, ids=[f"{c.key} {c.attribute}" for c in CASES])
def test_scaled_case_multiplies_the_compiled_value(case: ScaleCase) -> None:
    """Scaling the case by 2 multiplies what MuJoCo compiles from the attribute by 2 (or 4).

    An element the installed MuJoCo does not read (MuJoCo 3.9 has no ``pid``) must be refused.
    """
    assert (case.key, case.attribute) in changed_attributes(case.xml)
    if not known(case.key, case.attribute):
        with pytest.raises(ValueError, match="unrecognized"):
            mujoco.MjModel.from_xml_string(case.xml)
        return
    original = case.value(mujoco.MjModel.from_xml_string(case.xml))
    changed = case.value(compiled(scaled(loads(case.xml), FACTOR)))
    assert np.any(original != 0)
    np.testing.assert_allclose(changed, original * FACTOR**case.power, rtol=case.rtol, atol=0)


def test_every_attribute_scaling_writes_has_a_case() -> None:
    """What scaling changes on any case, the prefix cases too, is an attribute with a case.

    Scaling refuses ``<attach>`` (it scales the expansion), so that prefix case is left out.
    """
    covered = {(c.key, c.attribute) for c in CASES}
    models = [c.xml for c in CASES] + [
        c.xml for c in reference_cases().values() if c.key != "body/attach"
    ]
    written = set().union(*(changed_attributes(xml) for xml in models))
    assert sorted(written - covered) == []


def test_every_key_with_a_scaling_rule_has_a_case_or_a_reason() -> None:
    """A key whose rule scales something has a case, or a listed reason it has none."""
    scaling = {key for key, rule in RULES.items() if rule is not NO_LENGTHS}
    assert sorted(scaling - {c.key for c in CASES} - UNCHECKED.keys()) == []
    assert sorted(UNCHECKED.keys() & {c.key for c in CASES}) == []


@pytest.mark.parametrize("key", ["actuator", "actuator/adhesion", "actuator/orientation"])
def test_unchecked_actuator_keys_still_have_no_crank_length(key: str) -> None:
    """The actuator keys listed as unchecked still have no ``cranklength`` to scale."""
    assert "cranklength" not in SCHEMA[key].attributes
