"""The parts ``compose`` attaches, read from its words: each file, prefix, point and placement.

A part is written ``FILE[:PREFIX][@NAME]``; the placement words that follow it
(``pos=X,Y,Z``, then ``quat=W,X,Y,Z`` or ``euler=A,B,C``) place that part, so a
shell line reads left to right and negative numbers need no quoting:

>>> [part.placement() for part in parts_of(["cup.xml:a_", "pos=0,-1,0", "cup.xml:b_"])]
[{'pos': (0.0, -1.0, 0.0)}, {}]
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence

import attrs

from mjcf_model.errors import MjcfValueError
from mjcf_model.tools.cli.common import STDIO
from mjcf_model.values.reading import floats_from_text

__all__ = ["PLACEMENT_FORM", "Part", "parts_of", "split_part"]

#: Each placement word's key, the numbers it holds, and how they are written.
_WORDS = {"pos": "X,Y,Z", "quat": "W,X,Y,Z", "euler": "A,B,C"}
#: The placement words a part may be followed by, as ``--help`` shows them.
PLACEMENT_FORM = "[pos=X,Y,Z] [quat=W,X,Y,Z | euler=A,B,C]"


@attrs.frozen(kw_only=True)
class Part:
    """One part: its file, the prefix of its names, its attach point and its placement."""

    #: The word the part was written as (named in error messages).
    word: str
    #: The model's file (``-``: standard input).
    path: str
    #: Put before every name the part declares.
    prefix: str = ""
    #: The body, frame or site it is attached at (``None``: ``--at``, else the world).
    at: str | None = None
    #: Where the part's world is placed, relative to the attach point.
    pos: tuple[float, ...] | None = None
    #: Its orientation, as a quaternion (w, x, y, z).
    quat: tuple[float, ...] | None = None
    #: Its orientation as Euler angles, in the base model's ``<compiler>`` units and sequence.
    euler: tuple[float, ...] | None = None

    def placement(self) -> dict[str, tuple[float, ...]]:
        """The keywords of :func:`mjcf_model.attach` that place this part (only those given).

        Examples:
            >>> Part(word="a.xml", path="a.xml", euler=(0, 0, 90)).placement()
            {'euler': (0, 0, 90)}

        """
        given = {"pos": self.pos, "quat": self.quat, "euler": self.euler}
        return {key: value for key, value in given.items() if value is not None}


def split_part(argument: str) -> tuple[str, str, str | None]:
    """``FILE[:PREFIX][@NAME]`` as ``(file, prefix, name)``.

    The file is the longest start of ``argument`` that names an existing file (so
    prefixes and names may hold ``/`` and file names ``:`` or ``@``); when none
    does, the first mark after the file name's ``.xml`` ends it.

    Examples:
        >>> split_part("robots/arm.xml:left/@left_mount"), split_part("arm.xml")
        (('robots/arm.xml', 'left/', 'left_mount'), ('arm.xml', '', None))

    """
    if argument == STDIO or os.path.exists(argument):
        return argument, "", None
    cuts = [i for i, char in enumerate(argument) if char in ":@"]
    found = [i for i in cuts if os.path.isfile(argument[:i])]
    if not found:  # no such file: cut after the file name's ".xml", else at the first mark
        after = argument.rfind(".xml") + 4 if ".xml" in argument else 0
        found = [min((i for i in cuts if i >= after), default=len(argument))]
    path, rest = argument[: found[-1]], argument[found[-1] :]
    if rest.startswith(":"):
        prefix, _, name = rest[1:].partition("@")
    else:
        prefix, name = "", rest[1:]
    return path, prefix, name or None


def parts_of(words: Sequence[str]) -> list[Part]:
    """The parts ``words`` name, each with the placement words that follow it.

    A word that starts with ``pos=``, ``quat=`` or ``euler=`` places the part
    before it (a model file named so is written ``./pos=...``); its numbers are
    separated by commas (or spaces, quoted).

    Raises:
        MjcfValueError: A placement word comes before any part, or is given twice
            for one part, holds the wrong count of numbers or something else than
            finite numbers, or a part has both ``quat=`` and ``euler=``; the
            message names the part and the form expected.

    Examples:
        >>> [part] = parts_of(["arm.xml:r_@mount", "pos=1,0,0", "euler=0,0,-90"])
        >>> part.at, part.pos, part.euler
        ('mount', (1.0, 0.0, 0.0), (0.0, 0.0, -90.0))

    """
    words_and_placements: list[tuple[str, dict[str, tuple[float, ...]]]] = []
    for word in words:
        key, mark, text = word.partition("=")
        if not mark or key not in _WORDS:
            words_and_placements.append((word, {}))
            continue
        if not words_and_placements:
            raise MjcfValueError(
                f"the placement {word!r} comes before any part; write it after the PART it places"
            )
        part, placement = words_and_placements[-1]
        if key in placement:
            raise MjcfValueError(f"part {part!r}: {key}= is given twice; give it once")
        placement[key] = _numbers(part, key, text)
        if "quat" in placement and "euler" in placement:
            raise MjcfValueError(f"part {part!r} has both quat= and euler=; give one orientation")
    return [_part(word, placement) for word, placement in words_and_placements]


def _part(word: str, placement: dict[str, tuple[float, ...]]) -> Part:
    """The part written ``word``, placed by ``placement``."""
    path, prefix, at = split_part(word)
    pos, quat, euler = (placement.get(key) for key in _WORDS)
    return Part(word=word, path=path, prefix=prefix, at=at, pos=pos, quat=quat, euler=euler)


def _numbers(part: str, key: str, text: str) -> tuple[float, ...]:
    """The numbers of ``part``'s placement word ``key=text``, or the error saying what is wrong."""
    count = len(_WORDS[key].split(","))
    expected = f"{key}={_WORDS[key]} ({count} numbers, separated by commas)"
    try:
        numbers = floats_from_text(count, count, text.replace(",", " "))
    except MjcfValueError as error:
        raise MjcfValueError(
            f"part {part!r}: {key}={text} is not {expected}: {error.detail}"
        ) from None
    if not all(map(math.isfinite, numbers)):
        raise MjcfValueError(
            f"part {part!r}: {key}={text} is not {expected}: the numbers must be finite"
        )
    return numbers
