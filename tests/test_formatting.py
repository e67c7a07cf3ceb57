"""``fmt``'s library: every real file's canonical form is proven and stable."""

from __future__ import annotations

from pathlib import Path

import pytest

from mjcf_model.tools.formatting import format_file, format_text
from tests.conftest import compiling_corpus, corpus_id, loading_corpus

COMPILING = set(compiling_corpus())


@pytest.mark.parametrize("path", loading_corpus(), ids=corpus_id)
def test_corpus_canonical_form_is_proven_and_stable(path: Path) -> None:
    """Each corpus file's rewrite is proven unchanged, and formatting it again does nothing.

    Proven: it compiles to the same model, or, for files MuJoCo rejects alone,
    reads to the same elements.
    """
    result = format_file(path)
    assert result.safe, result.differences
    proofs = ("compiled", "unchanged") if path in COMPILING else ("elements", "unchanged")
    assert result.proof in proofs
    again = format_text(result.text, filename=str(path))
    assert not again.changed and again.safe


def test_text_without_a_file_compiles_from_memory() -> None:
    """Text given alone is checked by compiling it; the canonical text is MuJoCo-equivalent."""
    result = format_text("<mujoco><worldbody><geom size='.5' type='sphere'/></worldbody></mujoco>")
    assert (result.proof, result.safe) == ("compiled", True)
    assert '<geom size=".5" type="sphere"/>' in result.text  # the number as written


def test_fragment_is_compared_element_by_element() -> None:
    """A part MuJoCo rejects on its own (its includer's material) is proven by its elements."""
    result = format_text("<mujoco><worldbody><geom  size='1' material='m'/></worldbody></mujoco>")
    assert result.proof == "elements" and result.safe and result.changed
