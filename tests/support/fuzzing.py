"""The machinery of the fuzz suite (``tests/test_fuzz.py``): seeds, mutations, the case check.

A case is a :class:`Mutant`: the bytes of a seed document (a real corpus file,
or the text of a model drawn by :func:`mjcf_model.strategies.models`) after a
few mutations, each drawn by hypothesis so that a failure shrinks to a small
example. :func:`check_case` runs the properties on one case under a wall-clock
limit (:func:`time_limit`).

The mutations work on bytes, not on a parsed tree, so they still apply after an
earlier mutation broke the document: elements and attributes are found with
forgiving regular expressions (:func:`element_spans`, :func:`attribute_spans`).
"""

from __future__ import annotations

import contextlib
import difflib
import functools
import math
import os
import re
import signal
import sys
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from types import FrameType
from typing import Any, TypeVar

import mujoco
from hypothesis import strategies as st

from mjcf_model.bridge.compare import model_differences
from mjcf_model.errors import MjcfError
from mjcf_model.nodes.root import Mujoco
from mjcf_model.serializers import dumps, from_dict, from_etree, loads, to_dict, to_etree
from mjcf_model.strategies import models
from mjcf_model.values.encoding import encoded
from tests.conftest import corpus_files, corpus_id

Draw = Callable[[st.SearchStrategy[Any]], Any]
_T = TypeVar("_T")


# -- seeds ------------------------------------------------------------------------------


@dataclass(frozen=True)
class Seed:
    """A document the mutations start from.

    Attributes:
        label: Where it came from (a corpus id, or ``"generated model"``).
        data: Its bytes.

    """

    label: str
    data: bytes

    def __repr__(self) -> str:
        return f"Seed({self.label!r}, {len(self.data)} bytes)"


@functools.cache
def _corpus_seeds() -> tuple[Seed, ...]:
    return tuple(Seed(corpus_id(path), path.read_bytes()) for path in corpus_files())


def _compiles_from_string(data: bytes) -> bool:
    try:
        mujoco.MjModel.from_xml_string(data.decode("utf-8"))
    except (ValueError, UnicodeDecodeError):
        return False
    return True


@functools.cache
def string_compiling_seeds() -> tuple[Seed, ...]:
    """The corpus files MuJoCo compiles from their text alone (no meshes, textures or includes).

    Only mutants of these (and of generated models) can reach the MuJoCo referee.
    """
    return tuple(seed for seed in _corpus_seeds() if _compiles_from_string(seed.data))


def corpus_seeds() -> st.SearchStrategy[Seed]:
    """Any file of the real corpus, half of the time one that compiles from a string."""
    return st.deferred(
        lambda: st.sampled_from(string_compiling_seeds()) | st.sampled_from(_corpus_seeds())
    )


def generated_seeds() -> st.SearchStrategy[Seed]:
    """The text of a model drawn by :func:`mjcf_model.strategies.models`."""
    return models().map(lambda model: Seed("generated model", dumps(model).encode("utf-8")))


@st.composite
def small_seeds(draw: Draw) -> Seed:
    """A small corpus file that compiles from a string, or (one time in four) a generated model.

    Generated models are the slow part of a case (drawing one takes about 0.1 s),
    hence the odds.
    """
    if draw(st.integers(0, 3)) == 3:
        seed: Seed = draw(generated_seeds())
        return seed
    small = [s for s in string_compiling_seeds() if len(s.data) <= 12_000]
    return small[draw(st.integers(0, len(small) - 1))]


# -- finding elements and attributes in possibly broken bytes ---------------------------

_TAG = re.compile(rb"<!--.*?-->|<(/?)([A-Za-z_][\w.:-]*)[^<>]*?(/?)>", re.DOTALL)
_ATTRIBUTE = re.compile(rb"""\s([A-Za-z_:][\w:.-]*)[ \t\r\n]*=[ \t\r\n]*("[^"<]*"|'[^'<]*')""")
#: An attribute value that looks like a list of numbers.
_NUMBERS = re.compile(rb"""\s*[-+]?[\d.][\d.eE+-]*(?:\s+[-+]?[\d.][\d.eE+-]*)*\s*""")


@dataclass(frozen=True)
class Span:
    """Where an element or an attribute sits in a document.

    Attributes:
        start: Index of its first byte.
        end: Index after its last byte.
        tag: The element's tag, or the attribute's name.
        value: For an attribute, where its value (without quotes) starts and ends.

    """

    start: int
    end: int
    tag: bytes
    value: tuple[int, int] = (0, 0)


def element_spans(data: bytes) -> list[Span]:
    """Every element whose start and end tag pair up (comments are skipped)."""
    spans: list[Span] = []
    open_tags: list[tuple[bytes, int]] = []
    for match in _TAG.finditer(data):
        closing, tag, empty = match.group(1), match.group(2), match.group(3)
        if tag is None:
            continue
        if closing:
            for depth in range(len(open_tags) - 1, -1, -1):
                if open_tags[depth][0] == tag:
                    spans.append(Span(open_tags[depth][1], match.end(), tag))
                    del open_tags[depth:]
                    break
        elif empty:
            spans.append(Span(match.start(), match.end(), tag))
        else:
            open_tags.append((tag, match.start()))
    return sorted(spans, key=lambda span: span.start)


def start_tag_ends(data: bytes) -> list[tuple[int, bytes]]:
    """For every start tag: the index of its closing ``>`` (or ``/>``) and its tag."""
    ends = []
    for match in _TAG.finditer(data):
        if match.group(2) is not None and not match.group(1):
            ends.append((match.end() - 1 - len(match.group(3)), match.group(2)))
    return ends


def attribute_spans(data: bytes) -> list[Span]:
    """Every ``name="value"`` in the document (leading whitespace included)."""
    return [
        Span(m.start(), m.end(), m.group(1), (m.start(2) + 1, m.end(2) - 1))
        for m in _ATTRIBUTE.finditer(data)
    ]


def numeric_attribute_spans(data: bytes) -> list[Span]:
    """The attributes whose value looks like one or more numbers."""
    return [
        span
        for span in attribute_spans(data)
        if _NUMBERS.fullmatch(data[span.value[0] : span.value[1]])
    ]


# -- values -----------------------------------------------------------------------------

#: Number-like text MuJoCo and Python disagree about, or that breaks naive parsers.
NUMBER_GARBAGE = (
    "0x10",
    "0X1F",
    "0x1p3",
    "--1",
    "+-1",
    "-+1",
    "++1",
    "1..2",
    "0.20.4",
    "..1",
    "1.2.",
    "",
    " ",
    "\t",
    "1e",
    "1e+",
    "1E-",
    "e5",
    ".",
    "-",
    "+",
    ".e1",
    "nan",
    "NaN",
    "-nan",
    "nan(0x1)",
    "inf",
    "-inf",
    "+inf",
    "Infinity",
    "INF",
    "1_000",
    "1,5",
    "1;2",
    "1e999",
    "-1e999",
    "1e-999",
    "4.9e-324",
    "2.2250738585072014e-308",
    "1e308",
    "1" * 400,
    "0b101",
    "0o17",
    "1j",
    "true",
    "None",
    "\u0663",
    "\u0661\u0662\u0663",
    "\uff11\uff12",
    "\U0001d7d9",
    "\u00bd",
    "\u00b2",
    "1\u00a02",
    "1\u20002",
    "\u22121",
    "1 2 3 4 5 6 7 8 9 10 11 12",
    "0 0 0 0",
    "9223372036854775808",
    "-9223372036854775809",
    "2147483648",
    "4294967296",
    "-0",
    "0e0",
    "00012",
    "1.",
    ".5",
    "  1  ",
    "1\n2",
    "1&#10;2",
    "1&#9;2",
)


def number_garbage() -> st.SearchStrategy[str]:
    """Text that is almost, or not at all, a number (or a list of numbers)."""
    runs = st.integers(10, 120)
    return st.one_of(
        st.sampled_from(NUMBER_GARBAGE),
        runs.map(lambda n: "1" * n + "x"),
        runs.map(lambda n: "1" * n + "e"),
        runs.map(lambda n: "-" + "1." * n),
        st.text("0123456789.eE+-xX nNaAiIfF", max_size=24),
        st.floats().map(repr),
        st.integers().map(str),
        st.text(st.characters(categories=["Nd", "No"]), min_size=1, max_size=4),
    )


#: Characters that XML 1.0 does not allow, raw or as a character reference.
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def odd_text() -> st.SearchStrategy[str]:
    """Names with odd unicode (no lone surrogates), control characters now and then."""
    return st.one_of(
        st.text(st.characters(exclude_categories=["Cs"]), max_size=12),
        st.text(st.characters(exclude_categories=["Cs", "Cc"]), max_size=12),
        st.sampled_from(["", " ", "a b", "\u200b", "\u202e", "e\u0301", "\U0001f600", "a\tb"]),
    )


def escaped(text: str, references: bool) -> bytes:
    """``text`` as an attribute value: escaped, with odd characters as references if asked."""
    out = text.replace("&", "&amp;").replace("<", "&lt;").replace('"', "&quot;")
    if references:
        out = "".join(c if c.isascii() and c.isprintable() else f"&#x{ord(c):x};" for c in out)
    return out.encode("utf-8", "surrogatepass")


# -- mutations --------------------------------------------------------------------------

Mutation = Callable[[Draw, bytes], tuple[bytes, str]]


def _position(draw: Draw, data: bytes) -> int:
    return int(draw(st.integers(0, len(data))))


def _pick(draw: Draw, spans: Sequence[Span]) -> Span | None:
    if not spans:
        return None
    return spans[draw(st.integers(0, len(spans) - 1))]


def flip_byte(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """XOR one byte with a drawn mask."""
    if not data:
        return data, "flip: empty"
    at = draw(st.integers(0, len(data) - 1))
    mask = draw(st.integers(1, 255))
    return data[:at] + bytes([data[at] ^ mask]) + data[at + 1 :], f"flip byte {at} ^ {mask:#x}"


#: Bytes worth inserting anywhere.
_INTERESTING = (
    b"<",
    b">",
    b"/",
    b"&",
    b"'",
    b'"',
    b"=",
    b"\x00",
    b"\x01",
    b"\xff",
    b"\xc3",
    b"\xed\xa0\x80",
    b"\xef\xbb\xbf",
    b"]]>",
    b"<!--",
    b"-->",
    b"<?",
    b"?>",
    b"<![CDATA[",
    b"\r",
    b"\t",
    b"\xe2\x80\xa8",
)


def insert_bytes(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Insert random or syntax-laden bytes at a drawn position."""
    at = _position(draw, data)
    payload = draw(st.sampled_from(_INTERESTING) | st.binary(min_size=1, max_size=4))
    return data[:at] + payload + data[at:], f"insert {payload!r} at {at}"


def delete_bytes(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Delete a short run of bytes."""
    at = _position(draw, data)
    length = draw(st.integers(1, 16))
    return data[:at] + data[at + length :], f"delete {data[at : at + length]!r} at {at}"


def truncate(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Cut the document at a drawn position."""
    at = _position(draw, data)
    return data[:at], f"truncate at {at}"


def delete_element(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Remove one element, its children with it."""
    span = _pick(draw, element_spans(data))
    if span is None:
        return data, "delete element: none"
    return data[: span.start] + data[span.end :], f"delete <{span.tag.decode()}> at {span.start}"


def duplicate_element(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Repeat one element right after itself."""
    span = _pick(draw, element_spans(data))
    if span is None:
        return data, "duplicate element: none"
    element = data[span.start : span.end]
    return (
        data[: span.end] + element + data[span.end :],
        f"duplicate <{span.tag.decode()}> at {span.start}",
    )


def delete_attribute(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Remove one attribute."""
    span = _pick(draw, attribute_spans(data))
    if span is None:
        return data, "delete attribute: none"
    return (
        data[: span.start] + data[span.end :],
        f"delete attribute {span.tag.decode()} at {span.start}",
    )


def duplicate_attribute(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Copy one attribute into its own start tag again, or into another element's."""
    span = _pick(draw, attribute_spans(data))
    if span is None:
        return data, "duplicate attribute: none"
    attribute = data[span.start : span.end]
    if draw(st.booleans()):
        return (
            data[: span.end] + attribute + data[span.end :],
            f"repeat attribute {span.tag.decode()} at {span.start}",
        )
    ends = start_tag_ends(data)
    if not ends:
        return data, "transplant attribute: no start tag"
    at, tag = ends[draw(st.integers(0, len(ends) - 1))]
    return (
        data[:at] + attribute + data[at:],
        f"copy attribute {attribute!r} into <{tag.decode()}> at {at}",
    )


def garbage_value(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Replace a whole attribute value (preferably a numeric one) with number garbage."""
    span = _pick(draw, numeric_attribute_spans(data) or attribute_spans(data))
    if span is None:
        return data, "garbage value: no attribute"
    value = escaped(draw(number_garbage()), references=False)
    start, end = span.value
    return data[:start] + value + data[end:], f"{span.tag.decode()}={value!r} at {span.start}"


def garbage_token(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Replace one number of a numeric attribute, or append numbers to it."""
    span = _pick(draw, numeric_attribute_spans(data))
    if span is None:
        return data, "garbage token: no numeric attribute"
    start, end = span.value
    tokens = data[start:end].split()
    garbage = escaped(draw(number_garbage()), references=False)
    if tokens and draw(st.booleans()):
        index = draw(st.integers(0, len(tokens) - 1))
        tokens[index] = garbage
    else:
        tokens.append(garbage)
    value = b" ".join(tokens)
    return data[:start] + value + data[end:], f"{span.tag.decode()}={value!r} at {span.start}"


def odd_name(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Give an attribute (a name, preferably) odd unicode or control characters."""
    spans = attribute_spans(data)
    names = [s for s in spans if s.tag in {b"name", b"class", b"childclass", b"model"}]
    span = _pick(draw, names or spans)
    if span is None:
        return data, "odd name: no attribute"
    text = draw(odd_text())
    value = (
        text.encode("utf-8")
        if draw(st.integers(0, 4)) == 0
        else escaped(text, references=draw(st.booleans()))
    )
    start, end = span.value
    return data[:start] + value + data[end:], f"{span.tag.decode()}={value!r} at {span.start}"


def _wrap(data: bytes, span: Span | None, opening: bytes, closing: bytes) -> bytes:
    if span is not None:
        return (
            data[: span.start] + opening + data[span.start : span.end] + closing + data[span.end :]
        )
    inner = opening + b'<geom size="0.1"/>' + closing
    worldbody = re.search(rb"<worldbody[^<>]*?>", data)
    if worldbody is not None:
        return data[: worldbody.end()] + inner + data[worldbody.end() :]
    root_end = data.rfind(b"</mujoco>")
    at = root_end if root_end >= 0 else len(data)
    return data[:at] + b"<worldbody>" + inner + b"</worldbody>" + data[at:]


#: Elements that may stand in a body, so that wrapping them in bodies stays valid MJCF.
_IN_BODY = {b"body", b"geom", b"site", b"frame", b"camera", b"light", b"inertial"}


def deep_bodies(draw: Draw, data: bytes, depth: int | None = None) -> tuple[bytes, str]:
    """Wrap an element of the kinematic tree in up to 600 nested bodies (or frames, or junk)."""
    n = depth if depth is not None else draw(st.integers(1, 600))
    tag = draw(st.sampled_from([b"body", b"frame", b"x"]))
    span = _pick(draw, [s for s in element_spans(data) if s.tag in _IN_BODY])
    opening, closing = b"<" + tag + b">", b"</" + tag + b">"
    where = f"<{span.tag.decode()}> at {span.start}" if span else "a new geom"
    return _wrap(data, span, opening * n, closing * n), f"wrap {where} in {n} <{tag.decode()}>"


def deep_defaults(draw: Draw, data: bytes, depth: int | None = None) -> tuple[bytes, str]:
    """Nest up to 600 default classes (a geom default innermost) just inside the root."""
    n = depth if depth is not None else draw(st.integers(1, 600))
    root = re.search(rb"<mujoco[^<>]*?>", data)
    at = root.end() if root is not None else 0
    opening = b"".join(b'<default class="fuzz%d">' % i for i in range(n))
    nested = b"<default>" + opening + b'<geom rgba="1 0 0 1"/>' + b"</default>" * (n + 1)
    return data[:at] + nested + data[at:], f"{n} nested default classes at {at}"


#: Encodings to declare: real ones, aliases, ones expat does not know, and made-up ones.
_ENCODINGS = (
    "UTF-8",
    "utf8",
    "ISO-8859-1",
    "latin-1",
    "US-ASCII",
    "cp1252",
    "koi8-r",
    "Shift_JIS",
    "UTF-16",
    "UTF-16LE",
    "UTF-16BE",
    "UTF-32",
    "utf-7",
    "x-unknown",
    "bogus",
    "",
    "rot13",
    "base64",
)


def declaration(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Put an XML declaration in front: lying about the encoding, or true after re-encoding."""
    encoding = draw(st.sampled_from(_ENCODINGS))
    body = re.sub(rb"^\s*<\?xml[^>]*\?>", b"", data)
    header = f'<?xml version="1.0" encoding="{encoding}"?>\n'
    kind = draw(st.sampled_from(["lying", "honest", "bom"]))
    if kind == "lying":
        return header.encode("ascii") + body, f"declare encoding {encoding!r}, keep bytes"
    if kind == "bom":
        bom = draw(
            st.sampled_from([b"\xef\xbb\xbf", b"\xff\xfe", b"\xfe\xff", b"\xff\xfe\x00\x00"])
        )
        return bom + header.encode("ascii") + body, f"BOM {bom!r}, declare {encoding!r}"
    text = header + body.decode("utf-8", "replace")
    try:
        encoded = text.encode(encoding, "xmlcharrefreplace")
    except (LookupError, UnicodeError):
        return header.encode("ascii") + body, f"declare unknown {encoding!r}"
    return encoded, f"re-encode as {encoding!r} and declare it"


#: Ampersands and references, well-formed or not.
_AMPERSANDS = (
    b"&",
    b"& ",
    b"&amp",
    b"&foo;",
    b"&#;",
    b"&#x;",
    b"&#0;",
    b"&#1;",
    b"&#xD800;",
    b"&#1114112;",
    b"&#x110000;",
    b"&#99999999999999999999;",
    b"&lt;",
    b"&#65;",
    b"&#x1F600;",
)


def ampersand(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Insert a bare ``&`` or an odd reference into an attribute value or anywhere."""
    spans = attribute_spans(data)
    if spans and draw(st.booleans()):
        span = spans[draw(st.integers(0, len(spans) - 1))]
        at = draw(st.integers(*span.value))
    else:
        at = _position(draw, data)
    payload = draw(st.sampled_from(_AMPERSANDS))
    return data[:at] + payload + data[at:], f"insert {payload!r} at {at}"


_JUNK = (
    b"x",
    b"<mujoco/>",
    b"<!-- after -->",
    b"<?pi after?>",
    b"\x00",
    b"</mujoco>",
    b"&",
    b"  \n",
    b"<a>",
    b"<![CDATA[x]]>",
    b"\xff\xfe",
)


def junk_after_root(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Append text, markup or bytes after the root element."""
    junk = draw(st.sampled_from(_JUNK) | st.binary(min_size=1, max_size=8))
    return data + junk, f"append {junk!r}"


_MARKUP = (
    b"<!-- c -->",
    b"<!---->",
    b"<?pi data?>",
    b"<![CDATA[x < y]]>",
    b"text",
    b"<unknown/>",
    b'<unknown a="1"><b/></unknown>',
    b"<body/>",
    b"<geom/>",
    b'<geom size="1"/>',
    b"<default/>",
    b"<worldbody/>",
    b'<include file="missing.xml"/>',
    b"<mujoco/>",
)


def insert_markup(draw: Draw, data: bytes) -> tuple[bytes, str]:
    """Insert a comment, processing instruction, CDATA, text or element after a tag."""
    ends = [m.end() for m in _TAG.finditer(data)]
    at = ends[draw(st.integers(0, len(ends) - 1))] if ends else _position(draw, data)
    markup = draw(st.sampled_from(_MARKUP))
    return data[:at] + markup + data[at:], f"insert {markup!r} at {at}"


#: Every mutation the general fuzzers draw from.
MUTATIONS: tuple[Mutation, ...] = (
    flip_byte,
    insert_bytes,
    delete_bytes,
    truncate,
    delete_element,
    duplicate_element,
    delete_attribute,
    duplicate_attribute,
    garbage_value,
    garbage_token,
    odd_name,
    deep_bodies,
    deep_defaults,
    declaration,
    ampersand,
    junk_after_root,
    insert_markup,
)


class Mutant:
    """A seed after some mutations: the input of one fuzz case.

    A plain class, so that hypothesis reports a failing case by its seed and its
    steps instead of printing all its bytes.

    Attributes:
        seed: The label of the seed.
        steps: What each mutation did, in order.
        data: The mutated bytes.

    """

    __slots__ = ("data", "seed", "steps")

    def __init__(self, seed: str, steps: tuple[str, ...], data: bytes) -> None:
        self.seed = seed
        self.steps = steps
        self.data = data

    def __repr__(self) -> str:
        steps = "".join(f"\n    {step}" for step in self.steps)
        return f"Mutant(seed={self.seed!r}, {len(self.data)} bytes, steps:{steps})"


@st.composite
def mutants(
    draw: Draw,
    seeds: st.SearchStrategy[Seed],
    mutations: Sequence[Mutation] = MUTATIONS,
    max_steps: int = 4,
) -> Mutant:
    """A seed drawn from ``seeds`` after one to ``max_steps`` drawn mutations."""
    seed = draw(seeds)
    data, steps = seed.data, []
    for mutation in draw(st.lists(st.sampled_from(mutations), min_size=1, max_size=max_steps)):
        data, step = mutation(draw, data)
        steps.append(step)
    return Mutant(seed.label, tuple(steps), data)


# -- minimal cases ----------------------------------------------------------------------


def _nested(depth: int, tag: bytes) -> bytes:
    opening, closing = b"<" + tag + b">", b"</" + tag + b">"
    return (
        b"<mujoco><worldbody>"
        + opening * depth
        + b'<geom size="1"/>'
        + closing * depth
        + b"</worldbody></mujoco>"
    )


def _geom(attributes: bytes) -> bytes:
    return b"<mujoco><worldbody><geom " + attributes + b"/></worldbody></mujoco>"


def _named(name: bytes) -> bytes:
    return (
        b'<mujoco><worldbody><body name="'
        + name
        + b'"><geom size="1"/></body></worldbody></mujoco>'
    )


#: One small input for each kind of failure the fuzzers found, checked on every run.
MINIMAL_CASES: dict[str, bytes] = {
    "number 1..2": _geom(b'size="1..2"'),
    "number 0x10": _geom(b'size="0x10"'),
    "number 0X1F in an int": _geom(b'size="1" contype="0X1F"'),
    "empty pos": _geom(b'size="1" pos=""'),
    "digit run": _geom(b'size="' + b"1" * 40 + b'x"'),
    "digit run in a list": _geom(b'size="1" pos="0 0 ' + b"1" * 40 + b'e"'),
    "unicode digits": _geom('size="\u0661\u0662"'.encode()),
    "nan": b'<mujoco><option impratio="nan"/></mujoco>',
    "nan in a vector": _geom(b'size="1" pos="0 nan 0"'),
    "1e999": _geom(b'size="1e999"'),
    "unknown encoding": b'<?xml version="1.0" encoding="x-unknown"?><mujoco/>',
    "codec that is no text encoding": b'<?xml version="1.0" encoding="base64"?><mujoco/>',
    "multi-byte encoding": b'<?xml version="1.0" encoding="utf-7"?><mujoco/>',
    "latin-1 declared, UTF-8 bytes": b'<?xml version="1.0" encoding="ISO-8859-1"?>'
    + _named("\u00e9".encode()),
    "UTF-16 declared, UTF-8 bytes": b'<?xml version="1.0" encoding="UTF-16"?><mujoco/>',
    "UTF-16 honest": '<?xml version="1.0" encoding="UTF-16"?><mujoco/>'.encode("utf-16"),
    "UTF-32 with a byte order mark": '<?xml version="1.0" encoding="UTF-32"?><mujoco><!-- c -->'
    "</mujoco>".encode("utf-32"),
    "UTF-32 without one": "<mujoco><!-- c --></mujoco>".encode("utf-32-le"),
    "BOM": b"\xef\xbb\xbf<mujoco/>",
    "whitespace before the declaration": b'  <?xml version="1.0"?><mujoco/>',
    "empty encoding declared": b'<?xml version="1.0" encoding=""?>' + _named(b"b"),
    "declaration without a space": b'<?xml version="1.0"encoding="UTF-8"?>' + _named(b"b"),
    "declaration without a version": b'<?xml encoding="UTF-8"?>' + _named(b"b"),
    "bare ampersand": _named(b"a&b"),
    "unknown entity": _named(b"a&foo;b"),
    "empty hex reference": _named(b"&#x;b"),
    "empty decimal reference": _named(b"&#;b"),
    "reference to a control character": _named(b"a&#1;b"),
    "raw control character": _named(b"a\x01b"),
    "less-than in a value": _named(b"a<b"),
    "tab in a name": _named(b"a\tb"),
    "line feed in a name": _named(b"a\nb"),
    "carriage return in the model name": b'<mujoco model="\r"/>',
    "odd unicode in a name": _named("e\u0301\u202e\U0001f600".encode()),
    "junk after the root": _named(b"b") + b"x<y/>",
    "second root": _named(b"b") + b"<mujoco/>",
    "no space between attributes": _geom(b'name="g"size="1"'),
    "unknown <!...> node in an element": b'<mujoco><!,- x --><worldbody><geom size="1"/>'
    b"</worldbody></mujoco>",
    "text before the root": b"x" + _named(b"b"),
    "> before the root": b">" + _named(b"b"),
    "]]> in text": b"<mujoco><worldbody>]]></worldbody></mujoco>",
    "-- in a comment": b"<mujoco><!-- a -- b --></mujoco>",
    "repeated attribute": b'<mujoco model="a" model="b"/>',
    "truncated": b'<mujoco><worldbody><geom size="1',
    "empty": b"",
    "bodies 496 deep": _nested(496, b"body"),
    "frames 2000 deep": _nested(2000, b"frame"),
    "unknown elements 2000 deep": _nested(2000, b"x"),
    "default classes 600 deep": b"<mujoco><default>"
    + b"".join(b'<default class="c%d">' % i for i in range(600))
    + b"</default>" * 601
    + b"</mujoco>",
}


# -- the case check ---------------------------------------------------------------------


class CaseTimeout(BaseException):
    """Raised by the alarm; a ``BaseException`` so that no ``except Exception`` swallows it."""


@contextlib.contextmanager
def time_limit(seconds: float) -> Iterator[None]:
    """Fail the enclosed block (an ``AssertionError``) when it runs longer than ``seconds``.

    Uses ``SIGALRM``, so it interrupts Python code and regular expressions, and
    reports a call into C (MuJoCo) that overran as soon as the call returns. The
    alarm rings again every second after the limit, in case the first
    :class:`CaseTimeout` landed where exceptions are swallowed (a garbage-collector
    callback, a ``__del__``, a broad ``except``); a block that ends after the
    alarm rang fails even if it swallowed every ring.
    """
    state = {"armed": True, "rang": False}

    def ring(_signum: int, _frame: FrameType | None) -> None:
        if state["armed"]:
            state["rang"] = True
            raise CaseTimeout

    previous = signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds, 1.0)
    try:
        yield
    except CaseTimeout:
        state["rang"] = True
    finally:
        state["armed"] = False
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    if state["rang"]:
        raise AssertionError(f"case took longer than {seconds} s")


@contextlib.contextmanager
def python_recursion_limit(limit: int = 1000) -> Iterator[None]:
    """Run the block under Python's default recursion limit, as a user's program does.

    Hypothesis raises the limit by 2000 frames around each test, which would hide
    a recursion that fails on deep models everywhere else.
    """
    previous = sys.getrecursionlimit()
    sys.setrecursionlimit(limit)
    try:
        yield
    finally:
        sys.setrecursionlimit(previous)


def _trim_traceback(error: BaseException, frames: int = 60) -> None:
    """Cut a runaway traceback (a ``RecursionError``'s) to its first ``frames`` frames."""
    tb = error.__traceback__
    for _ in range(frames):
        if tb is None:
            return
        tb = tb.tb_next
    if tb is not None:
        tb.tb_next = None


def _escaped_error(operation: str, error: Exception) -> AssertionError:
    _trim_traceback(error)
    detail = str(error)
    if len(detail) > 300:
        detail = detail[:300] + "..."
    return AssertionError(f"{operation} raised {type(error).__name__}, not an MjcfError: {detail}")


def load_outcome(data: bytes) -> Mujoco | MjcfError:
    """Property 1: ``loads(data)`` returns a model or raises an ``MjcfError``, nothing else."""
    try:
        return loads(data)
    except MjcfError as error:
        return error
    except Exception as error:
        raise _escaped_error("loads", error) from error


def _first_difference(expected: str, found: str) -> str:
    lines = difflib.unified_diff(expected.splitlines(), found.splitlines(), lineterm="", n=1)
    return "\n".join(list(lines)[:12])


def _must(operation: str, function: Callable[[], _T]) -> _T:
    """``function()``, which no exception at all may escape."""
    try:
        return function()
    except MjcfError as error:
        raise AssertionError(
            f"{operation} raised {type(error).__name__} on a model loads accepted: {error}"
        ) from error
    except Exception as error:
        raise _escaped_error(operation, error) from error


def _may(operation: str, function: Callable[[], _T]) -> _T | MjcfError:
    """``function()``, or the ``MjcfError`` it raised; no other exception may escape."""
    try:
        return function()
    except MjcfError as error:
        return error
    except Exception as error:
        raise _escaped_error(operation, error) from error


def json_copy(value: Any) -> Any:
    """``json.loads(json.dumps(value, allow_nan=False))``, without recursion.

    The standard library's encoder recurses, so it gives up on a dict 500 models
    deep that MuJoCo still compiles; this walks with an explicit stack.

    Raises:
        TypeError: A value JSON has no form for (a dict key that is not text, a custom object).
        ValueError: A NaN or an infinity.

    """
    root: list[Any] = [None]
    stack: list[tuple[Any, Any, Any]] = [(value, root, 0)]
    while stack:
        item, target, key = stack.pop()
        copy: Any
        if isinstance(item, dict):
            copy = {}
            for name, child in item.items():
                if not isinstance(name, str):
                    raise TypeError(f"keys must be str, not {type(name).__name__}")
                copy[name] = None
                stack.append((child, copy, name))
        elif isinstance(item, (list, tuple)):
            copy = [None] * len(item)
            stack.extend((child, copy, index) for index, child in enumerate(item))
        elif item is None or isinstance(item, (str, int)):
            copy = item
        elif isinstance(item, float):
            if not math.isfinite(item):
                raise ValueError(f"Out of range float values are not JSON compliant: {item!r}")
            copy = item
        else:
            raise TypeError(f"Object of type {type(item).__name__} is not JSON serializable")
        target[key] = copy
    return root[0]


def check_round_trips(model: Mujoco) -> str:
    """Property 2: a loaded model survives every serializer, equality and hashing.

    ``dumps`` and reading its text back must succeed and give an equal model
    with an equal hash; ``to_dict``/``from_dict`` (through strict JSON) and
    ``to_etree``/``from_etree`` may refuse with an ``MjcfError``, and when they
    do not they must give an equal model too.

    Returns:
        ``dumps(model)``.

    """
    text = _must("dumps(model)", lambda: dumps(model))
    again = _must("loads(dumps(model))", lambda: loads(text))
    rewritten = _must("dumps(loads(dumps(model)))", lambda: dumps(again))
    same = _must("loads(dumps(model)) == model", lambda: again == model)
    assert same, "loads(dumps(model)) != model:\n" + _first_difference(text, rewritten)
    hashes = _must("hash(model)", lambda: (hash(again), hash(model)))
    assert hashes[0] == hashes[1], "equal models hash differently"
    assert rewritten == text, "writing is not idempotent:\n" + _first_difference(text, rewritten)
    data = _may("to_dict(model)", lambda: to_dict(model))
    if not isinstance(data, MjcfError):
        strict = _must("JSON of to_dict(model)", lambda: json_copy(data))
        restored = _may("from_dict(to_dict(model))", lambda: from_dict(strict))
        if not isinstance(restored, MjcfError):
            same = _must("from_dict(to_dict(model)) == model", lambda: restored == model)
            assert same, "from_dict(json(to_dict(model))) != model"
    element = _may("to_etree(model)", lambda: to_etree(model))
    if not isinstance(element, MjcfError):
        rebuilt = _may("from_etree(to_etree(model))", lambda: from_etree(element))
        if not isinstance(rebuilt, MjcfError):
            same = _must("from_etree(to_etree(model)) == model", lambda: rebuilt == model)
            assert same, "from_etree(to_etree(model)) != model"
    return text


#: A numeric character reference.
_REFERENCE = re.compile(r"&#(?:x([0-9A-Fa-f]{1,8})|([0-9]{1,10}));")


def _carries(text: str) -> bool:
    """Whether XML 1.0 can carry every character of ``text``, references included."""
    if _NOT_XML.search(text):
        return False
    for match in _REFERENCE.finditer(text):
        code = int(match.group(1), 16) if match.group(1) else int(match.group(2))
        if code > 0x10FFFF or 0xD800 <= code <= 0xDFFF or _NOT_XML.match(chr(code)):
            return False
    return True


def mujoco_compiles(data: bytes) -> Any | None:
    """The model MuJoCo compiles from ``data`` as a string, or ``None`` if it does not.

    Only input that mjcf-model does not refuse by design goes to MuJoCo (see the
    behaviour guide): it must hold no character XML 1.0 cannot carry (control
    characters, raw or as references: no node can hold them), and declare no DTD
    (refused for safety). Everything else MuJoCo's parser (tinyxml2) reads, bytes
    that are not UTF-8, a bare ``&`` or junk after the root included, mjcf-model
    must read the same way. MuJoCo is given the bytes, as it reads a file.
    """
    text = data.decode("utf-8", "replace")  # a byte that is not UTF-8 is carried
    if not _carries(text) or "<!DOCTYPE" in text:
        return None
    try:
        return mujoco.MjModel.from_xml_string(data)
    except ValueError:
        return None


def check_referee(original: Any, outcome: Mujoco | MjcfError, written: str | None) -> None:
    """Property 3: what MuJoCo compiled (``original``), ``loads`` accepts, compiled the same."""
    if original is None:
        return
    assert isinstance(outcome, Mujoco), f"MuJoCo compiles the input but loads refused it: {outcome}"
    assert written is not None
    try:
        again = mujoco.MjModel.from_xml_string(encoded(written))
    except ValueError as error:
        raise AssertionError(
            f"MuJoCo compiles the input but not dumps(loads(input)): {error}"
        ) from None
    differences = model_differences(original, again)
    assert differences == [], f"the round trip compiles differently in {differences[:20]}"


def case_timeout() -> float:
    """The wall-clock limit of one case in seconds (``MJCF_FUZZ_TIMEOUT``, default 5)."""
    value = float(os.environ.get("MJCF_FUZZ_TIMEOUT", "5"))
    assert value > 0 and math.isfinite(value), "MJCF_FUZZ_TIMEOUT must be a positive number"
    return value


def check_case(mutant: Mutant) -> None:
    """Run the three properties on one mutant within :func:`case_timeout` seconds.

    MuJoCo's own time is not the library's: the input is compiled first, outside the
    limit, and the limit grows by that time for the round trip's compile (a fuzzed
    skybox 5476 texels wide takes MuJoCo 2.4 s a compile).
    """
    data = mutant.data
    started = time.perf_counter()
    original = mujoco_compiles(data)
    limit = case_timeout() + (time.perf_counter() - started)
    try:
        with time_limit(limit), python_recursion_limit():
            outcome = load_outcome(data)
            written = check_round_trips(outcome) if isinstance(outcome, Mujoco) else None
            check_referee(original, outcome, written)
    except CaseTimeout:  # the alarm rang while the limit was being lifted
        raise AssertionError(f"case took longer than {limit} s") from None
