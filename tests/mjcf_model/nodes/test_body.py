"""Tests of ``mjcf_model.nodes.body``."""

from __future__ import annotations

from mjcf_model import (
    Body,
    Comment,
    FreeJoint,
    Geom,
    Joint,
    Site,
)

# -- Node behaviour: immutability, typed views, attribute order, generic elements, values. -----


def test_typed_views_follow_document_order() -> None:
    """``body.geoms``/``joints``/``sites``/``bodies`` list direct children in order."""
    inner = Body(name="inner")
    body = Body(
        name="b",
        children=[
            Geom(name="g1"),
            Comment(text=" x "),
            FreeJoint(name="free"),
            Site(name="s"),
            Geom(name="g2"),
            inner,
            Joint(name="j"),
        ],
    )
    assert [g.name for g in body.geoms] == ["g1", "g2"]
    assert [j.name for j in body.joints] == ["free", "j"]
    assert body.bodies == (inner,)
    assert [s.name for s in body.sites] == ["s"]
    assert len(body.elements) == 6
