"""The composition check (tests/support/composing.py) on real models and fixtures, by folder."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from tests.conftest import FIXTURES, compiling_corpus, corpus_id
from tests.support.composing import STAGES, compose_problems

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


#: Fixture robots that can be a loaded parent: not the gripper, whose inertiafromgeom="true"
#: ignores the explicit inertials that keep another model's masses (see the next test).
PARENTS = [path for path in FIXTURE_MODELS if path.parent.name != "gripper_degree"]


@pytest.mark.parametrize(
    ("parent", "child"),
    [(p, c) for p in PARENTS for c in FIXTURE_MODELS if p != c],
    ids=lambda path: path.parent.name,
)
def test_a_model_attached_into_a_loaded_parent_keeps_both(
    parent: Path, child: Path, tmp_path: Path
) -> None:
    """Into a parent loaded with its own folder and compiler, both keep every value."""
    outcome = compose_problems([child], tmp_path, parent=parent)
    assert outcome.passed == STAGES, outcome.problems


def test_a_parent_that_ignores_inertials_refuses_naming_the_setting(tmp_path: Path) -> None:
    """Under inertiafromgeom="true" the arm's explicit inertial cannot hold: refused by name."""
    gripper, arm = FIXTURE_MODELS[1], FIXTURE_MODELS[0]
    outcome = compose_problems([arm], tmp_path, parent=gripper)
    assert outcome.passed == ()
    assert "MjcfValueError" in outcome.problems[0]
    assert "inertiafromgeom" in outcome.problems[0]
