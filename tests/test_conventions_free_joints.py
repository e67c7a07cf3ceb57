"""Free joints under another ``alignfree``: align written where auto, refused where it cannot be.

MuJoCo's ``alignfree`` aligns a free body (one with no child bodies) with its
inertial frame unless its free joint says ``align``. A ``<freejoint>`` that says
``align="auto"`` follows ``alignfree``, so the child's value is written on it; a
``<joint type="free">`` (its type written or given by a class) cannot say
``align``, so in a leaf body it is refused with what to do instead; in a body
with child bodies ``alignfree`` does not apply and it passes. MuJoCo, compiling
the child alone, referees.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from mjcf_model import Mujoco, compiled
from mjcf_model.errors import MjcfValueError
from mjcf_model.nodes.compiler import Compiler
from mjcf_model.transforms.composition.conventions import in_conventions
from mjcf_model.tree.traversal import with_children
from serializers import loads

REFUSAL = "^" + re.escape(
    "the parent's alignfree differs from the child's, and a <joint "
    'type="free"> cannot say which applies to it; write it as <freejoint>'
)


def _bodies_kept(child: Mujoco, parent: Mujoco) -> bool:
    """Whether the rewritten child compiles under the parent to the child's body frames."""
    converted = in_conventions(child, parent)
    found = compiled(with_children(converted, [*parent.children, *converted.children]))
    expected = compiled(child)
    return all(
        np.allclose(getattr(found, f), getattr(expected, f), rtol=1e-12, atol=1e-12)
        for f in ("body_pos", "body_quat", "body_ipos", "body_iquat", "geom_pos", "qpos0")
    )


def test_a_freejoint_saying_align_auto_keeps_the_child_alignment() -> None:
    """A <freejoint align="auto"> gets the child's alignfree: the body frame is kept."""
    child = loads(
        '<mujoco><compiler alignfree="true"/><worldbody><body pos="1 0 0">'
        '<freejoint align="auto"/><geom size=".1" pos=".2 0 0"/></body></worldbody></mujoco>'
    )
    parent = loads("<mujoco/>")
    unconverted = with_children(child, [c for c in child.children if not isinstance(c, Compiler)])
    assert not np.allclose(compiled(unconverted).body_pos, compiled(child).body_pos)
    assert _bodies_kept(child, parent)


def test_a_free_joint_with_child_bodies_passes() -> None:
    """A <joint type="free"> in a body with child bodies is not aligned: it compiles the same."""
    child = loads(
        '<mujoco><compiler alignfree="true"/><worldbody><body pos="1 0 0">'
        '<joint type="free"/><geom size=".1" pos=".2 0 0"/>'
        '<body pos="0 1 0"><geom size=".1"/></body></body></worldbody></mujoco>'
    )
    assert _bodies_kept(child, loads("<mujoco/>"))


def test_a_free_joint_in_a_leaf_body_is_refused_with_what_to_write() -> None:
    """A leaf body's <joint type="free"> is refused: write it as <freejoint>."""
    child = loads(
        '<mujoco><compiler alignfree="true"/><worldbody><body pos="1 0 0">'
        '<joint type="free"/><geom size=".1" pos=".2 0 0"/></body></worldbody></mujoco>'
    )
    with pytest.raises(MjcfValueError, match=REFUSAL + "$"):
        in_conventions(child, loads("<mujoco/>"))


def test_a_free_type_from_a_childclass_is_refused() -> None:
    """A joint made free by its body's childclass is refused like one that says so."""
    child = loads(
        '<mujoco><compiler alignfree="true"/><default><default class="loose">'
        '<joint type="free"/></default></default><worldbody>'
        '<body pos="1 0 0" childclass="loose"><joint/><geom size=".1" pos=".2 0 0"/></body>'
        "</worldbody></mujoco>"
    )
    with pytest.raises(MjcfValueError, match=REFUSAL + "$"):
        in_conventions(child, loads("<mujoco/>"))
