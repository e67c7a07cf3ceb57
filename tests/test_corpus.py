"""Every compiling XML file of the installed robosuite and dm_control wheels round-trips."""

from __future__ import annotations

from pathlib import Path

import pytest

from mjcf_model import Comment, Include, Node
from mjcf_model.nodes.base import Element
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.tools.check import check_file
from tests.conftest import compiling_corpus, corpus_files, corpus_id

CORPUS = compiling_corpus()


def _walk(node: Node) -> list[Node]:
    found = [node]
    if isinstance(node, Element):
        for child in node.children:
            found.extend(_walk(child))
    return found


def test_corpus_is_the_real_one() -> None:
    """The corpus is found through the installed packages and most of it compiles."""
    assert len(corpus_files()) >= 100
    assert len(CORPUS) >= 100


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_round_trip_compiles_identically(path: Path) -> None:
    """Load, write and compile: every MjModel field equals the original's (includes kept)."""
    result = check_file(path)
    assert result.status == "identical", (result.differences, result.message)


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_round_trip_with_inlined_includes(path: Path) -> None:
    """With includes inlined the written model still compiles identically."""
    result = check_file(path, inline_includes=True)
    assert result.status == "identical", (result.differences, result.message)
    assert not any(isinstance(n, Include) for n in _walk(load(path, inline_includes=True)))


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_text_is_idempotent_and_comments_survive(path: Path) -> None:
    """Writing is idempotent, the tree survives re-reading, and every comment is kept."""
    model = load(path)
    text = dumps(model)
    assert loads(text) == model
    assert dumps(loads(text)) == text
    source = path.read_text(encoding="utf-8")
    comments = [n for n in _walk(model) if isinstance(n, Comment)]
    assert len(comments) == source.count("<!--")
    for comment in comments:
        assert f"<!--{comment.text}-->" in text
