"""Tests of ``mjcf_model.tree.paths``: editing a tree at the paths ``walk`` gives."""

from __future__ import annotations

import pytest

from mjcf_model import Body, Comment, Geom, Site
from mjcf_model.errors import MjcfValueError
from mjcf_model.serializers import dumps, loads
from mjcf_model.tree.paths import appended_at, edited_at, replaced_at, subtree_at
from mjcf_model.tree.traversal import walk

#: Two arms with a comment between them, the second with a hand.
MODEL = loads(
    """<mujoco><worldbody>
      <body name="left"><geom name="l" size="0.1"/></body>
      <!-- the right arm -->
      <body name="right"><geom name="r" size="0.1"/><body name="hand"><site name="s"/></body></body>
    </worldbody></mujoco>"""
)


def test_every_path_walk_gives_leads_to_its_element() -> None:
    """``subtree_at`` follows child indexes; a path through a comment is refused."""
    for path, element in walk(MODEL):
        assert subtree_at(MODEL, path) is element
    with pytest.raises(MjcfValueError):
        subtree_at(MODEL, (0, 1))  # the comment


def test_replacing_rebuilds_only_the_path() -> None:
    """The element at the path becomes the new nodes (or none); the rest is shared."""
    right = MODEL.worldbody.children[2]
    swapped = replaced_at(MODEL, (0, 2, 1), [Site(name="a"), Site(name="b")])
    new_right = swapped.worldbody.children[2]
    assert [type(c).__name__ for c in new_right.children] == ["Geom", "Site", "Site"]
    assert new_right.children[0] is right.children[0]
    assert swapped.worldbody.children[0] is MODEL.worldbody.children[0]
    assert isinstance(swapped.worldbody.children[1], Comment)
    removed = replaced_at(MODEL, (0, 0), [])
    assert [b.name for b in removed.worldbody.bodies] == ["right"]


def test_appending_and_editing_change_only_their_paths() -> None:
    """Appended children go last; edits apply by path, ``None`` removing an attribute."""
    grown = appended_at(MODEL, (0, 0), [Geom(name="extra", size=(0.2,))])
    assert [g.name for g in grown.worldbody.bodies[0].geoms] == ["l", "extra"]
    edited = edited_at(MODEL, {(0, 0): {"name": "LEFT"}, (0, 2, 0): {"size": None}, (0, 1): {}})
    assert [b.name for b in edited.worldbody.bodies] == ["LEFT", "right"]
    assert edited.worldbody.bodies[1].geoms[0].size is None
    assert edited.worldbody.bodies[1].bodies[0] is MODEL.worldbody.bodies[1].bodies[0]
    assert "<!-- the right arm -->" in dumps(edited)
    assert edited_at(Body(name="x"), {}) == Body(name="x")


def test_replacing_the_root_gives_the_new_root_or_says_why_not() -> None:
    """The empty path is the root: one node of its class replaces it; anything else is refused."""
    body, other = Body(name="a"), Body(name="b", children=[Geom(name="g")])
    assert replaced_at(body, (), [other]) is other
    for wrong in ([], [other, other], [Geom(name="g")]):
        with pytest.raises(MjcfValueError, match="root Body can only be replaced"):
            replaced_at(body, (), wrong)
