"""Tests of ``mjcf_model.serializers.canonical``."""

from __future__ import annotations

from pathlib import Path

import pytest

from mjcf_model import (
    GenericElement,
    Mujoco,
)
from mjcf_model.serializers import dumps, from_dict, from_etree, load, loads, to_dict, to_etree
from tests.conftest import corpus_id, loading_corpus

# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


# -- nodes that cannot be written cannot be built --------------------------------------


@pytest.mark.parametrize("value", ["a\tb", "a\nb", "a\rb", "a\r\nb", " lead", "trail "])
def test_normalised_characters_come_back_unchanged(value: str) -> None:
    """Tabs and line breaks in names and text are written as references and read back."""
    model = Mujoco(
        children=[
            GenericElement(tag="future", attributes={"note": value}, text=f"x{value}x"),
        ]
    )
    model = Mujoco(model=value, children=model.children)
    again = loads(dumps(model))
    assert again.model == value
    assert again.children[0] == model.children[0]
    assert from_etree(to_etree(model)) == model


# -- Files keep their format: ``dumps(load(path))`` gives the file back, edits stay local. -----
#
# MuJoCo is the referee for every edit: the dumped text compiles exactly as the
# same edit made by hand in the source text.


CORPUS = loading_corpus()


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_canonical_form_ignores_layouts(path: Path) -> None:
    """``canonical=True`` writes a loaded model as the same model built without layouts."""
    model = load(path)
    built = from_dict(to_dict(model))
    assert built == model and hash(built) == hash(model)
    assert dumps(model, canonical=True) == dumps(built)
