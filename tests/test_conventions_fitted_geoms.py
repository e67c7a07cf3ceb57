"""A geom fitted to a mesh refuses another ``fitaabb``; every other geom passes.

MuJoCo sizes a primitive geom that names a ``mesh`` from the mesh's box or
ellipsoid as ``fitaabb`` says, so a child whose ``fitaabb`` differs from the
parent's cannot keep such a geom's size: the conversion refuses, naming the geom,
the mesh and what to do. A ``mesh`` or ``sdf`` geom is not fitted, and nothing is
refused when ``fitaabb`` is the same. MuJoCo, compiling the child alone, referees.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from mjcf_model import Mujoco, compiled
from mjcf_model.errors import MjcfValueError
from mjcf_model.transforms.composition.conventions import in_conventions
from mjcf_model.tree.traversal import with_children
from serializers import loads

MESH = '<asset><mesh name="wedge" vertex="0 0 0 1 0 0 0 2 0 0 0 3 1 1 1"/></asset>'


def _child(compiler: str, body: str, defaults: str = "") -> Mujoco:
    return loads(
        f"<mujoco><compiler {compiler}/>{MESH}<default>{defaults}</default>"
        f'<worldbody><body name="holder"><joint name="hinge"/>{body}</body></worldbody></mujoco>'
    )


def _same_geoms(child: Mujoco, parent: Mujoco) -> bool:
    """Whether the rewritten child compiles under the parent to the child's geoms."""
    converted = in_conventions(child, parent)
    found = compiled(with_children(converted, [*parent.children, *converted.children]))
    expected = compiled(child)
    return all(
        np.allclose(getattr(found, f), getattr(expected, f), rtol=1e-12, atol=1e-12)
        for f in ("geom_type", "geom_size", "geom_pos", "geom_quat", "body_mass")
    )


def _refusal(geom: str, mesh: str) -> str:
    return (
        "^the parent's fitaabb differs from the child's, and geom "
        + re.escape(f"{geom} is fitted to mesh {mesh!r}: ")
        + re.escape("its size would change; give the two models the same fitaabb")
        + "$"
    )


def test_a_named_fitted_geom_is_refused_by_name() -> None:
    """The refusal names the fitted geom and its mesh and says to give the same fitaabb."""
    child = _child('fitaabb="true"', '<geom name="fitted" type="box" mesh="wedge"/>')
    parent = loads("<mujoco/>")
    under_parent = _child('fitaabb="false"', '<geom name="fitted" type="box" mesh="wedge"/>')
    assert not np.allclose(compiled(under_parent).geom_size, compiled(child).geom_size)
    with pytest.raises(MjcfValueError, match=_refusal("fitted", "wedge")):
        in_conventions(child, parent)


def test_an_unnamed_fitted_geom_is_refused_as_unnamed() -> None:
    """An unnamed fitted geom is called (unnamed) in the refusal."""
    child = _child('fitaabb="true"', '<geom type="capsule" mesh="wedge"/>')
    with pytest.raises(MjcfValueError, match=_refusal("(unnamed)", "wedge")):
        in_conventions(child, loads("<mujoco/>"))


def test_a_mesh_from_a_childclass_makes_a_fitted_geom() -> None:
    """A box geom whose mesh comes from its body's childclass is fitted: refused."""
    child = _child(
        'fitaabb="true"',
        '<body name="inner" childclass="shaped"><geom name="boxed" type="box"/></body>',
        '<default class="shaped"><geom mesh="wedge"/></default>',
    )
    with pytest.raises(MjcfValueError, match=_refusal("boxed", "wedge")):
        in_conventions(child, loads("<mujoco/>"))


def test_a_mesh_type_from_a_childclass_is_not_fitted() -> None:
    """A geom a childclass makes type="mesh" is not fitted: it compiles as the child alone."""
    child = _child(
        'fitaabb="true"',
        '<body name="inner" childclass="shaped"><geom name="shaped" mesh="wedge"/></body>',
        '<default class="shaped"><geom type="mesh"/></default>',
    )
    assert _same_geoms(child, loads("<mujoco/>"))


def test_an_sdf_geom_with_a_mesh_is_not_fitted() -> None:
    """An sdf geom that names a mesh is not fitted: it compiles as the child alone."""
    child = _child('fitaabb="true"', '<geom name="field" type="sdf" mesh="wedge"/>')
    assert _same_geoms(child, loads("<mujoco/>"))


def test_a_fitted_geom_passes_when_fitaabb_is_the_same() -> None:
    """Only fitaabb can refuse a fitted geom: another setting differing converts it."""
    child = _child('fitaabb="true" angle="radian"', '<geom name="fitted" type="box" mesh="wedge"/>')
    assert _same_geoms(child, loads('<mujoco><compiler fitaabb="true"/></mujoco>'))
