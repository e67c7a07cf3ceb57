"""The composition check (tests/composing.py) on real models and fixtures, folder by folder."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from tests.composing import STAGES, compose_problems
from tests.conftest import FIXTURES, compiling_corpus, corpus_id

#: Fixture robots, each in a folder of its own with its own meshes and <compiler>.
FIXTURE_MODELS = [
    FIXTURES / "compose" / "arm_radian" / "arm.xml",
    FIXTURES / "compose" / "gripper_degree" / "gripper.xml",
    FIXTURES / "compose" / "walker_limits" / "walker.xml",
    FIXTURES / "compose" / "prop_include" / "prop.xml",
]
#: How many corpus pairs are checked.
CORPUS_PAIRS = 40


def _corpus_pairs() -> list[tuple[Path, Path]]:
    """Deterministic pairs of corpus models from different folders (every model is used)."""
    corpus = compiling_corpus()
    pairs = []
    step = 37  # co-prime to the corpus size, so the partners spread over it
    for index, first in enumerate(corpus):
        second = corpus[(index * step + 11) % len(corpus)]
        if first.parent != second.parent:
            pairs.append((first, second))
    return pairs[:: max(1, len(pairs) // CORPUS_PAIRS)][:CORPUS_PAIRS]


PAIRS = list(itertools.permutations(FIXTURE_MODELS, 2)) + _corpus_pairs()


def _pair_id(pair: tuple[Path, Path]) -> str:
    return " + ".join(corpus_id(path) for path in pair)


def test_the_check_covers_enough_pairs() -> None:
    """Every ordered pair of fixtures and 40 corpus pairs from different folders are checked."""
    assert len(PAIRS) == 12 + CORPUS_PAIRS
    assert all(a.parent != b.parent for a, b in PAIRS)


@pytest.mark.parametrize("pair", PAIRS, ids=[_pair_id(p) for p in PAIRS])
def test_two_models_from_different_folders_compose(pair: tuple[Path, Path], tmp_path: Path) -> None:
    """The scene compiles with every object's values, dumps elsewhere and exports, identically."""
    outcome = compose_problems(list(pair), tmp_path)
    assert outcome.passed == STAGES, outcome.problems
