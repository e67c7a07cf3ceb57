"""Tests of ``mjcf_model.nodes.file_layout``: what a node asks of the layout it keeps."""

from __future__ import annotations

import pickle

from mjcf_model import Body, Geom, loads, with_attributes
from mjcf_model.nodes.file_layout import FileLayout
from mjcf_model.serializers.layout import Layout, SourceText

TEXT = (
    "<mujoco>\n  <worldbody>\n"
    + "".join(f'    <geom name="g{i}" size="0.1"/>\n' for i in range(25))
    + "  </worldbody>\n</mujoco>\n"
)


def test_the_serializers_layout_is_a_file_layout() -> None:
    """The layout the reader gives every element is what the protocol describes."""
    model = loads(TEXT, filename="scene.xml")
    assert isinstance(model.layout, Layout) and isinstance(model.layout, FileLayout)
    assert model.worldbody.geoms[3].layout.where() == ("scene.xml", 6)  # line 3 holds g0  # type: ignore[union-attr]
    assert repr(model.worldbody) == "<Worldbody: 26 elements from 'scene.xml', line 2>"


def test_a_loaded_element_pickles_as_its_layout_says() -> None:
    """A loaded element pickles through its layout, and an edit since reading survives it."""
    geom = loads(TEXT).worldbody.geoms[0]
    layout = geom.layout
    assert layout is not None and layout.reduced(geom) is not None
    edited = with_attributes(geom, name="renamed")
    copy = pickle.loads(pickle.dumps(edited))
    assert copy == edited and copy.name == "renamed" and isinstance(copy.layout, Layout)


def test_a_text_without_a_reader_pickles_field_by_field() -> None:
    """A layout over a text no reader gave a way to reduce: the element pickles as any other."""
    origin = SourceText(b'<geom size="1"/>')
    geom = Geom(size=[1.0], layout=Layout(origin, "geom", 0, 16, 16, ("size", "1"), (), None))
    assert geom.layout is not None and geom.layout.reduced(geom) is None
    assert pickle.loads(pickle.dumps(geom)) == geom


def test_a_new_parent_keeps_no_replaced_child_alive() -> None:
    """Replacing an element's children gives it a layout that holds no replaced child."""
    body = loads('<mujoco><worldbody><body><geom size="1"/></body></worldbody></mujoco>')
    old = body.worldbody.bodies[0]
    new = Body(children=[Geom(size=[2.0])], layout=old.layout)
    layout = old.layout
    assert layout is not None
    kept = layout.without_old_children(new.children)
    assert isinstance(kept, Layout) and old.children[0] not in kept.children


def test_an_unpickled_element_pickles_small_again() -> None:
    """The reader's way of pickling is not pickled with the text, and comes back with it."""
    geom = loads(TEXT).worldbody.geoms[0]
    once = pickle.dumps(geom)
    copy = pickle.loads(once)
    assert len(pickle.dumps(copy)) == len(once)
    assert copy.layout is not None and copy.layout.reduced(copy) is not None
