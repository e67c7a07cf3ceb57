"""A pickled subtree carries its own text, not its file's, and keeps its format.

Work sent to worker processes is pickled: a geom taken from a 21 KB robot file
used to carry the whole file with it. The referee for the format is the writer
on the original: the unpickled copy writes the same text, before and after an
edit, and names the same lines.
"""

from __future__ import annotations

import gc
import pickle
import weakref
from collections.abc import Callable
from pathlib import Path

import pytest

from mjcf_model import Body, Element, Geom, map_elements, prefixed, scaled, walk
from mjcf_model.nodes.base import AnyElement, with_attributes
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.serializers.layout import Layout
from mjcf_model.tree.traversal import map_tree, with_children
from tests.conftest import compiling_corpus, corpus_id, loading_corpus


def _copy(node: AnyElement) -> AnyElement:
    copied = pickle.loads(pickle.dumps(node))
    assert isinstance(copied, Element)
    return copied  # type: ignore[return-value]


def _text_carried(layout: Layout) -> int:
    origin = layout.origin
    return len(origin.raw or origin.text)


def _own_text(layout: Layout) -> int:
    return layout.after - layout.begin


@pytest.mark.parametrize("path", loading_corpus(), ids=corpus_id)
def test_every_corpus_element_pickles_with_its_own_text_and_writes_the_same(path: Path) -> None:
    """Each element of each file: equal copy, same text written, same lines, own text only."""
    model = load(path)
    for _, element in walk(model):
        layout = element.layout
        if layout is None:
            continue
        copied = _copy(element)
        assert copied == element
        assert dumps(copied) == dumps(element)
        kept = copied.layout
        assert kept is not None
        if element is model:
            assert _text_carried(kept) == _text_carried(layout)  # the file around the root
        else:
            assert _text_carried(kept) == _own_text(layout)
        for (_, before), (_, after) in zip(walk(element), walk(copied), strict=True):
            if before.layout is not None and before.layout.origin is layout.origin:
                assert after.layout is not None
                assert after.layout.origin.line(after.layout.begin) == layout.origin.line(
                    before.layout.begin
                )
                assert after.layout.origin.filename == layout.origin.filename


@pytest.mark.parametrize("path", loading_corpus(), ids=corpus_id)
def test_a_corpus_element_without_children_pickles_to_a_few_hundred_bytes(path: Path) -> None:
    """Issue 26's bound for a subtree: at most twice its own text plus 1 KiB."""
    for _, element in walk(load(path)):
        layout = element.layout
        if layout is not None and not element.children:
            assert len(pickle.dumps(element)) <= 2 * _own_text(layout) + 1024


@pytest.mark.parametrize("path", compiling_corpus()[::4], ids=corpus_id)
def test_an_unpickled_model_prefixes_to_the_same_text(path: Path) -> None:
    """The format survives pickling for an edit too: every element changed by prefixing."""
    model = load(path, inline_includes=True)
    assert dumps(prefixed(_copy(model), "p/")) == dumps(prefixed(model, "p/"))


def _unnamed_and_red(element: AnyElement, key: str | None, _: object) -> AnyElement:
    if isinstance(element, Geom):
        return with_attributes(element, {"name": None, "rgba": (1.0, 0.0, 0.0, 1.0)})
    return element


_EDITS = {
    "prefixed": lambda model: prefixed(model, "p/"),
    "scaled": lambda model: scaled(model, 1.3, mass="volume"),
    "geoms unnamed and red": lambda model: map_elements(_unnamed_and_red, model),
}


@pytest.mark.parametrize("edit", _EDITS.values(), ids=_EDITS.keys())
@pytest.mark.parametrize("path", compiling_corpus()[1::6], ids=corpus_id)
def test_an_edited_model_pickles_to_an_equal_one_that_writes_the_same(
    path: Path, edit: Callable[[AnyElement], AnyElement]
) -> None:
    """Values changed, added and removed since reading survive the pickle read again."""
    edited = edit(load(path, inline_includes=True))
    copied = _copy(edited)
    assert copied == edited and dumps(copied) == dumps(edited)
    for (_, before), (_, after) in zip(walk(edited), walk(copied), strict=True):
        assert before.__dict__.keys() - {"layout"} == after.__dict__.keys() - {"layout"}


_SPACED = """<mujoco model="spaced">
  <worldbody>

    <!-- the base, with a blank line above -->
    <body name="base">
      <geom name="ä" size="0.1"/>


      <geom name="second"   size="0.2"/>
      <body name="arm">
        <geom name="tip" size="0.05"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def _without_second(node: object) -> object:
    if isinstance(node, Body) and node.name == "base":
        kept = [child for child in node.children if getattr(child, "name", "") != "second"]
        return with_children(node, kept)
    return node


def _renamed_tip(node: object) -> object:
    if isinstance(node, Geom) and node.name == "tip":
        return Geom(name="end", size=node.size, layout=node.layout)
    return node


def test_an_edited_subtree_pickled_and_edited_again_keeps_its_gaps() -> None:
    """Removing a child after a first edit and a pickle keeps blank lines and comments."""
    model = loads(_SPACED)
    base = model.worldbody.bodies[0]
    edited = map_tree(_renamed_tip, base)
    expected = dumps(map_tree(_without_second, edited))
    assert "<!-- the base" not in expected and '<geom name="end"' in expected
    assert '<geom name="ä" size="0.1"/>\n\n\n      <body name="arm">' in expected
    again = map_tree(_without_second, _copy(edited))  # type: ignore[arg-type]
    assert dumps(again) == expected


def test_a_non_ascii_file_pickles_a_subtree_with_byte_offsets() -> None:
    """Offsets are byte offsets: a piece of a UTF-8 file still writes and counts lines right."""
    model = loads(_SPACED)
    arm = model.worldbody.bodies[0].bodies[0]
    copied = _copy(arm)
    assert (
        dumps(copied)
        == dumps(arm)
        == ('<body name="arm">\n        <geom name="tip" size="0.05"/>\n      </body>\n')
    )
    assert copied.layout is not None and copied.layout.origin.line(copied.layout.begin) == 10


def test_a_transformed_model_does_not_keep_the_nodes_it_replaced() -> None:
    """A layout keeps of the children an element was read with only what the writer needs."""
    model = loads(_SPACED)
    old_tip = weakref.ref(model.worldbody.bodies[0].bodies[0].geoms[0])
    renamed = map_tree(_renamed_tip, model)
    del model
    gc.collect()
    assert old_tip() is None
    assert '<geom name="end" size="0.05"/>' in dumps(renamed)
