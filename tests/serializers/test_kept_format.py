"""Tests of ``mjcf_model.serializers.kept_format``."""

from __future__ import annotations

import difflib
import json
import pickle
import re
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path
from xml.sax.saxutils import escape

import mujoco
import pytest
from hypothesis import given
from hypothesis import strategies as st

from mjcf_model import Body, Geom, Mujoco, Site, prefixed, scaled
from mjcf_model.bridge.compare import compile_text_beside, model_differences, path_fields
from mjcf_model.nodes.base import (
    AnyElement,
    Node,
    attribute_items,
    build_node,
    get_attribute,
    with_attributes,
)
from mjcf_model.serializers import dump, dumps, from_dict, load, loads, to_dict, to_etree
from mjcf_model.strategies import models
from mjcf_model.tree.traversal import map_tree, with_children
from mjcf_model.values import Value
from tests.conftest import compiling_corpus, corpus_id, loading_corpus

# -- Files keep their format: ``dumps(load(path))`` gives the file back, edits stay local. -----
#
# MuJoCo is the referee for every edit: the dumped text compiles exactly as the
# same edit made by hand in the source text.


CORPUS = loading_corpus()
CARTPOLE = "dm_control/suite/cartpole.xml"
ARM = "dm_control/mujoco/testing/assets/arm.xml"
IIWA = "robosuite/models/assets/robots/iiwa/robot.xml"

#: Small files written the ways people write MJCF; each has a body "b" holding a geom "g".
FORMATS = {
    "crlf": (
        '<?xml version="1.0"?>\r\n<mujoco model="crlf">\r\n  <worldbody>\r\n'
        "    <!-- two\r\n         lines -->\r\n"
        '    <body name="b">\r\n      <geom name="g" size="0.1"/>\r\n    </body>\r\n'
        "  </worldbody>\r\n</mujoco>\r\n"
    ),
    "tabs": (
        '<mujoco>\n\t<worldbody>\n\t\t<body name="b">\n\t\t\t<geom name="g" size="0.1"/>\n'
        "\t\t</body>\n\t</worldbody>\n</mujoco>\n"
    ),
    "single quotes": (
        "<mujoco model='q'>\n  <worldbody>\n    <body name='b'>\n"
        "      <geom name='g' size='0.1' rgba='1 0 0 1'/>\n    </body>\n  </worldbody>\n</mujoco>\n"
    ),
    "wrapped attributes": (
        '<mujoco>\n  <worldbody>\n    <body name="b"\n          pos="0 0 1">\n'
        '      <geom name="g" type="box"\n            size="0.1 0.2 0.3"\n'
        '            rgba="1 0 0 1" />\n    </body>\n  </worldbody>\n</mujoco>'
    ),
    "declaration and comments": (
        '\ufeff<?xml version="1.0" encoding="utf-8"?>\n<!-- before -->\n\n<mujoco>\n'
        "  <!-- inside -->\n  <worldbody>\n\n\n"
        '    <body name="b">\n        <geom name="g" size="1e-1"/>  <!-- same line -->\n'
        "    </body>\n  </worldbody>\n</mujoco>\n<!-- after -->\n\n"
    ),
    "utf-8": (
        '<mujoco model="caf\u00e9">\n  <!-- \u2603 -->\n  <worldbody>\n'
        '    <body name="b" pos="0 0 1">\n      <geom name="g" size="0.1"/>\n'
        "    </body>\n  </worldbody>\n</mujoco>\n"
    ),
    "references": (
        '<mujoco model="a &amp; b">\n  <custom>\n'
        '    <text name="t" data="x &lt; y &quot;z&quot; &#65;&#x42; &#9;tab"/>\n  </custom>\n'
        '  <worldbody>\n    <body name="b&#46;1">\n      <geom name="g&#x30;" size="0.1"/>\n'
        '    </body>\n    <body name="b">\n      <geom name="g" size="0.1"/>\n    </body>\n'
        "  </worldbody>\n</mujoco>\n"
    ),
}


def _package_file(relative: str) -> Path:
    """The corpus file whose path ends with ``relative``."""
    found = [p for p in CORPUS if p.as_posix().endswith(relative)]
    assert len(found) == 1, relative
    return found[0]


def _changed_lines(before: str, after: str) -> list[str]:
    """The ``-`` and ``+`` lines of the unified diff between two texts."""
    diff = difflib.unified_diff(before.splitlines(True), after.splitlines(True), n=0)
    return [line for line in diff if line[:1] in "+-" and line[:3] not in ("---", "+++")]


def _edit(model: Mujoco, tag: str, name: str, change: Callable[[AnyElement], Node]) -> Mujoco:
    """``model`` with its one element ``<tag name=...>`` replaced by ``change(element)``."""
    found: list[AnyElement] = []

    def visit(node: Node) -> Node:
        if isinstance(node, AnyElement) and node.tag == tag and get_attribute(node, "name") == name:
            found.append(node)
            return change(node)
        return node

    edited = map_tree(visit, model)
    assert len(found) == 1 and isinstance(edited, Mujoco)
    return edited


def _start_tag(text: str, tag: str, name: str) -> re.Match[str]:
    """The start tag ``<tag ... name="name" ...>`` in source text (either quote)."""
    found = re.search(rf"<{tag}\b[^>]*?\bname=(['\"]){re.escape(name)}\1[^>]*>", text)
    assert found is not None
    return found


def _hand_edited(text: str, tag: str, name: str, attribute: str, value: str | None) -> str:
    """``text`` with one attribute of one start tag replaced, removed or added, by hand."""
    tag_match = _start_tag(text, tag, name)
    start = tag_match.group(0)
    current = re.search(rf"(\s+){attribute}=(['\"])[^'\"]*\2", start)
    if value is None:
        assert current is not None
        start = start[: current.start()] + start[current.end() :]
    elif current is not None:
        quote = current.group(2)
        new = f"{current.group(1)}{attribute}={quote}{value}{quote}"
        start = start[: current.start()] + new + start[current.end() :]
    else:
        last_quote = max(start.rfind('"'), start.rfind("'"))
        start = start[: last_quote + 1] + f' {attribute}="{value}"' + start[last_quote + 1 :]
    return text[: tag_match.start()] + start + text[tag_match.end() :]


def _same_compiled(text: str, by_hand: str, path: Path | None = None) -> list[str]:
    """Where MuJoCo's models of two texts differ (compiled beside ``path`` when given)."""
    if path is None:
        return model_differences(
            mujoco.MjModel.from_xml_string(text), mujoco.MjModel.from_xml_string(by_hand)
        )
    return model_differences(compile_text_beside(text, path), compile_text_beside(by_hand, path))


@pytest.mark.parametrize("path", CORPUS, ids=corpus_id)
def test_corpus_files_come_back_byte_identical(path: Path) -> None:
    """``dumps(load(path))`` is the file's text, byte for byte."""
    assert dumps(load(path)) == path.read_bytes().decode("utf-8")


@pytest.mark.parametrize(
    ("relative", "tag", "name", "attribute", "value", "text"),
    [
        (CARTPOLE, "joint", "slider", "damping", 0.25, "0.25"),
        (ARM, "geom", "link_1", "rgba", (0.1, 0.2, 0.3, 1.0), "0.1 0.2 0.3 1"),
        (IIWA, "joint", "joint_1", "damping", None, None),
        (ARM, "geom", "base", "margin", 0.01, "0.01"),
    ],
    ids=["change damping", "change rgba in single quotes", "remove on a wrapped line", "add"],
)
def test_one_attribute_edit_is_a_two_line_diff(
    relative: str, tag: str, name: str, attribute: str, value: Value | None, text: str | None
) -> None:
    """One attribute edited: one ``-`` and one ``+`` line; MuJoCo compiles it as by hand."""
    path = _package_file(relative)
    source = path.read_text()
    edited = _edit(load(path), tag, name, lambda e: with_attributes(e, {attribute: value}))
    written = dumps(edited)
    by_hand = _hand_edited(source, tag, name, attribute, text)
    assert [line[0] for line in _changed_lines(source, written)] == ["-", "+"]
    assert written == by_hand
    assert _same_compiled(written, by_hand, path) == []
    assert model_differences(compile_text_beside(source, path), compile_text_beside(written, path))


def test_removing_an_element_removes_its_line() -> None:
    """A removed geom takes its line and nothing else; MuJoCo compiles it as removed by hand."""
    path = _package_file(CARTPOLE)
    source = path.read_text()

    def without_rail(node: Node) -> Node:
        if not isinstance(node, AnyElement):
            return node
        kept = [c for c in node.children if not isinstance(c, Geom) or c.name != "rail1"]
        return with_children(node, kept)

    written = dumps(map_tree(without_rail, load(path)))
    line = source[: _start_tag(source, "geom", "rail1").end()].rsplit("\n", 1)[1] + "\n"
    by_hand = source.replace("\n" + line, "\n", 1)
    assert _changed_lines(source, written) == ["-" + line]
    assert written == by_hand
    assert _same_compiled(written, by_hand, path) == []


def test_adding_an_element_adds_its_lines_indented_as_siblings() -> None:
    """A body added in code: only its lines are added, indented as the worldbody's children."""
    path = _package_file(CARTPOLE)
    source = path.read_text()
    extra = Body(name="extra", pos=(0, 0, 2), children=[Geom(size=(0.1,))])
    written = dumps(
        _edit(load(path), "body", "cart", lambda body: with_children(body, [*body.children, extra]))
    )
    added = '      <body name="extra" pos="0 0 2">\n        <geom size="0.1"/>\n      </body>\n'
    cart_end = "\n    </body>\n  </worldbody>"
    by_hand = source.replace(cart_end, "\n" + added.rstrip("\n") + cart_end, 1)
    assert _changed_lines(source, written) == ["+" + line for line in added.splitlines(True)]
    assert written == by_hand
    assert _same_compiled(written, by_hand, path) == []


@pytest.mark.parametrize("name", sorted(FORMATS))
def test_fixture_comes_back_byte_identical(name: str) -> None:
    """Line breaks, tabs, quotes, wrapped attributes, comments, references: all come back."""
    text = FORMATS[name]
    assert dumps(loads(text)) == text


@pytest.mark.parametrize("name", sorted(FORMATS))
def test_fixture_attribute_edit_is_a_two_line_diff(name: str) -> None:
    """Changing the geom's size rewrites its value in place; MuJoCo compiles it as by hand."""
    text = FORMATS[name]
    size = {"size": (0.25, 0.5, 0.75)}
    written = dumps(_edit(loads(text), "geom", "g", lambda g: with_attributes(g, size)))
    by_hand = _hand_edited(text, "geom", "g", "size", "0.25 0.5 0.75")
    assert written == by_hand
    assert [line[0] for line in _changed_lines(text, written)] == ["-", "+"]
    assert _same_compiled(written, by_hand) == []


@pytest.mark.parametrize("name", sorted(FORMATS))
def test_fixture_added_element_follows_the_file_style(name: str) -> None:
    """A site added to body "b" is one new line, indented and ended as the geom's line."""
    text = FORMATS[name]
    site = Site(name="s", pos=(0, 0, 1))
    written = dumps(
        _edit(loads(text), "body", "b", lambda b: with_children(b, [*b.children, site]))
    )
    geom_line = text[: _start_tag(text, "geom", "g").start()].rsplit("\n", 1)[1]
    newline = "\r\n" if "\r\n" in text else "\n"
    line = geom_line + '<site name="s" pos="0 0 1"/>'
    changed = _changed_lines(text, written)
    assert changed == ["+" + line + newline]
    end_of_body = text.index("</body>", _start_tag(text, "geom", "g").end())
    line_start = text.rindex("\n", 0, end_of_body) - (1 if newline == "\r\n" else 0)
    by_hand = text[:line_start] + newline + line + text[line_start:]
    assert written == by_hand
    assert _same_compiled(written, by_hand) == []


def test_removed_attributes_take_their_white_space_and_added_ones_go_last() -> None:
    """Removing and adding attributes in one tag edits only that tag's text."""
    text = FORMATS["wrapped attributes"]
    written = dumps(
        _edit(loads(text), "geom", "g", lambda g: with_attributes(g, {"rgba": None, "mass": 2}))
    )
    expected = text.replace(
        'size="0.1 0.2 0.3"\n            rgba="1 0 0 1" />', 'size="0.1 0.2 0.3" mass="2" />'
    )
    assert written == expected
    assert _same_compiled(written, expected) == []


@pytest.mark.parametrize("path", compiling_corpus()[::5], ids=corpus_id)
def test_prefixed_model_compiles_as_its_canonical_dump(path: Path) -> None:
    """``prefixed`` edits names in place: the kept text compiles as the canonical one."""
    model = prefixed(load(path, inline_includes=True), "p_")
    assert _same_compiled(dumps(model), dumps(model, canonical=True), path) == []


#: The lines scaling adds to a model without default classes, values emptied.
_ADDED_DEFAULT = frozenset({"<default>", '<geom friction=""/>', "</default>"})


def _skeleton(line: str) -> str:
    """A line with its quoted attribute values emptied."""
    return re.sub(r"\"[^\"]*\"|'[^']*'", '""', line)


@pytest.mark.parametrize(
    ("relative", "transform"),
    [
        (IIWA, lambda m: prefixed(m, "p_")),
        (ARM, lambda m: prefixed(m, "p_")),
        (ARM, lambda m: scaled(m, 2)),
        (IIWA, lambda m: scaled(m, 1.5)),
    ],
    ids=["prefixed robosuite", "prefixed dm_control", "scaled dm_control", "scaled robosuite"],
)
def test_transforms_edit_values_in_place(
    relative: str, transform: Callable[[Mujoco], Node]
) -> None:
    """Prefixing and scaling change values inside their quotes, line for line.

    Scaling a model without default classes adds one, giving geoms MuJoCo's
    built-in friction scaled; those added lines are left out of the comparison.
    """
    path = _package_file(relative)
    source = path.read_text()
    model = transform(load(path))
    written = dumps(model)
    lines = written.splitlines()
    if "<default" not in source:
        lines = [line for line in lines if _skeleton(line).strip() not in _ADDED_DEFAULT]
    pairs = list(zip(source.splitlines(), lines, strict=True))
    changed = [(a, b) for a, b in pairs if a != b]
    # values changed in place; scaling may add attributes (``density``) before the tag's end
    assert changed and all(_skeleton(b).startswith(_skeleton(a).rstrip("/> ")) for a, b in changed)
    assert _same_compiled(written, dumps(model, canonical=True), path) == []


def test_dump_elsewhere_relocates_paths_in_place(tmp_path: Path) -> None:
    """Dumped into another folder, only the lines naming files change, and MuJoCo agrees."""
    path = _package_file(IIWA)
    source = path.read_text()
    target = tmp_path / "moved" / "robot.xml"
    target.parent.mkdir()
    dump(load(path), target)
    written = target.read_text()
    changed = _changed_lines(source, written)
    removed = [line for line in changed if line[0] == "-"]
    assert changed and len(removed) * 2 == len(changed)
    assert all("file=" in line or "dir=" in line for line in changed)
    original = mujoco.MjModel.from_xml_path(str(path))
    moved = mujoco.MjModel.from_xml_path(str(target))
    assert model_differences(original, moved, ignore=path_fields()) == []


def test_layouts_stay_out_of_dicts_and_element_trees() -> None:
    """The dict form is JSON and rebuilds the model; ElementTree sees the model, not the text."""
    path = _package_file(ARM)
    model = load(path)
    data = to_dict(model)
    assert from_dict(json.loads(json.dumps(data))) == model
    canonical = loads(dumps(model, canonical=True))
    assert ET.tostring(to_etree(model)) == ET.tostring(to_etree(canonical))


@given(models())
def test_code_models_round_trip_through_kept_text(model: Mujoco) -> None:
    """A model built in code: its text read back writes the same text, and is the same model."""
    text = dumps(model)
    again = loads(text)
    assert again == model
    assert dumps(again) == text


def test_a_loaded_model_pickles_and_its_copy_writes_the_same_text() -> None:
    """Pickling keeps a loaded model's layouts: the copy is equal and dumps the same bytes."""
    text = (
        '<mujoco>\n  <worldbody>\n    <geom size="1.0"/>\n    <site name="s"\n'
        '      pos="0 0 1"/>\n  </worldbody>\n</mujoco>\n'
    )
    model = loads(text)
    copied = pickle.loads(pickle.dumps(model))
    assert copied == model and dumps(copied) == text
    edited = map_tree(
        lambda n: with_attributes(n, {"pos": (0, 0, 2)}) if isinstance(n, Site) else n, copied
    )
    assert dumps(edited) == text.replace('pos="0 0 1"', 'pos="0 0 2"')


def test_an_attribute_added_while_text_is_removed_is_written() -> None:
    """The writer's check for an untouched element compares the fields stored, not their count."""
    text = (
        '<mujoco>\n  <worldbody>\n    <geom name="a" size="1">junk</geom>\n'
        "  </worldbody>\n</mujoco>\n"
    )
    model = loads(text)
    geom = model.worldbody.geoms[0]
    changed = build_node(Geom, {"text": None, "rgba": "1 0 0 1"}, geom)
    written = dumps(map_tree(lambda n: changed if n is geom else n, model))
    assert '<geom name="a" size="1" rgba="1 0 0 1">' in written
    assert loads(written).worldbody.geoms[0].rgba == (1.0, 0.0, 0.0, 1.0)


def test_untouched_subtrees_keep_multibyte_text_beside_an_edit() -> None:
    """Beside an edited element, untouched ones keep non-ASCII text, CRLF and odd spacing."""
    text = (
        "<mujoco>\r\n  <!-- r\u00e9sum\u00e9 \u2014 \u65e5\u672c -->\r\n  <worldbody>\r\n"
        '    <body name="\u00e4rm"   pos="0 0 1">\r\n      <geom size = "1.0"/><!--x-->\r\n'
        '    </body>\r\n    <site name="s" pos="0 0 1"/>\r\n  </worldbody>\r\n</mujoco>\r\n'
    )
    model = loads(text.encode("utf-8"))
    assert dumps(model) == text
    edited = map_tree(
        lambda n: with_attributes(n, {"pos": (0, 0, 2)}) if isinstance(n, Site) else n, model
    )
    assert edited.worldbody.bodies[0] is model.worldbody.bodies[0]
    expected = text.replace('<site name="s" pos="0 0 1"/>', '<site name="s" pos="0 0 2"/>')
    assert dumps(edited) == expected


def test_an_element_rebuilt_with_its_children_writes_its_own_edit_only() -> None:
    """A parent given a new attribute but its old children is edited in its start tag only."""
    text = (
        '<mujoco>\n  <worldbody>\n    <body name="b">\n      <geom size="1"/>\n'
        "    </body>\n  </worldbody>\n</mujoco>\n"
    )
    model = loads(text)
    body = model.worldbody.bodies[0]
    moved = with_attributes(body, {"pos": (1, 0, 0)})
    assert moved.children is body.children
    written = dumps(map_tree(lambda n: moved if n is body else n, model))
    assert written == text.replace('<body name="b">', '<body name="b" pos="1 0 0">')


# -- Stray text between elements (mixed content, which MuJoCo ignores) survives changed
#    children.
#
# An element whose children change (an ``<include>`` inlined, a child removed) is
# written with all its text: read back, the model is equal to the one written,
# and MuJoCo compiles the written text as it compiles the original file.


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


# -- Editing a start tag: only what changed is spliced in, escaped for its quotes. ---------


def _edited_elements(model: Node) -> list[AnyElement]:
    """The elements of ``model`` that carry a layout, each once."""
    from mjcf_model import walk

    return [element for _, element in walk(model) if element.layout is not None]


@pytest.mark.parametrize("path", compiling_corpus()[::3], ids=corpus_id)
def test_splicing_changed_attributes_writes_the_general_edit(path: Path) -> None:
    """The writer's fast splice gives, for every edited start tag, the general edit's text.

    Prefixed (names change), scaled (values change, attributes are added) and with every
    third attribute removed: each start tag the splice writes equals the one the general
    edit (``_edited_start`` over every attribute) writes, and the splice handles most tags.
    """
    from mjcf_model.serializers.kept_format import _edited_start, _spliced_start
    from mjcf_model.serializers.layout import detail
    from mjcf_model.serializers.parsed_elements import recorded_values

    model = load(path, inline_includes=True)

    def thinned(element: AnyElement) -> AnyElement:
        names = [name for name, _ in attribute_items(element)][::3]
        return with_attributes(element, dict.fromkeys(names))

    spliced = 0
    for variant in (prefixed(model, "p_"), scaled(model, 1.5), map_tree(_thinning(thinned), model)):
        for element in _edited_elements(variant):
            layout = element.layout
            assert layout is not None
            cut = detail(layout)
            recorded_values(cut, type(element), layout)
            if cut.getter is None or element.tag != layout.tag:
                continue
            fast = _spliced_start(element, cut)
            if fast is not None:
                spliced += 1
                assert fast == _edited_start(cut, attribute_items(element))
    assert spliced > 0


def _thinning(change: Callable[[AnyElement], AnyElement]) -> Callable[[Node], Node]:
    def visit(node: Node) -> Node:
        if isinstance(node, Mujoco) or not hasattr(node, "layout") or node.layout is None:
            return node
        return change(node)  # type: ignore[arg-type]

    return visit


def _single_quoted(text: str) -> str:
    """Canonical text with every attribute value in single quotes (comments left alone)."""
    pieces = re.split(r"(<!--.*?-->)", text, flags=re.DOTALL)
    for index in range(0, len(pieces), 2):
        pieces[index] = re.sub(
            r'="([^"]*)"', lambda m: "='" + m.group(1).replace("'", "&apos;") + "'", pieces[index]
        )
    return "".join(pieces)


#: Text with every character XML escapes in an attribute, and plain letters between.
_MARKUP_TEXT = st.text(alphabet="&<>\"' ab", min_size=1, max_size=12).filter(
    lambda text: text.strip() == text
)


@given(models(), st.booleans(), st.data())
def test_attributes_edited_to_markup_characters_read_back(
    model: Mujoco, single: bool, data: st.DataObject
) -> None:
    """Names and unknown attributes set to text with ``& < > " '`` are written escaped.

    The model is loaded from its text (in double or single quotes, so that its start tags
    are edited in place), a few of its elements are renamed and given an unknown attribute
    holding such text, and the written text reads back to the edited model.
    """
    text = dumps(model)
    loaded = loads(_single_quoted(text) if single else text)
    assert loaded == model
    named = [
        (path, element)
        for path, element in walk_paths(loaded)
        if isinstance(get_attribute(element, "name"), str)
    ]
    chosen = data.draw(st.lists(st.sampled_from(named), min_size=1, max_size=4, unique_by=id))
    edits: dict[tuple[int, ...], dict[str, Value | None]] = {}
    for index, (path, _) in enumerate(chosen):
        renamed, noted = data.draw(st.sampled_from([(True, False), (False, True), (True, True)]))
        edits[path] = {}
        if renamed:  # a typed field: the splice of changed values writes it
            edits[path]["name"] = data.draw(_MARKUP_TEXT) + str(index)
        if noted:  # an attribute without a field: the general edit writes it
            edits[path]["note"] = data.draw(_MARKUP_TEXT)
    from mjcf_model.tree.paths import edited_at

    edited = edited_at(loaded, edits)
    written = dumps(edited)
    assert loads(written) == edited
    assert ET.fromstring(written) is not None  # well-formed for any XML reader too


def walk_paths(model: Node) -> list[tuple[tuple[int, ...], AnyElement]]:
    """Every element of ``model`` with its path, the root left out."""
    from mjcf_model import walk

    return [(path, element) for path, element in walk(model) if path]
