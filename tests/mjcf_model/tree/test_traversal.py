"""Tests of ``mjcf_model.tree.traversal``."""

from __future__ import annotations

from mjcf_model import Body, Geom
from mjcf_model.tree import traversal
from mjcf_model.tree.queries import walk

# -- Queries: find, find_all, parent_of and categorized, checked against robosuite's mjcf_utils.


def test_walk_is_the_traversal_walk() -> None:
    """``queries.walk`` is re-exported from traversal."""
    assert walk is traversal.walk
    assert [e.tag for _, e in walk(Body(children=[Geom()]))] == ["body", "geom"]
