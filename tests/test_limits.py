"""Limits: trees deeper than the recursion limit, and the memory a huge attribute takes."""

from __future__ import annotations

import copy
import sys
from collections.abc import Callable

import pytest

from mjcf_model import (
    Mujoco,
    full_repr,
    prefixed,
    scaled,
)
from mjcf_model.serializers import dumps, from_dict, from_etree, loads, to_dict, to_etree
from tests.support.oracles import _compiled, _round_trips_like_mujoco

# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


#: MuJoCo's parser (tinyxml2) refuses element nesting deeper than this.
MUJOCO_DEEPEST_BODY_CHAIN = 496


# -- depth -----------------------------------------------------------------------------


def _chain_text(depth: int) -> str:
    return (
        "<mujoco><worldbody>"
        + '<body><geom size="0.1"/>' * depth
        + "</body>" * depth
        + "</worldbody></mujoco>"
    )


def _default_chain_text(depth: int) -> str:
    opened = "".join(f'<default class="c{i}"><geom size="{i + 1}"/>' for i in range(depth))
    return (
        f"<mujoco><default>{opened}{'</default>' * depth}</default>"
        f'<worldbody><geom class="c{depth - 1}"/></worldbody></mujoco>'
    )


OPERATIONS: dict[str, Callable[[Mujoco], object]] = {
    "dumps and loads": lambda m: loads(dumps(m)) == m,
    "==": lambda m: m == loads(dumps(m)),
    "hash": lambda m: hash(m) == hash(loads(dumps(m))),
    "dicts": lambda m: from_dict(to_dict(m)) == m,
    "ElementTree": lambda m: from_etree(to_etree(m)) == m,
    "prefixed": lambda m: len(dumps(prefixed(m, "p_"))) > 0,
    "scaled": lambda m: len(dumps(scaled(m, 2.0))) > 0,
    "repr": lambda m: full_repr(m).count("Body(") >= 495 or full_repr(m).count("Default(") >= 495,
    "deepcopy": lambda m: copy.deepcopy(m) == m,
}


@pytest.mark.parametrize("operation", sorted(OPERATIONS))
@pytest.mark.parametrize(
    ("text", "label"),
    [
        (_chain_text(MUJOCO_DEEPEST_BODY_CHAIN), "bodies as deep as MuJoCo reads"),
        (_default_chain_text(495), "default classes as deep as MuJoCo reads"),
        (_chain_text(5_000), "bodies ten times deeper"),
        (_default_chain_text(5_000), "default classes ten times deeper"),
    ],
    ids=["bodies-496", "defaults-495", "bodies-5000", "defaults-5000"],
)
def test_deep_trees_work_without_recursion_limits(text: str, label: str, operation: str) -> None:
    """Every operation works at MuJoCo's depth and beyond, with Python's default limit."""
    assert sys.getrecursionlimit() <= 1000 or label  # the default limit is what users have
    model = loads(text)
    assert OPERATIONS[operation](model) is not False


def test_mujoco_reads_the_deepest_chain_we_test() -> None:
    """The depth above is MuJoCo's own limit: one more level and it refuses the file."""
    _compiled(_chain_text(MUJOCO_DEEPEST_BODY_CHAIN))
    with pytest.raises(ValueError, match="DEPTH"):
        _compiled(_chain_text(MUJOCO_DEEPEST_BODY_CHAIN + 1))


def test_deep_default_chain_compiles_identically() -> None:
    """Default classes nested as deep as MuJoCo reads compile the same after a round trip."""
    _round_trips_like_mujoco(_default_chain_text(495))


# -- memory ----------------------------------------------------------------------------


def test_memory_stays_a_small_multiple_of_a_huge_attribute() -> None:
    """A 10 MB attribute of numbers: load peaks below 8x its size, dump below 12x.

    The floats themselves take 32 bytes per number (about 3.6x this text); the
    bound fails if the text is ever split into one string per number at once,
    which took the 50 MB case of the fuzzing campaign to 4.6 GB.
    """
    import tracemalloc

    count = 10_000_000 // 9
    text = (
        '<mujoco><custom><numeric name="n" data="' + "0.123456 " * count + '"/></custom></mujoco>'
    )
    tracemalloc.start()
    try:
        model = loads(text)
        _, load_peak = tracemalloc.get_traced_memory()
        tracemalloc.reset_peak()
        written = dumps(model)
        _, dump_peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert len(model.children[0].children[0].data) == count  # type: ignore[attr-defined]
    assert len(written) > len(text) * 0.9
    assert load_peak < 8 * len(text), load_peak / len(text)  # issue 26's bound
    assert dump_peak < 12 * len(text), dump_peak / len(text)
