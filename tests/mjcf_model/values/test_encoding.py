"""Tests of ``mjcf_model.values.encoding``: bytes that are not UTF-8, read and written back."""

from __future__ import annotations

import mujoco
import pytest

from mjcf_model import compiled, dumps, loads
from mjcf_model.bridge.compare import model_differences
from mjcf_model.values.encoding import (
    encoded,
    escaped_bytes,
    for_mujoco,
    with_placeholders,
    without_placeholders,
)


@pytest.mark.parametrize("byte", range(0x80, 0x100), ids=lambda byte: f"0x{byte:02X}")
def test_every_byte_that_is_not_utf8_alone_reads_and_writes_back(byte: int) -> None:
    """Each of the 128 high bytes, alone in a name and a comment, as MuJoCo reads it.

    The file text comes back byte for byte, and compiles as MuJoCo compiles the file.
    """
    data = (
        b"<mujoco><!-- a"
        + bytes([byte])
        + b' --><worldbody><geom name="g'
        + bytes([byte])
        + b'" size="1"/></worldbody></mujoco>'
    )
    model = loads(data)
    assert model.worldbody.geoms[0].name == "g" + chr(0xDC00 + byte)
    assert encoded(dumps(model)) == data
    assert escaped_bytes(dumps(model)) == [byte, byte]
    assert model_differences(compiled(model), mujoco.MjModel.from_xml_string(data)) == []


def test_placeholders_stand_in_one_for_one_and_utf8_needs_none() -> None:
    """Every escaped byte has its own placeholder; UTF-8 and ASCII text are left alone."""
    raw = bytes(range(0x80, 0x100)) + "é".encode()
    placeheld = with_placeholders(raw)
    assert placeheld is not None
    text = without_placeholders(placeheld.decode("utf-8"))
    assert text == raw.decode("utf-8", "surrogateescape") and encoded(text) == raw
    assert with_placeholders("é".encode()) is None and with_placeholders(b"<a/>") is None
    assert with_placeholders(chr(0x10FE80).encode() + b"\x80") is None


def test_mujoco_is_given_bytes_only_for_text_that_escapes_some() -> None:
    """The bindings refuse lone surrogates: such text goes as its bytes."""
    assert for_mujoco("<mujoco model='é'/>") == "<mujoco model='é'/>"
    assert for_mujoco("<mujoco model='\udce9'/>") == b"<mujoco model='\xe9'/>"
    assert escaped_bytes("plain") == [] and escaped_bytes("é\udc80") == [0x80]
