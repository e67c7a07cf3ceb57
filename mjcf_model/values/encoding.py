r"""Bytes that are not UTF-8: read as MuJoCo reads them, and written back as they were.

MuJoCo's XML reader passes every byte of a name, a comment or a value through, so a
file written in Latin-1 (``caf\xe9``) compiles. The library reads such a byte as
Python's ``surrogateescape`` codec does: byte ``0xE9`` becomes the lone surrogate
``"\udce9"`` in the text, names and comments read; writing encodes it back to the byte
(:func:`encoded`), so the file is written back byte for byte and MuJoCo is handed the
bytes it would have read.

expat, the reader underneath, refuses such bytes; the reader gives it the text with
each escaped byte as a placeholder from Unicode's private use plane 16
(:func:`with_placeholders`), and turns the placeholders back into escapes in what it
read (:func:`without_placeholders`). A file that holds such a placeholder itself
cannot be read this way (none is known to).

Examples:
    >>> text = with_placeholders(b"<a b='caf\xe9'/>")
    >>> without_placeholders(text.decode())
    "<a b='caf\udce9'/>"
    >>> encoded("caf\udce9")
    b'caf\xe9'
    >>> with_placeholders(b"<a b='caf\xc3\xa9'/>") is None  # UTF-8: nothing to escape
    True

"""

from __future__ import annotations

import re

__all__ = [
    "encoded",
    "escaped_bytes",
    "for_mujoco",
    "with_placeholders",
    "without_placeholders",
]

#: Where the placeholder of byte ``b`` stands while expat reads: ``_PLACEHOLDER + b``.
_PLACEHOLDER = 0x10FE00

#: One escaped byte: a character that stands for a byte that is not UTF-8
#: (``surrogateescape``'s), which :data:`mjcf_model.values.kinds.NOT_XML_CHARACTER` allows.
_ESCAPE = re.compile("[\udc80-\udcff]")

_TO_PLACEHOLDER = {0xDC00 + byte: _PLACEHOLDER + byte for byte in range(0x80, 0x100)}
_FROM_PLACEHOLDER = {value: key for key, value in _TO_PLACEHOLDER.items()}


def with_placeholders(raw: bytes) -> bytes | None:
    r"""``raw`` as UTF-8 expat reads, each byte that is not UTF-8 as its placeholder.

    Returns:
        ``None`` when ``raw`` is UTF-8 already, or when it holds a placeholder itself
        (it then cannot be read back exactly: the reader refuses the bytes).

    Examples:
        >>> with_placeholders(b"\xe9").decode() == chr(0x10FEE9)
        True

    """
    if raw.isascii():
        return None
    try:
        raw.decode("utf-8")
    except UnicodeDecodeError:
        text = raw.decode("utf-8", "surrogateescape")
    else:
        return None
    if any(chr(code) in text for code in _FROM_PLACEHOLDER):
        return None
    return text.translate(_TO_PLACEHOLDER).encode("utf-8")


def without_placeholders(text: str) -> str:
    r"""``text`` read from :func:`with_placeholders`' bytes, each placeholder its escape again.

    Examples:
        >>> without_placeholders("b" + chr(0x10FEE9))
        'b\udce9'

    """
    return text.translate(_FROM_PLACEHOLDER)


def encoded(text: str) -> bytes:
    r"""``text`` as the bytes of a file: UTF-8, each escaped byte the byte it stands for.

    Examples:
        >>> encoded("é\udce9")
        b'\xc3\xa9\xe9'

    """
    return text.encode("utf-8", "surrogateescape")


def for_mujoco(text: str) -> str | bytes:
    r"""``text`` as MuJoCo's Python bindings take it: the text, or its bytes if it escapes any.

    The bindings refuse a string with lone surrogates, and read bytes as MuJoCo reads
    a file.

    Examples:
        >>> for_mujoco("<mujoco/>"), for_mujoco("<mujoco model='\udce9'/>")
        ('<mujoco/>', b"<mujoco model='\xe9'/>")

    """
    return encoded(text) if escaped_bytes(text) else text


def escaped_bytes(text: str) -> list[int]:
    r"""The bytes ``text`` escapes, in order (none for text read from UTF-8).

    Examples:
        >>> escaped_bytes("caf\udce9 \udcff"), escaped_bytes("café")
        ([233, 255], [])

    """
    if text.isascii():
        return []
    return [ord(c) - 0xDC00 for c in _ESCAPE.findall(text)]
