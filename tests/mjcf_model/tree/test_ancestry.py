"""Tests of ``mjcf_model.tree.ancestry``: the ancestors the tree walks hand to visitors."""

from __future__ import annotations

import sys
from typing import Any

from mjcf_model import Body
from mjcf_model.nodes.base import AnyElement
from mjcf_model.tree.ancestry import Ancestors, fold_ancestors


def _chain(names: list[str]) -> list[Ancestors]:
    levels = [Ancestors()]
    for name in names:
        levels.append(levels[-1].extended(Body(name=name, childclass=name.upper())))
    return levels


def test_each_level_is_its_parents_ancestors_and_one_more_root_first() -> None:
    """A level reads as the tuple of bodies from the root; earlier levels are unchanged."""
    levels = _chain(["root", "arm", "hand"])
    assert [len(level) for level in levels] == [0, 1, 2, 3]
    hand = levels[-1]
    assert [body.name for body in hand] == ["root", "arm", "hand"]
    assert [body.name for body in reversed(hand)] == ["hand", "arm", "root"]
    assert hand[-1].name == "hand" and hand[0].name == "root"
    assert [b.name for b in hand[1:]] == ["arm", "hand"]
    assert hand == tuple(hand.as_tuple()) and hash(hand) == hash(hand.as_tuple())
    assert [body.name for body in levels[1]] == ["root"]
    assert levels[0] == () and list(levels[0]) == []


def test_a_fold_runs_once_per_level_and_equals_a_plain_fold() -> None:
    """Folding a deeper level reuses what shallower levels folded; any sequence folds alike."""
    calls: list[str] = []

    def childclass(inherited: Any, element: AnyElement) -> Any:
        calls.append(element.name)  # type: ignore[attr-defined]
        return element.childclass or inherited  # type: ignore[attr-defined]

    levels = _chain(["a", "b", "c"])
    assert levels[2].folded(childclass, None) == "B"
    assert calls == ["a", "b"]
    assert levels[3].folded(childclass, None) == "C"
    assert calls == ["a", "b", "c"]  # only the new level
    assert levels[3].folded(childclass, None) == "C" and calls == ["a", "b", "c"]
    plain = [Body(childclass="x"), Body(), Body()]
    assert fold_ancestors(plain, lambda i, e: e.childclass or i, None) == "x"  # type: ignore[attr-defined]


def test_a_chain_deeper_than_the_recursion_limit_is_walked_without_recursion() -> None:
    """Iterating, reversing and folding stay iterative however deep the chain."""
    level = Ancestors()
    depth = sys.getrecursionlimit() + 100
    for index in range(depth):
        level = level.extended(Body(name=str(index)))
    assert len(level) == depth and level[0].name == "0"
    assert level.folded(lambda count, _: count + 1, 0) == depth
