"""Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads.

Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
compiles a file, we load it and write it back so that it compiles identically.
"""

from __future__ import annotations

import ast
import copy
import re
import sys
import time
from collections.abc import Callable
from pathlib import Path

import mujoco
import pytest

import mjcf_model
import serializers
from mjcf_model import (
    Body,
    Comment,
    GenericElement,
    Geom,
    Mesh,
    MjcfError,
    MjcfIncludeError,
    MjcfSyntaxError,
    MjcfValueError,
    Mujoco,
    Node,
    Unparsed,
    attach,
    full_repr,
    prefixed,
    scaled,
)
from mjcf_model.bridge.compare import model_differences
from mjcf_model.nodes.base import build_node
from serializers import dump, dumps, from_dict, from_etree, load, loads, to_dict, to_etree
from serializers.parsed_elements import DEFERRED_TEXT
from tests.support.oracles import _compiled, _round_trips_like_mujoco

#: The packages as imported: the installed wheel under tests/run_installed.py.
PACKAGES = [Path(mjcf_model.__file__).parent, Path(serializers.__file__).parent]

#: MuJoCo's parser (tinyxml2) refuses element nesting deeper than this.
MUJOCO_DEEPEST_BODY_CHAIN = 496


# -- numbers ---------------------------------------------------------------------------


def _patterns() -> list[tuple[Path, str]]:
    found = []
    for package in PACKAGES:
        for path in package.rglob("*.py"):
            for node in ast.walk(ast.parse(path.read_text())):
                if (
                    isinstance(node, ast.Call)
                    and isinstance(node.func, ast.Attribute)
                    and isinstance(node.func.value, ast.Name)
                    and node.func.value.id == "re"
                ):
                    first = node.args[0] if node.args else None
                    assert isinstance(first, ast.Constant), f"{path}: a pattern built at run time"
                    pattern = first.value
                    found.append((path, pattern if isinstance(pattern, str) else pattern.decode()))
    return found


def test_every_regular_expression_is_one_character_class() -> None:
    """No pattern can backtrack: each is a single character class, matched in linear time.

    This is how the library keeps regular expressions off untrusted text: a
    pattern with quantifiers or alternation fails here, and must be replaced by
    plain string code (as number parsing was: ``float`` on split tokens).
    """
    patterns = _patterns()
    assert patterns, "the scan found no pattern at all: it is broken"
    for path, pattern in patterns:
        assert pattern.startswith("[") and pattern.endswith("]"), (path, pattern)
        inner = pattern[1:-1].replace("\\]", "")
        assert "]" not in inner and "[" not in inner.replace("\\[", ""), (path, pattern)


@pytest.mark.parametrize("digits", [20, 30, 5000])
def test_number_parsing_is_linear(digits: int) -> None:
    """``size="111...1x"`` took 44 s at 20 digits, multiplying by 7 for each two more."""
    text = f'<mujoco><worldbody><geom size="{"1" * digits}x"/></worldbody></mujoco>'
    start = time.perf_counter()
    geom = loads(text).worldbody.geoms[0]
    with pytest.raises(MjcfValueError, match="expected a number"):
        Geom(size=geom.size.text)
    assert time.perf_counter() - start < 1.0


@pytest.mark.parametrize("spelling", ["1..2", "0.20.4", "-0.-0.015", "--1", "1,2", "1e", "x"])
def test_malformed_numbers_raise_mjcf_errors(spelling: str) -> None:
    """``float``'s ValueError never escapes: building a node raises MjcfValueError."""
    with pytest.raises(MjcfValueError, match="expected a number"):
        Geom(size=spelling)
    with pytest.raises(MjcfValueError):
        Geom(group=spelling)


@pytest.mark.parametrize(
    ("attribute", "spelling"),
    [("size", "0x10"), ("pos", ""), ("friction", ""), ("size", "0x1p-2 1")],
)
def test_spellings_mujoco_reads_are_kept_verbatim(attribute: str, spelling: str) -> None:
    """MuJoCo reads ``0x10`` (16) and empty values; the text is kept and compiles the same."""
    text = (
        f'<mujoco><worldbody><geom size="0.1" {attribute}="{spelling}"/></worldbody></mujoco>'
        if attribute != "size"
        else f'<mujoco><worldbody><geom {attribute}="{spelling}"/></worldbody></mujoco>'
    )
    _round_trips_like_mujoco(text)
    geom = loads(text).worldbody.geoms[0]
    value = getattr(geom, attribute)
    assert value == Unparsed(spelling)
    with pytest.raises(MjcfValueError, match="kept verbatim") as caught:
        value[0]
    assert caught.value.path == "/mujoco/worldbody/geom" and caught.value.line == 1


def test_unparsed_values_survive_dicts_and_element_tree() -> None:
    """Every serializer carries the verbatim text; transforms that read it raise MjcfValueError."""
    model = loads('<mujoco><worldbody><geom name="g" size="0x10"/></worldbody></mujoco>')
    assert from_dict(to_dict(model)) == model
    assert from_etree(to_etree(model)) == model
    assert prefixed(model, "p_").worldbody.geoms[0].size == Unparsed("0x10")
    with pytest.raises(MjcfValueError, match="kept verbatim"):
        scaled(model, 2.0)


def test_large_values_are_shortened_in_errors() -> None:
    """An error about a huge attribute quotes its start, not all of it."""
    with pytest.raises(MjcfValueError) as caught:
        Geom(size="1 " * 100_000 + "x")
    assert len(str(caught.value)) < 300


# -- depth -----------------------------------------------------------------------------


def _chain_text(depth: int) -> str:
    return (
        "<mujoco><worldbody>"
        + '<body><geom size="0.1"/>' * depth
        + "</body>" * depth
        + "</worldbody></mujoco>"
    )


def _default_chain_text(depth: int) -> str:
    opened = "".join(f'<default class="c{i}"><geom size="{i + 1}"/>' for i in range(depth))
    return (
        f"<mujoco><default>{opened}{'</default>' * depth}</default>"
        f'<worldbody><geom class="c{depth - 1}"/></worldbody></mujoco>'
    )


OPERATIONS: dict[str, Callable[[Mujoco], object]] = {
    "dumps and loads": lambda m: loads(dumps(m)) == m,
    "==": lambda m: m == loads(dumps(m)),
    "hash": lambda m: hash(m) == hash(loads(dumps(m))),
    "dicts": lambda m: from_dict(to_dict(m)) == m,
    "ElementTree": lambda m: from_etree(to_etree(m)) == m,
    "prefixed": lambda m: len(dumps(prefixed(m, "p_"))) > 0,
    "scaled": lambda m: len(dumps(scaled(m, 2.0))) > 0,
    "repr": lambda m: full_repr(m).count("Body(") >= 495 or full_repr(m).count("Default(") >= 495,
    "deepcopy": lambda m: copy.deepcopy(m) == m,
}


@pytest.mark.parametrize("operation", sorted(OPERATIONS))
@pytest.mark.parametrize(
    ("text", "label"),
    [
        (_chain_text(MUJOCO_DEEPEST_BODY_CHAIN), "bodies as deep as MuJoCo reads"),
        (_default_chain_text(495), "default classes as deep as MuJoCo reads"),
        (_chain_text(5_000), "bodies ten times deeper"),
        (_default_chain_text(5_000), "default classes ten times deeper"),
    ],
    ids=["bodies-496", "defaults-495", "bodies-5000", "defaults-5000"],
)
def test_deep_trees_work_without_recursion_limits(text: str, label: str, operation: str) -> None:
    """Every operation works at MuJoCo's depth and beyond, with Python's default limit."""
    assert sys.getrecursionlimit() <= 1000 or label  # the default limit is what users have
    model = loads(text)
    assert OPERATIONS[operation](model) is not False


def test_mujoco_reads_the_deepest_chain_we_test() -> None:
    """The depth above is MuJoCo's own limit: one more level and it refuses the file."""
    _compiled(_chain_text(MUJOCO_DEEPEST_BODY_CHAIN))
    with pytest.raises(ValueError, match="DEPTH"):
        _compiled(_chain_text(MUJOCO_DEEPEST_BODY_CHAIN + 1))


def test_deep_default_chain_compiles_identically() -> None:
    """Default classes nested as deep as MuJoCo reads compile the same after a round trip."""
    _round_trips_like_mujoco(_default_chain_text(495))


def test_include_chain_deeper_than_the_recursion_limit(tmp_path: Path) -> None:
    """MuJoCo follows include chains of any length (1,000 here); so does ``load``."""
    length = 1_000
    for index in range(length):
        inner = (
            f'<include file="part{index + 1}.xml"/>'
            if index + 1 < length
            else '<geom name="last" size="0.1"/>'
        )
        (tmp_path / f"part{index}.xml").write_text(f"<mujoco>{inner}</mujoco>")
    main = tmp_path / "main.xml"
    main.write_text('<mujoco><worldbody><include file="part0.xml"/></worldbody></mujoco>')
    compiled = mujoco.MjModel.from_xml_path(str(main))
    model = load(main, inline_includes=True)
    assert [g.name for g in model.worldbody.geoms] == ["last"]
    assert model_differences(compiled, _compiled(dumps(model))) == []


def test_include_root_may_be_any_element(tmp_path: Path) -> None:
    """MuJoCo takes the children of an included file's root, whatever its tag."""
    (tmp_path / "part.xml").write_text('<parts><geom name="g" size="1"/></parts>')
    main = tmp_path / "main.xml"
    main.write_text('<mujoco><worldbody><include file="part.xml"/></worldbody></mujoco>')
    compiled = mujoco.MjModel.from_xml_path(str(main))
    model = load(main, inline_includes=True)
    assert model_differences(compiled, _compiled(dumps(model))) == []


def test_include_name_too_long_is_an_include_error(tmp_path: Path) -> None:
    """``OSError: File name too long`` becomes an include error naming the element."""
    main = tmp_path / "main.xml"
    main.write_text(f'<mujoco><include file="{"x" * 5000}.xml"/></mujoco>')
    with pytest.raises(MjcfIncludeError) as caught:
        load(main, inline_includes=True)
    assert caught.value.line == 1 and caught.value.path == "/mujoco/include"


# -- bytes and markup as MuJoCo reads them ---------------------------------------------


@pytest.mark.parametrize(
    "declaration",
    ["ISO-8859-1", "no-such-encoding", "UTF-16", "Shift_JIS"],
)
def test_bytes_are_read_as_utf8_whatever_the_declaration(declaration: str) -> None:
    """MuJoCo ignores the declared encoding; a name with é reads the same in both."""
    text = (
        f'<?xml version="1.0" encoding="{declaration}"?>'
        '<mujoco><worldbody><geom name="é" size="1"/></worldbody></mujoco>'
    ).encode()
    assert mujoco.MjModel.from_xml_string(text.decode()).geom(0).name == "é"
    model = loads(text)
    assert model.worldbody.geoms[0].name == "é"
    assert loads(dumps(model)) == model


def test_bytes_that_are_not_utf8_are_a_syntax_error() -> None:
    """A Latin-1 file is refused with the reason; MuJoCo's Python binding fails on it too."""
    with pytest.raises(MjcfSyntaxError, match="byte 0xE9 is not UTF-8") as caught:
        loads(b'<mujoco model="\xe9"/>')
    assert caught.value.line == 1


def test_a_latin1_comment_is_refused_naming_byte_line_and_column(tmp_path: Path) -> None:
    """MuJoCo compiles a file with a Latin-1 comment; mjcf-model refuses it, saying exactly where.

    The decision (documented in the README): a node holds text as Unicode, so
    the byte could not be written back as it was; the error names the byte, file,
    line and column, and says how to convert the file.
    """
    path = tmp_path / "old.xml"
    path.write_bytes(
        b'<mujoco>\n  <!-- caf\xe9 -->\n  <worldbody><geom size="1"/></worldbody>\n</mujoco>\n'
    )
    assert mujoco.MjModel.from_xml_path(str(path)).ngeom == 1  # MuJoCo reads it
    with pytest.raises(MjcfSyntaxError) as caught:
        load(path)
    error = caught.value
    assert (error.file, error.line) == (str(path), 2)
    assert "(column 11)" in str(error) and "byte 0xE9 is not UTF-8" in str(error)
    assert "iconv -f latin1 -t utf-8" in str(error)


@pytest.mark.parametrize(
    "text",
    [
        '<mujoco><worldbody><geom name="a&b" size="1"/></worldbody></mujoco>',
        '<mujoco><worldbody><geom name="a&foo;b" size="1"/></worldbody></mujoco>',
        '<mujoco><worldbody><geom name="a<b" size="1"/></worldbody></mujoco>',
        '<mujoco><worldbody><geom size="1"/></worldbody></mujoco><extra/>',
        '<mujoco><worldbody><geom size="1"/></worldbody></mujoco></mujoco>',
        "<mujoco><!-- a & b --><worldbody><geom name='&#65;' size='1'/></worldbody></mujoco>",
    ],
    ids=[
        "bare-ampersand",
        "unknown-entity",
        "less-than-in-value",
        "element-after-root",
        "end-tag-after-root",
        "mixed",
    ],
)
def test_markup_mujoco_reads_loads_the_same(text: str) -> None:
    """tinyxml2 reads stray ``&`` and ``<`` as characters and ignores elements after the root."""
    _round_trips_like_mujoco(text)
    compiled = _compiled(text)
    ours = _compiled(dumps(loads(text)))
    assert [compiled.geom(i).name for i in range(compiled.ngeom)] == [
        ours.geom(i).name for i in range(ours.ngeom)
    ]


def test_comments_keep_their_ampersands() -> None:
    """Repairing stray ``&`` leaves comments alone."""
    model = loads("<mujoco><!-- a & b --><worldbody name='x&y'/></mujoco>")
    assert model.children[0] == Comment(text=" a & b ")


@pytest.mark.parametrize("junk", ["junk", "<"])
def test_text_after_the_root_is_refused_like_mujoco(junk: str) -> None:
    """Text after the root is refused, by MuJoCo as by us."""
    text = f'<mujoco><worldbody><geom size="1"/></worldbody></mujoco>{junk}'
    with pytest.raises(ValueError):
        _compiled(text)
    with pytest.raises(MjcfSyntaxError):
        loads(text)


def test_control_characters_are_refused_and_the_error_says_mujoco_reads_them() -> None:
    """XML cannot carry U+0001; MuJoCo reads it, and the error says so."""
    text = '<mujoco><worldbody><geom name="a\x01b" size="1"/></worldbody></mujoco>'
    _compiled(text)  # MuJoCo reads it
    with pytest.raises(MjcfSyntaxError, match="MuJoCo's own parser reads it") as caught:
        loads(text)
    assert "U+0001" in str(caught.value)


# -- nodes that cannot be written cannot be built --------------------------------------


@pytest.mark.parametrize("bad", ["a\x00b", "a\x01", "\ud800", "x\x1f", "\ufffe"])
def test_text_xml_cannot_carry_is_refused_when_the_node_is_made(bad: str) -> None:
    """Names, comments, attribute values and text refuse what could not be read back."""
    for build in (
        lambda: Geom(name=bad),
        lambda: Comment(text=bad),
        lambda: GenericElement(tag="x", attributes={"a": bad}),
        lambda: Body(text=bad),
    ):
        with pytest.raises(MjcfValueError, match="XML cannot carry"):
            build()


@pytest.mark.parametrize("tag", ["", "1a", "a b", "a<", "-x", "a=b"])
def test_tags_and_attribute_names_must_be_xml_names(tag: str) -> None:
    """A tag or attribute name that is not an XML name could not be written."""
    with pytest.raises(MjcfValueError, match="not an XML name"):
        GenericElement(tag=tag)
    with pytest.raises(MjcfValueError, match="not an XML name"):
        GenericElement(tag="x", attributes={tag: "1"})


def test_carriage_return_in_a_comment_is_refused() -> None:
    """XML reads a carriage return in a comment as a line feed; comments have no references."""
    with pytest.raises(MjcfValueError, match="carriage return"):
        Comment(text="a\rb")


@pytest.mark.parametrize("value", ["a\tb", "a\nb", "a\rb", "a\r\nb", " lead", "trail "])
def test_normalised_characters_come_back_unchanged(value: str) -> None:
    """Tabs and line breaks in names and text are written as references and read back."""
    model = Mujoco(
        children=[
            GenericElement(tag="future", attributes={"note": value}, text=f"x{value}x"),
        ]
    )
    model = Mujoco(model=value, children=model.children)
    again = loads(dumps(model))
    assert again.model == value
    assert again.children[0] == model.children[0]
    assert from_etree(to_etree(model)) == model


def test_dump_of_any_buildable_node_loads_back(tmp_path: Path) -> None:
    """What can be built can be dumped to a file and read back equal."""
    model = Mujoco(model="é\U0001f600", children=[Comment(text=" ok ")])
    dump(model, tmp_path / "m.xml")
    assert load(tmp_path / "m.xml") == model


# -- only MjcfError escapes ------------------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "",
        "<",
        "<mujoco>",
        "<mujoco></robot>",
        "<mujoco><worldbody><geom size='1' size='2'/></worldbody></mujoco>",
        "<mujoco><worldbody><geom size=1/></worldbody></mujoco>",
        "\ufeff<mujoco/>x",
    ],
)
def test_broken_text_raises_only_mjcf_errors(text: str) -> None:
    """Malformed text raises MjcfError subclasses only, from text and from bytes."""
    with pytest.raises(MjcfError):
        loads(text)
    with pytest.raises(MjcfError):
        loads(text.encode("utf-8", "surrogatepass"))


def test_errors_from_bad_attributes_never_quote_megabytes() -> None:
    """A 2 MB attribute loads; the error on use quotes its start and its length."""
    text = "<mujoco><worldbody><geom size='" + "1 " * 1_000_000 + "'/></worldbody></mujoco>"
    geom = loads(text).worldbody.geoms[0]
    with pytest.raises(MjcfValueError) as caught:
        geom.size[0]
    assert len(str(caught.value)) < 400
    assert re.search(r"\(\d+ characters\)", str(caught.value))
    assert str(caught.value).startswith("<string>:1: /mujoco/worldbody/geom: attribute 'size'")


def test_a_long_number_list_reads_as_a_short_one_does() -> None:
    """Converted after parsing (over 1 MiB of text), a list is the value the builder makes."""
    numbers = " ".join(f"{i / 7:.6f}" for i in range(3 * 60_000))
    text = f'<mujoco><asset><mesh name="m" vertex="{numbers}"/></asset></mujoco>'
    assert len(numbers) > DEFERRED_TEXT
    mesh = loads(text).asset.meshes[0]
    assert mesh.vertex == build_node(Mesh, {"vertex": numbers}).vertex
    assert type(mesh.vertex) is tuple and len(mesh.vertex) == 180_000
    assert dumps(loads(text)) == text
    assert dumps(prefixed(loads(text), "p_")) == text.replace('name="m"', 'name="p_m"')


# -- memory ----------------------------------------------------------------------------


def test_memory_stays_a_small_multiple_of_a_huge_attribute() -> None:
    """A 10 MB attribute of numbers: load peaks below 8x its size, dump below 12x.

    The floats themselves take 32 bytes per number (about 3.6x this text); the
    bound fails if the text is ever split into one string per number at once,
    which took the 50 MB case of the fuzzing campaign to 4.6 GB.
    """
    import tracemalloc

    count = 10_000_000 // 9
    text = (
        '<mujoco><custom><numeric name="n" data="' + "0.123456 " * count + '"/></custom></mujoco>'
    )
    tracemalloc.start()
    try:
        model = loads(text)
        _, load_peak = tracemalloc.get_traced_memory()
        tracemalloc.reset_peak()
        written = dumps(model)
        _, dump_peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert len(model.children[0].children[0].data) == count  # type: ignore[attr-defined]
    assert len(written) > len(text) * 0.9
    assert load_peak < 8 * len(text), load_peak / len(text)  # issue 26's bound
    assert dump_peak < 12 * len(text), dump_peak / len(text)


def test_attach_classes_replicates_nested_deeper_than_the_recursion_limit() -> None:
    """A parent whose world nests replicates 3,000 deep keeps its main defaults when attached to."""
    depth = 3_000
    opened = '<replicate count="1" offset="0 0 0">' * depth
    parent = loads(
        f'<mujoco><default><geom rgba="1 0 0 1"/></default><worldbody>{opened}'
        f'<geom size="0.1"/>{"</replicate>" * depth}</worldbody></mujoco>'
    )
    child = loads(
        '<mujoco><default><geom rgba="0 1 0 1"/></default>'
        '<worldbody><body name="b"><geom size="0.1"/></body></worldbody></mujoco>'
    )
    scene = attach(parent, child, prefix="c_", at=None)
    inner: Node = scene.worldbody.children[0]  # the replicates; the attached body follows
    for _ in range(depth - 1):
        (inner,) = inner.children  # type: ignore[attr-defined]
    (geom,) = inner.children  # type: ignore[attr-defined]
    assert geom.dclass == "parent_main"  # the parent's main class, moved where it applies
