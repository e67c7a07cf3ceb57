"""Stray text between elements (mixed content, which MuJoCo ignores) survives changed children.

An element whose children change (an ``<include>`` inlined, a child removed) is
written with all its text: read back, the model is equal to the one written,
and MuJoCo compiles the written text as it compiles the original file.
"""

from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import escape

import mujoco
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import Geom, Mujoco
from mjcf_model.bridge.compare import compile_text_beside, model_differences
from mjcf_model.nodes.base import AnyElement, Node
from mjcf_model.tree.traversal import map_tree, with_children
from serializers import dumps, load, loads

#: The included file: a world with one geom.
PART = '<mujoco><worldbody><geom name="part" size="1"/></worldbody></mujoco>\n'


def _round_trip(main: Path) -> None:
    """Assert the inlined model reads back equal and compiles as MuJoCo compiles ``main``."""
    model = load(main, inline_includes=True)
    written = dumps(model)
    assert "<include" not in written
    assert loads(written, base_dir=main.parent) == model
    expected = mujoco.MjModel.from_xml_path(str(main))
    assert model_differences(expected, compile_text_beside(written, main)) == []


@pytest.mark.parametrize(
    "root",
    [
        'stray<include file="part.xml"/>tail',
        'stray<include file="part.xml"/>',
        '<include file="part.xml"/>tail',
        '<option/>x<include file="part.xml"/>y<size/>z',
        '\n  a &amp; b\n  <include file="part.xml"/>\n  &lt;c&gt;\n',
    ],
)
def test_stray_text_around_an_inlined_include(tmp_path: Path, root: str) -> None:
    """The root's text before, between and after an inlined include is all written."""
    (tmp_path / "part.xml").write_text(PART)
    main = tmp_path / "main.xml"
    main.write_text(f"<mujoco>{root}</mujoco>\n")
    _round_trip(main)


def test_stray_text_beside_a_removed_child() -> None:
    """Removing a child keeps the text that stood before it."""
    model = loads(
        '<mujoco><worldbody>a<geom size="1"/>b<geom name="x" size="1"/>c</worldbody></mujoco>'
    )

    def without_x(node: Node) -> Node:
        if not isinstance(node, AnyElement):
            return node
        return with_children(node, [c for c in node.children if getattr(c, "name", None) != "x"])

    removed = map_tree(without_x, model)
    assert isinstance(removed, Mujoco) and removed.worldbody is not None
    assert removed.worldbody.text == "a b c"
    again = loads(dumps(removed))
    assert again == removed and again.worldbody is not None
    assert [type(c) for c in again.worldbody.children] == [Geom]


stray = st.text(alphabet="ab &<>\n ", max_size=4).map(escape)


@given(
    texts=st.lists(stray, min_size=4, max_size=4),
    inside=st.booleans(),
)
def test_stray_text_anywhere_around_inlined_includes(
    tmp_path_factory: pytest.TempPathFactory, texts: list[str], inside: bool
) -> None:
    """Any stray text around an include, at the root or in the world, round-trips inlined."""
    folder = tmp_path_factory.mktemp("stray")
    part = PART if not inside else '<mujoco><geom name="part" size="1"/></mujoco>\n'
    (folder / "part.xml").write_text(part)
    include = '<include file="part.xml"/>'
    if inside:
        body = f'<worldbody>{texts[0]}<geom size="1"/>{texts[1]}{include}{texts[2]}</worldbody>'
        root = f"{body}{texts[3]}"
    else:
        root = f"{texts[0]}<option/>{texts[1]}{include}{texts[2]}<size/>{texts[3]}"
    main = folder / "main.xml"
    main.write_text(f"<mujoco>{root}</mujoco>\n")
    _round_trip(main)
