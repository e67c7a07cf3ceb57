"""The complete scaling oracle: every compiled field has its expected change, MuJoCo compiles both.

:func:`scaled_model_problems` multiplies each float array of the original model
by its kind's factor (:data:`mjcf_model.bridge.scaled_fields.FLOAT_FIELDS`) and requires the
scaled model's array to match; every other array and size, and the ``opt``,
``stat`` and ``vis`` structs, must be unchanged, but for the few stated here.
"""

from __future__ import annotations

from collections.abc import Collection
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from mjcf_model.bridge.compare import (
    compile_text_beside,
    model_differences,
    model_fields,
    path_fields,
)
from mjcf_model.bridge.scaled_fields import FLOAT_FIELDS, float_fields
from mjcf_model.serializers import dumps, load, loads
from mjcf_model.transforms.scaling.transform import MassPolicy, scaled
from tests.conftest import FIXTURES, MUJOCO_VERSION

__all__ = ["MESH_ARRAYS_COMPARABLE", "scaled_model_problems"]

#: Whether the arrays MuJoCo computes from a mesh's principal frame are comparable one
#: by one. Before 4.0 MuJoCo picks those axes so that a scaled nearly symmetric mesh
#: can come out turned or perturbed in the eighth digit (measured on MuJoCo 3.9.0:
#: bounding boxes off by up to 10% of the extent on 28 corpus models, inertias
#: permuted with equal traces); there mesh vertices and frames, the sizes, boxes
#: and frames of mesh geoms and the bounding volumes are left out, and body inertias
#: are compared by their traces; so are the normals, which are in that frame, and
#: whether a geom's frame is its body's.
MESH_ARRAYS_COMPARABLE = MUJOCO_VERSION >= (4, 0)

#: Integer arrays of the bounding volume hierarchies and octrees: MuJoCo splits
#: them where boxes tie, which scaled floats can reorder; when they differ, their
#: boxes are not compared one by one (the geoms' and meshes' own boxes still are).
_TREES = ("bvh_", "oct_")

#: The struct fields with a length or a mass in them (every other one is unchanged).
_STRUCTS = {"opt.o_margin": "s", "stat.center": "s"}
_STRUCTS_MASS = {"stat.meanmass"}
#: Struct fields MuJoCo derives: the mean inertia from inertias and armatures; the
#: extent and mean body size are lengths, but MuJoCo falls back to fixed values
#: when there is little to measure (measured on MuJoCo 4.0: extent 2 and 0.4 and
#: mean size 0.2 and 1e-5 on corpus models that stay put under scaling); they are
#: checked through the positions and sizes they are measured from.
_STRUCTS_DERIVED = {"stat.meaninertia", "stat.extent", "stat.meansize"}

_MESH_FIELDS = frozenset(
    {
        "mesh_vert",
        "mesh_normal",
        "mesh_polynormal",
        "mesh_facenormal",
        "mesh_pos",
        "mesh_quat",
        "body_iquat",
        "body_inertia",
        "bvh_aabb",
        "oct_aabb",
        "geom_sameframe",
    }
)
_MESH_GEOM_FIELDS = frozenset({"geom_size", "geom_aabb", "geom_rbound", "geom_quat"})

#: Whether a frame is its body's frame (1) or inertial frame (2), or shares only its
#: rotation (3, 4): MuJoCo decides within an absolute tolerance, so an offset near it
#: can cross it when scaled (a drawn mesh geom 0.6 micrometres from the inertial
#: frame was "same" (2), and 1.1 micrometres away at twice the size, 4).
_SAMEFRAME = ("body_sameframe", "geom_sameframe", "site_sameframe")
#: The pairs of flags an offset crossing the tolerance turns into each other.
_POSITION_FLIPS = (frozenset({1, 3}), frozenset({2, 4}))
#: MuJoCo's tolerance: a frame is at another when no coordinate of the offset reaches
#: it (measured on 3.9 and 4.0: 0.9 micrometres along x or along x and y is "same",
#: 1 micrometre is not).
_SAME_POSITION = 1e-6


def _mass_factor(factor: float, mass: str) -> float:
    return factor**3 if mass == "volume" else 1.0


def _tree_arrays_equal(original: Any, changed: Any, prefix: str) -> bool:
    names = [n for n in model_fields() if n.startswith(prefix) and n != prefix + "aabb"]
    return not model_differences(
        original, changed, ignore=frozenset(model_fields()) - frozenset(names)
    )


def _springdamper_rows(original: Any, changed: Any, field: str) -> np.ndarray:
    """Joints (or dofs) whose stiffness or damping MuJoCo derived from ``springdamper``.

    MuJoCo computes them from the dof's inverse weight at ``qpos0``
    (``dof_invweight0``), so they follow its change: their product with it stays.
    """
    before, after = getattr(original, field), getattr(changed, field)
    dofs = original.jnt_dofadr if field.startswith("jnt_") else np.arange(original.nv)
    old, new = original.dof_invweight0[dofs], changed.dof_invweight0[dofs]
    ratio = old / np.where(new == 0, 1, new)
    return np.isclose(after, before * ratio, rtol=1e-6, atol=0) & (after != before)


def _expected(original: Any, field: str, factor: float, mass: float) -> np.ndarray | None:
    multiplier = FLOAT_FIELDS[field]
    if multiplier is None:
        return None
    before = np.asarray(getattr(original, field), dtype=float)
    if before.size == 0:
        return before
    factors = np.asarray(multiplier(original, factor, mass))
    if before.ndim == 1 and factors.ndim == 2:  # per-row factors of a one-column field
        factors = factors[:, 0]
    return before * factors


def _skipped_rows(original: Any, field: str) -> np.ndarray | None:
    """Rows left out before MuJoCo 4.0 (see :data:`MESH_ARRAYS_COMPARABLE`)."""
    if MESH_ARRAYS_COMPARABLE or field not in _MESH_GEOM_FIELDS:
        return None
    import mujoco

    return np.asarray(original.geom_type == mujoco.mjtGeom.mjGEOM_MESH)


def _float_problem(
    original: Any, changed: Any, field: str, factor: float, mass: float, rtol: float
) -> str | None:
    expected = _expected(original, field, factor, mass)
    after = np.asarray(getattr(changed, field), dtype=float)
    if expected is None:
        return None
    if expected.shape != after.shape:
        return f"{field}: shape {after.shape}, expected {expected.shape}"
    close = np.isclose(after, expected, rtol=rtol, atol=0) | (after == expected)
    if field in ("jnt_stiffness", "dof_damping"):
        close |= _springdamper_rows(original, changed, field)
    skipped = _skipped_rows(original, field)
    if skipped is not None:
        close[skipped] = True
    if bool(np.all(close)):
        return None
    where = np.argwhere(~close)[0]
    index = tuple(int(i) for i in where)
    return (
        f"{field}{list(index)}: {after[index]!r}, expected {expected[index]!r} "
        f"(originally {np.asarray(getattr(original, field))[index]!r})"
    )


def _offset(original: Any, field: str, index: int, flags: frozenset[int]) -> float:
    """The largest coordinate of the offset a ``field`` flag compares with the tolerance."""
    kind = field.removesuffix("_sameframe")
    if kind == "body":
        return float(np.max(np.abs(original.body_ipos[index])))
    position = getattr(original, f"{kind}_pos")[index]
    if flags == _POSITION_FLIPS[1]:
        position = position - original.body_ipos[getattr(original, f"{kind}_bodyid")[index]]
    return float(np.max(np.abs(position)))


def _sameframe_problems(
    original: Any, changed: Any, factor: float, left_out: Collection[str]
) -> list[str]:
    """The ``*_sameframe`` flags that changed other than by an offset crossing the tolerance.

    An offset crosses it when scaling by ``factor`` carries its largest coordinate from
    one side of the tolerance to the other (1% slack for MuJoCo's own arithmetic).
    """
    low, high = sorted((_SAME_POSITION, _SAME_POSITION / factor))
    problems = []
    for field in (f for f in _SAMEFRAME if f not in left_out):
        before, after = getattr(original, field), getattr(changed, field)
        for index in np.flatnonzero(before != after):
            flags = frozenset({int(before[index]), int(after[index])})
            crossed = flags in _POSITION_FLIPS and (
                0.99 * low <= _offset(original, field, index, flags) <= 1.01 * high
            )
            if not crossed:
                problems.append(f"{field}[{index}]: {before[index]} became {after[index]}")
    return problems


def _struct_problems(
    original: Any, changed: Any, factor: float, mass: float, *, frames_flipped: bool
) -> list[str]:
    problems = []
    for name in [*_STRUCTS, *_STRUCTS_MASS]:
        struct, field = name.split(".")
        before = np.asarray(getattr(getattr(original, struct), field), dtype=float)
        after = np.asarray(getattr(getattr(changed, struct), field), dtype=float)
        expected = before * (factor if name in _STRUCTS else mass)
        rtol, atol = 1e-9, 0.0
        if name == "stat.center" and original.nmesh and not MESH_ARRAYS_COMPARABLE:
            # before 4.0 the centre comes from mesh boxes, which move in the 6th digit
            rtol, atol = 1e-5, 1e-5 * float(changed.stat.extent)
        if name == "stat.center" and frames_flipped:
            # a frame taken as its body's now is not (or the other way): MuJoCo places
            # the element at that frame, up to the offset that crossed the tolerance
            atol = _SAME_POSITION * max(factor, 1.0)
        if not np.allclose(after, expected, rtol=rtol, atol=atol):
            problems.append(f"{name}: {after!r}, expected {expected!r}")
    return problems


def scaled_model_problems(
    original: Any,
    changed: Any,
    factor: float,
    *,
    mass: str = "keep",
    rtol: float = 1e-9,
    ignore: Collection[str] = (),
) -> list[str]:
    """What keeps ``changed`` from being ``original`` uniformly scaled by ``factor``.

    Every float array must be its classified multiple of the original's (within
    ``rtol``), every other array and size and struct field identical, but for
    derived fields, file paths, and bounding-volume trees split differently.
    ``mass`` is the policy ``scaled`` was given; under ``"volume"`` masses are
    expected to grow by ``factor**3`` (models without shell inertia). The fields
    in ``ignore`` are not compared (a caller's other oracle checks them).
    """
    masses = _mass_factor(factor, mass)
    floats = [f for f in float_fields(original) if f in FLOAT_FIELDS]
    unclassified = [f"{f}: not classified" for f in float_fields(original) if f not in FLOAT_FIELDS]
    left_out: set[str] = set(ignore)
    for prefix in _TREES:
        if not _tree_arrays_equal(original, changed, prefix):
            left_out |= {f for f in model_fields() if f.startswith(prefix)}
    if not MESH_ARRAYS_COMPARABLE:
        left_out |= _MESH_FIELDS
    ignored = frozenset({*floats, *path_fields(), *left_out, *_SAMEFRAME})
    struct_names = {*_STRUCTS, *_STRUCTS_MASS, *_STRUCTS_DERIVED}
    problems = unclassified + [
        f"{name}: changed"
        for name in model_differences(original, changed, ignore=ignored)
        if name not in struct_names
    ]
    for field in floats:
        if field not in left_out:
            problem = _float_problem(original, changed, field, factor, masses, rtol)
            problems += [] if problem is None else [problem]
    flipped = any(not np.array_equal(getattr(original, f), getattr(changed, f)) for f in _SAMEFRAME)
    problems += _struct_problems(original, changed, factor, masses, frames_flipped=flipped)
    problems += _sameframe_problems(original, changed, factor, left_out)
    if not MESH_ARRAYS_COMPARABLE:
        traces = np.sum(changed.body_inertia, axis=1), np.sum(original.body_inertia, axis=1)
        if not np.allclose(traces[0], masses * factor**2 * traces[1], rtol=1e-9, atol=0):
            problems.append("body_inertia traces")
    return problems


def compiled_pair(text: str, factor: float) -> tuple[mujoco.MjModel, mujoco.MjModel]:
    """MuJoCo's compilation of ``text`` and of it scaled by ``factor``."""
    original = mujoco.MjModel.from_xml_string(text)
    return original, mujoco.MjModel.from_xml_string(dumps(scaled(loads(text), factor)))


#: The scaling fixtures.
SCALING_FIXTURES = FIXTURES / "scaling"


#: What the complete oracle leaves to other checks, per fixture: an SDF mesh scales
#: through its plugin's settings (checked below) instead of ``scale``.
IGNORED = {
    "sdf.xml": ("plugin_attr", "plugin_attradr", "npluginattr", "mesh_scale"),
}


def _scaled_copy(path: Path, factor: float, mass: MassPolicy = "keep") -> mujoco.MjModel:
    """MuJoCo's compilation of the fixture scaled by ``factor``, includes inlined."""
    model = load(path, inline_includes=True)
    return compile_text_beside(dumps(scaled(model, factor, mass=mass)), path)


#: Slides along x, along MuJoCo's default axis (z) and along y given by a class, in bodies
#: that do not turn: per-axis scaling is exact there.
ALIGNED_SLIDES = """<mujoco>
  <default><default class="sideways"><joint type="slide" axis="0 1 0"/></default></default>
  <worldbody>
    <body name="a" pos="0.1 0.2 0.3">
      <joint name="x" type="slide" axis="1 0 0" range="-0.1 0.2"/>
      <geom size="0.05"/>
      <body name="b" pos="0.05 0 0.1">
        <joint name="z" type="slide" range="0 0.3"/>
        <geom size="0.05"/>
        <body name="c" pos="0 0.1 0" childclass="sideways">
          <joint name="y" range="-0.2 0.2"/>
          <geom size="0.05"/>
        </body>
      </body>
    </body>
  </worldbody>
  <keyframe><key qpos="0.15 0.25 -0.1"/></keyframe>
</mujoco>"""
