"""Tests of ``mjcf_model.tree.traversal``."""

from __future__ import annotations

from mjcf_model import Body, Comment, Geom
from mjcf_model.tree import traversal
from mjcf_model.tree.queries import walk

# -- Queries: find, find_all, parent_of and categorized, checked against robosuite's mjcf_utils.


def test_walk_is_the_traversal_walk() -> None:
    """``queries.walk`` is re-exported from traversal."""
    assert walk is traversal.walk
    assert [e.tag for _, e in walk(Body(children=[Geom()]))] == ["body", "geom"]


def test_walk_nodes_yields_comments_with_parents_and_paths_in_document_order() -> None:
    """Every node (comments too), its parent and its path, as ``walk`` orders elements."""
    inner = Body(name="in", children=[Geom(name="g")])
    note = Comment(text="c")
    root = Body(name="out", children=[note, inner])
    seen = [(parent, node, path) for parent, node, path in traversal.walk_nodes(root)]
    geom = inner.children[0]
    assert seen == [
        (None, root, ()),
        (root, note, (0,)),
        (root, inner, (1,)),
        (inner, geom, (1, 0)),
    ]
    elements = [(path, node) for _, node, path in seen if not isinstance(node, Comment)]
    assert elements == list(traversal.walk(root))
