"""The live ElementTree view: one tree for a model's whole life, edited in place.

The oracle: after any update the view's tree is the tree ``to_etree`` builds for the
new model (the same text), the elements of what did not change are the same objects,
and what other code added to the elements stays where the model does not change it.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from hypothesis import given, settings
from hypothesis import strategies as st

from mjcf_model import (
    Body,
    Comment,
    GenericElement,
    Geom,
    Mujoco,
    Site,
    prefixed,
    scaled,
    with_attributes,
)
from mjcf_model.serializers import to_etree
from mjcf_model.serializers.etree import from_etree
from mjcf_model.serializers.etree_view import (
    EtreeView,
    element_index,
    paired,
    shallow_node,
    write_back,
)
from mjcf_model.strategies import models
from mjcf_model.tree.paths import appended_at, replaced_at


def _text(element: ET.Element) -> str:
    return ET.tostring(element, encoding="unicode")


def test_a_changed_attribute_is_set_on_the_same_element_where_it_stands() -> None:
    """Attribute order is kept; a new attribute goes last; a removed one goes."""
    body = Body(name="arm", pos=(0, 0, 1), children=[Geom(name="g", size=[0.1])])
    view = EtreeView(body)
    root, geom = view.element, view.at((0,))
    changed = with_attributes(body, {"name": "forearm", "pos": None, "quat": (1, 0, 0, 0)})
    view.update(changed)
    assert view.element is root and view.at((0,)) is geom and view.node is changed
    assert list(root.attrib.items()) == [("name", "forearm"), ("quat", "1 0 0 0")]
    assert _text(root) == _text(to_etree(changed))


def test_children_that_come_and_go_keep_the_elements_of_the_others() -> None:
    """An appended child gets a new element, a removed one leaves, the others stay as they are."""
    body = Body(name="b", children=[Geom(name="a"), Geom(name="b"), Geom(name="c")])
    view = EtreeView(body)
    kept = [view.at((0,)), view.at((2,))]
    fewer = body.__class__(name="b", children=[body.children[0], body.children[2]])
    view.update(fewer)
    assert list(view.element) == kept
    more = appended_at(fewer, (), [Site(name="s")])
    view.update(more)
    assert list(view.element)[:2] == kept and view.element[2].tag == "site"
    assert _text(view.element) == _text(to_etree(more))


def test_edits_other_code_made_stay_unless_the_model_changes_them() -> None:
    """Robosuite's code sets attributes and appends children on the live elements."""
    body = Body(name="b", children=[Geom(name="g", size=[0.1])])
    view = EtreeView(body)
    view.element.set("user", "mine")
    view.at((0,)).set("rgba", "1 0 0 1")
    ET.SubElement(view.element, "site", {"name": "theirs"})
    changed = replaced_at(body, (0,), [with_attributes(body.children[0], {"size": (0.2,)})])
    view.update(with_attributes(changed, {"name": "c"}))
    assert view.element.get("user") == "mine" and view.element.get("name") == "c"
    assert view.at((0,)).get("rgba") == "1 0 0 1" and view.at((0,)).get("size") == "0.2"
    assert [child.get("name") for child in view.element] == ["g", "theirs"]


def test_write_back_edits_an_element_built_elsewhere() -> None:
    """A view over an element it did not build (robosuite's) edits that element."""
    element = ET.fromstring('<body name="b"><geom name="g" size="0.1"/></body>')
    geom = element[0]
    old = Body(name="b", children=[Geom(name="g", size=[0.1])])
    write_back(element, old, prefixed(old, "p_"))
    assert element[0] is geom and (element.get("name"), geom.get("name")) == ("p_b", "p_g")


@settings(deadline=None)
@given(models(max_trees=2), st.sampled_from(["prefix", "scale", "append"]))
def test_after_any_update_the_view_is_the_tree_of_the_new_model(model: Mujoco, change: str) -> None:
    """Prefixed, scaled or grown: the live tree writes as the new model's own tree."""
    view = EtreeView(model)
    root = view.element
    if change == "prefix":
        new = prefixed(model, "p_")
    elif change == "scale":
        new = scaled(model, 2.0)
    else:
        world = next(
            i for i, c in enumerate(model.children) if getattr(c, "tag", "") == "worldbody"
        )
        new = appended_at(model, (world,), [Site(name="added_site_x")])
    view.update(new)
    assert view.element is root
    assert _text(view.element) == _text(to_etree(new))


@given(models())
def test_paired_matches_every_node_with_the_element_it_came_from(model: Mujoco) -> None:
    """Each pair is an element and the node made from it: same tag, same attribute text."""
    element = to_etree(model)
    element.insert(0, ET.Comment(" a note "))
    node = from_etree(element, typed=False)
    pairs = list(paired(element, node))
    assert [e for e, _ in pairs] == list(element.iter())
    for live, made in pairs:
        if live.tag is ET.Comment:  # type: ignore[comparison-overlap]
            assert isinstance(made, Comment) and made.text == live.text
        else:
            assert isinstance(made, GenericElement)
            assert (made.tag, dict(made.attributes)) == (live.tag, live.attrib)
    index = element_index(element, node)
    assert all(index[id(made)] is live for live, made in pairs)


def test_shallow_node_keeps_the_attribute_text_and_drops_the_children() -> None:
    """The element alone: exact attribute text, no children; a comment stays a comment."""
    element = ET.fromstring('<geom size="0.10" pos="0  0 1"><x/></geom>')
    node = shallow_node(element)
    assert _text(to_etree(node)) == '<geom size="0.10" pos="0  0 1" />'
    assert _text(to_etree(shallow_node(ET.Comment(" c ")))) == "<!-- c -->"
