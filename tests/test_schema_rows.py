"""Every reference row of the namespace table, prefixed and refereed by MuJoCo.

Each row has a model of its own (``tests/support/schema_cases.py``). MuJoCo must compile
the prefixed model to the original's arrays with every name prefixed, and must
reject the model when that one reference names nothing: so the row's reference
is one MuJoCo reads, and a prefix that skips it fails here.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import mujoco
import pytest

from mjcf_model import compiled
from mjcf_model.nodes.base import AnyElement, get_attribute, with_attributes
from mjcf_model.schema.namespaces import SCHEMA
from mjcf_model.transforms.naming.renaming import prefixed
from mjcf_model.tree.traversal import keyed_walk, map_elements
from serializers import loads
from tests.support.oracles import prefix_problems
from tests.support.schema_cases import UNUSABLE, known, reference_cases, reference_rows
from tests.support.schema_model import Case

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
