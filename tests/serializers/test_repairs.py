"""Tests of ``mjcf_model.serializers.repairs``."""

from __future__ import annotations

import pytest

from mjcf_model import (
    Comment,
    MjcfSyntaxError,
)
from mjcf_model.serializers import dumps, loads
from tests.support.oracles import _compiled, _round_trips_like_mujoco

# -- Hostile and broken input: no hang, no stray exception, and MuJoCo decides what loads. -----
#
# Each test pins one cause found by fuzzing. MuJoCo is the referee: where it
# compiles a file, we load it and write it back so that it compiles identically.


# -- bytes and markup as MuJoCo reads them ---------------------------------------------


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
