r"""Fuzzing the reader and writer with mutated real files and mutated generated models.

Every case is a seed document after a few hypothesis-drawn mutations (see
``tests/support/fuzzing.py``): byte flips, inserts and deletes, truncation, element and
attribute deletion and duplication, number garbage in attribute values, deep
nesting of bodies and default classes, odd unicode and control characters in
names, lying or unknown encoding declarations, bare ``&`` and junk after the
root. The seeds are the real corpus files (the XML inside the installed
robosuite and dm_control wheels) and the text of models drawn by
:func:`mjcf_model.strategies.models`. Each case must hold three properties:

1. ``loads(data)`` returns a model or raises an ``MjcfError``; nothing else escapes.
2. A loaded model survives ``dumps``/``loads`` unchanged (``==`` and ``hash``
   agree) and writing it is idempotent; ``to_dict``/``from_dict`` (through
   JSON) and ``to_etree``/``from_etree`` raise nothing but ``MjcfError`` and,
   when they succeed, give the model back.
3. Whenever MuJoCo compiles the mutated text from a string, ``loads`` accepts it
   and MuJoCo compiles ``dumps`` of the loaded model to an identical ``MjModel``.
   Left out are only the inputs the behaviour guide says we refuse although MuJoCo
   reads them: characters XML 1.0 cannot carry, a DTD. Bytes that are not UTF-8 are
   in: MuJoCo is given the bytes, and the written text as bytes.

Every case runs under Python's default recursion limit (hypothesis raises it)
and a wall-clock limit (``SIGALRM``; 5 s, or ``MJCF_FUZZ_TIMEOUT`` seconds), so
a hang or a catastrophic backtrack fails the case instead of blocking CI.
``test_minimal_cases`` replays one small input for each kind of failure the
fuzzers have found, on every run.

The number of examples per test is the hypothesis profile's count of
``tests/conftest.py`` (``ci``: 100, ``dev``: 50). A long campaign sets
``MJCF_FUZZ_EXAMPLES``, runs the tests in parallel and varies the seed::

    MJCF_FUZZ_EXAMPLES=100000 .venv/bin/python -m pytest tests/test_fuzz.py \
        -q -n 4 -p no:cacheprovider --hypothesis-seed=$RANDOM

Hypothesis stores every failure it finds in ``.hypothesis/`` and replays it first
on the next run; ``--hypothesis-show-statistics`` shows the time per case. A
failure prints the seed, each mutation and the mutated bytes; add the bytes to
``MINIMAL_CASES`` in ``tests/support/fuzzing.py`` once it is understood.
"""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, given, note, settings

from tests.support.fuzzing import (
    MINIMAL_CASES,
    Mutant,
    Seed,
    check_case,
    corpus_seeds,
    deep_bodies,
    deep_defaults,
    garbage_token,
    garbage_value,
    generated_seeds,
    mujoco_compiles,
    mutants,
    small_seeds,
    string_compiling_seeds,
    time_limit,
)

#: Every fuzz test's settings: ``MJCF_FUZZ_EXAMPLES`` examples, or the profile's.
FUZZ = settings(
    max_examples=int(os.environ.get("MJCF_FUZZ_EXAMPLES", "0")) or settings().max_examples,
    deadline=None,
    suppress_health_check=[
        HealthCheck.too_slow,
        HealthCheck.data_too_large,
        HealthCheck.large_base_example,
    ],
)


def _run(mutant: Mutant) -> None:
    data = mutant.data
    note(repr(data) if len(data) <= 1200 else f"{data[:600]!r} ... {data[-600:]!r}")
    check_case(mutant)


@FUZZ
@given(mutants(corpus_seeds()))
def test_mutated_corpus_files(mutant: Mutant) -> None:
    """Mutated real files: only MjcfError escapes, and what MuJoCo compiles round-trips."""
    _run(mutant)


@FUZZ
@given(mutants(generated_seeds()))
def test_mutated_generated_models(mutant: Mutant) -> None:
    """Mutated generated models: only MjcfError escapes, and what MuJoCo compiles round-trips."""
    _run(mutant)


@FUZZ
@given(mutants(small_seeds(), mutations=(garbage_value, garbage_token), max_steps=2))
def test_number_garbage(mutant: Mutant) -> None:
    """Garbage in numeric attributes: refused cleanly, or read as MuJoCo reads it."""
    _run(mutant)


@FUZZ
@given(mutants(small_seeds(), mutations=(deep_bodies, deep_defaults), max_steps=2))
def test_deep_nesting(mutant: Mutant) -> None:
    """Up to 600 nested bodies, frames, unknown elements or default classes."""
    _run(mutant)


@pytest.mark.parametrize("seed", string_compiling_seeds(), ids=lambda seed: seed.label)
def test_unmutated_seeds_reach_the_referee(seed: Seed) -> None:
    """The referee is not vacuous: MuJoCo compiles every unmutated referee seed."""
    assert mujoco_compiles(seed.data) is not None
    check_case(Mutant(seed.label, (), seed.data))


def test_referee_seeds_exist() -> None:
    """Enough corpus files compile from a string for the referee to see real models."""
    assert len(string_compiling_seeds()) >= 10


def test_time_limit_turns_a_hang_into_a_failure() -> None:
    """A case that runs too long fails with a clear message instead of blocking."""
    with pytest.raises(AssertionError, match=r"case took longer than 0.2 s"), time_limit(0.2):
        while True:
            pass


@pytest.mark.parametrize("name", sorted(MINIMAL_CASES))
def test_minimal_cases(name: str) -> None:
    """One small input per kind of failure the fuzzers found: the three properties hold."""
    check_case(Mutant(name, (), MINIMAL_CASES[name]))
