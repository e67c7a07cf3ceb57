"""Tests of ``mjcf_model.compat.mjcf_utils.constants``."""

from __future__ import annotations

import pytest

from tests.support.compat_utils import (
    RS_CONSTANTS,
    comparable,
    ours,
    rs,
)

# -- compat ``mjcf_utils``: the same names and signatures as robosuite's, and the golden checks.
#
# The golden checks are items 1 to 6 of section 6 of the robosuite contract
# (``/work/shared/reference/robosuite_contract.md``), each run against robosuite
# 1.5.2 itself and against the exact text the contract recorded.


@pytest.mark.parametrize("name", RS_CONSTANTS)
def test_constants_match_robosuite(name: str) -> None:
    """Each constant has robosuite's value and type; ordered ones have robosuite's order."""
    mine, theirs = getattr(ours, name), getattr(rs, name)
    assert type(mine) is type(theirs)
    assert mine == theirs
    if not isinstance(mine, set):  # a set's iteration order depends on how it was built
        assert comparable(mine, {}) == comparable(theirs, {}) and list(mine) == list(theirs)
