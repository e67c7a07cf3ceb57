"""The referee for scaled variants written into a compiled model: MuJoCo compiling the variant.

:func:`patched_problems` compares a model ``patched`` made with MuJoCo's compilation of
the same scaled variant, every array and struct field:

* integer arrays exactly, but for the two that pick one element among equals (the
  faces of a mesh's bounding-volume leaves, a mesh's extreme vertex per direction):
  a recompiled mesh rounds its vertices again and may break a tie the other way, so
  there the patched model's choice must be a right one (each leaf box holds its face,
  each parent box its children; each extreme vertex reaches as far as MuJoCo's);
* a frame MuJoCo picks among equals (the principal axes of a mesh or body whose
  principal moments are equal, or nearly: a scaled copy rounds differently and may
  come out turned) by what it holds: the same inertia, the mesh's vertices and
  normals at the same places in the body, boxes that hold them;
* what MuJoCo derives from the inverse mass matrix to :data:`TOLERANCE` (an inverse
  carries the matrix's condition number times the rounding of its inputs: a drawn
  model without meshes was off by 1.9e-9), and not at all where that matrix is
  singular to working precision (see :func:`_singular`);
* float arrays to :data:`TOLERANCE` of the array's largest magnitude, or to
  :data:`TOLERANCE_WITHOUT_MESHES` in a model without meshes (but for 32-bit arrays),
  unit normals of mesh faces and polygons to :data:`NORMALS_TOLERANCE`, but for the
  normal of a polygon whose corners meet (MuJoCo's fallback normal, see
  :func:`_collapsed_polygons`).

Why those tolerances: MuJoCo keeps mesh vertices as 32-bit floats, one part in 1.7e7.
A scaled mesh compiled anew is rounded again, so its vertices move in the 8th digit,
and so does what MuJoCo computes from them (the mesh's centre and inertia, the body's
centre of mass and inertia, the boxes, and everything derived from masses). On the
corpus (factors 0.8, 1.3 and 1.7) the worst such difference was 7.9e-9 of an array's
scale in a 64-bit array (a bread's centre of mass), 3.0e-7 in a 32-bit one (mesh
vertices and normals), up to 7.7e-6 for the normals of a few nearly flat polygons
(TIAGo, at 1.7); without meshes, 7.2e-8, in 32-bit arrays only (a light's bulb
radius). The bounds sit above that: a wrong factor or a missed array is off by tens
of percent, and planted errors of 1e-5 in a mass or 1e-4 in a vertex are caught.
"""

from __future__ import annotations

import itertools
from typing import Any

import mujoco
import numpy as np

from mjcf_model.bridge.compare import field_value, model_fields, path_fields, struct_field_names
from tests.conftest import MUJOCO_VERSION

__all__ = ["NORMALS_TOLERANCE", "TOLERANCE", "TOLERANCE_WITHOUT_MESHES", "patched_problems"]

#: Float arrays of a model with meshes: a difference of at most this part of the array's scale.
TOLERANCE = 1e-6
#: Float arrays of a model without meshes (64-bit arrays are exact but for the last digits).
TOLERANCE_WITHOUT_MESHES = 1e-9
#: Unit normals of mesh faces and polygons, computed anew from rounded vertices.
NORMALS_TOLERANCE = 1e-5
_NORMALS = frozenset({"mesh_normal", "mesh_polynormal", "mesh_facenormal"})
#: Differences below this are rounding noise whatever the array's scale (a tendon whose
#: length does not change at ``qpos0`` has an inverse weight of 0 or of 1e-38).
_NOISE = 1e-30

#: The 27 directions of ``mesh_extrema``, in MuJoCo's order (the middle one is zero).
_DIRECTIONS = np.array(list(itertools.product((-1.0, 0.0, 1.0), repeat=3)))


def patched_problems(ours: Any, referee: Any) -> list[str]:
    """Every way ``ours`` differs from ``referee`` beyond the stated tolerances."""
    problems: list[str] = []
    floats = TOLERANCE if referee.nmesh else TOLERANCE_WITHOUT_MESHES
    elsewhere = _checked_elsewhere(ours, referee)
    left_out = set(path_fields()) | (_INVERSES if _singular(referee) else set())
    for name in sorted({*model_fields(), *struct_field_names()} - left_out):
        mine = np.asarray(field_value(ours, name))
        theirs = np.asarray(field_value(referee, name))
        if mine.shape != theirs.shape:
            problems.append(f"{name}: shape {mine.shape}, MuJoCo's {theirs.shape}")
        elif mine.dtype.kind not in "fc":
            if not np.array_equal(mine, theirs) and name not in ("bvh_nodeid", "mesh_extrema"):
                problems.append(f"{name}: {int(np.sum(mine != theirs))} entries differ")
        elif mine.size and not np.array_equal(mine, theirs):
            if name in elsewhere:
                kept = ~elsewhere[name]
                mine, theirs = mine[kept], theirs[kept]
            scale = float(np.max(np.abs(theirs))) if theirs.size else 0.0
            off = float(np.max(np.abs(mine.astype(float) - theirs.astype(float)), initial=0.0))
            bound = NORMALS_TOLERANCE if name in _NORMALS else floats
            noise = _NOISE
            if mine.dtype == np.float32 or name in _INVERSES:
                bound = max(bound, TOLERANCE)
            if name in _INVERSES:
                noise = max(noise, _inverse_noise(referee))
            if off > max(bound * scale, noise):
                problems.append(f"{name}: off by {off / max(scale, 1e-300):.2e} of its scale")
    problems += _bvh_problems(ours, referee, elsewhere["bvh_aabb"])
    problems += _extrema_problems(ours, referee)
    problems += _frame_problems(ours, referee)
    return problems


#: What MuJoCo derives from the inverse of the mass matrix at ``qpos0``.
_INVERSES = {
    "dof_invweight0", "body_invweight0", "tendon_invweight0", "actuator_acc0",
    "flexedge_invweight0",
}  # fmt: skip


def _inverse_noise(model: Any) -> float:
    """Below this, what MuJoCo derives from the inverse mass matrix is rounding noise.

    A millionth of a millionth of the largest inverse weight of a degree of freedom: an
    actuator or tendon whose moment is zero to working precision (a tendon that no
    degree of freedom lengthens) gets an ``acc0`` of that order, 1e-22 against DOF
    weights of 2e-5 in a drawn model, and a scaled copy's differs by its own rounding.
    """
    return 1e-12 * float(np.max(model.dof_invweight0, initial=0.0))


def _singular(model: Any) -> bool:
    """Whether the mass matrix at ``qpos0`` is singular to working precision.

    MuJoCo warns ("Inertia matrix is too close to singular") and what it derives from
    the inverse is rounding noise (drawn models can stack massless bodies): a scaled
    copy's differs by orders of magnitude, so it is not compared.
    """
    if not model.nv:
        return False
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)  # no collision: MuJoCo 3.9 aborts on some drawn models
    mujoco.mj_comPos(model, data)
    mujoco.mj_makeM(model, data)
    matrix = np.zeros((model.nv, model.nv))
    if MUJOCO_VERSION >= (4, 0):
        mujoco.mj_fullM(model, data, matrix)
    else:
        mujoco.mj_fullM(model, matrix, data.qM)
    return bool(np.linalg.cond(matrix) > 1e12)


def _turned_meshes(ours: Any, referee: Any) -> np.ndarray:
    """The meshes MuJoCo gave another principal frame than the patched model keeps.

    A mesh (or body) whose principal moments are equal, or nearly, has no one
    principal frame: MuJoCo picks one from its computed inertia, and a scaled copy,
    rounded differently, may come out turned. The patched model keeps the frame MuJoCo
    picked before; :func:`_frame_problems` checks that the two describe the same shape.
    """
    quats = np.abs(np.asarray(ours.mesh_quat) - np.asarray(referee.mesh_quat))
    return np.any(quats > TOLERANCE, axis=1) if ours.nmesh else np.zeros(0, dtype=bool)


def _turned_bodies(ours: Any, referee: Any) -> np.ndarray:
    """The bodies whose inertial frame MuJoCo picked otherwise (see :func:`_turned_meshes`).

    Any difference beyond the tolerance of models without meshes: principal axes carry
    the rounding of the moments divided by the gap between them (a drawn body's frame
    moved by 1.4e-9), so a body's frame is checked by the inertia it holds.
    """
    return np.any(np.abs(ours.body_iquat - referee.body_iquat) > TOLERANCE_WITHOUT_MESHES, axis=1)


def _rows_of(adr: np.ndarray, num: np.ndarray, chosen: np.ndarray, total: int) -> np.ndarray:
    """The rows ``adr[i]`` to ``adr[i] + num[i]`` of every chosen ``i``."""
    rows = np.zeros(total, dtype=bool)
    for index in np.flatnonzero(chosen):
        if adr[index] >= 0:
            rows[adr[index] : adr[index] + num[index]] = True
    return rows


def _checked_elsewhere(ours: Any, referee: Any) -> dict[str, np.ndarray]:
    """The rows of each array compared by what they mean rather than number for number."""
    meshes = _turned_meshes(ours, referee)
    bodies = _turned_bodies(ours, referee)
    mesh_geoms = np.isin(ours.geom_type, (7, 8))  # mesh and SDF geoms take their mesh's frame
    geoms = mesh_geoms & np.isin(ours.geom_dataid, np.flatnonzero(meshes))
    polygons = _rows_of(ours.mesh_polyadr, ours.mesh_polynum, meshes, ours.nmeshpoly)
    # a turned mesh turns its geoms' boxes, and so the boxes of their bodies' trees, which
    # stand in the bodies' inertial frames
    holders = np.isin(np.arange(ours.nbody), ours.geom_bodyid[geoms]) | bodies
    trees = (
        _retied_nodes(ours, referee)
        | _rows_of(ours.mesh_bvhadr, ours.mesh_bvhnum, meshes, ours.nbvh)
        | _rows_of(ours.body_bvhadr, ours.body_bvhnum, holders, ours.nbvh)
    )
    return {
        "bvh_aabb": trees,
        "mesh_polynormal": _collapsed_polygons(referee) | polygons,
        "mesh_vert": _rows_of(ours.mesh_vertadr, ours.mesh_vertnum, meshes, ours.nmeshvert),
        "mesh_normal": _rows_of(ours.mesh_normaladr, ours.mesh_normalnum, meshes, ours.nmeshnormal),
        "mesh_quat": meshes,
        "mesh_pos": meshes,
        "geom_quat": geoms,
        "geom_size": geoms,
        "geom_aabb": geoms,
        "body_iquat": bodies,
        "body_inertia": bodies,
    }


def _rotation(quat: np.ndarray) -> np.ndarray:
    matrix = np.zeros(9)
    mujoco.mju_quat2Mat(matrix, np.asarray(quat, dtype=float))
    return matrix.reshape(3, 3)


def _frame_problems(ours: Any, referee: Any) -> list[str]:
    """Turned frames must hold the same thing: each body's inertia, each mesh geom's shape."""
    problems = []
    for body in np.flatnonzero(_turned_bodies(ours, referee)):
        tensors = [
            _rotation(model.body_iquat[body])
            @ np.diag(model.body_inertia[body])
            @ _rotation(model.body_iquat[body]).T
            for model in (ours, referee)
        ]
        if np.max(np.abs(tensors[0] - tensors[1])) > TOLERANCE * np.max(np.abs(tensors[1])):
            problems.append(f"body {body}: another inertia in a turned frame")
    meshes = _turned_meshes(ours, referee)
    for geom in np.flatnonzero(np.isin(ours.geom_type, (7, 8))):
        mesh = int(ours.geom_dataid[geom])
        if mesh < 0 or not meshes[mesh]:
            continue
        shapes = []
        for model in (ours, referee):
            turn = _rotation(model.geom_quat[geom])
            start, count = int(model.mesh_normaladr[mesh]), int(model.mesh_normalnum[mesh])
            normals = np.asarray(model.mesh_normal[start : start + count], dtype=float)
            placed = model.geom_pos[geom] + _mesh_vertices(model, mesh) @ turn.T
            shapes.append((placed, normals @ turn.T))
        extent = float(np.max(np.abs(shapes[1][0])))
        if np.max(np.abs(shapes[0][0] - shapes[1][0]), initial=0.0) > TOLERANCE * extent:
            problems.append(f"geom {geom}: its mesh's vertices are elsewhere in its body")
        if np.max(np.abs(shapes[0][1] - shapes[1][1]), initial=0.0) > NORMALS_TOLERANCE:
            problems.append(f"geom {geom}: its mesh's normals point elsewhere in its body")
        low, high = _box(ours.geom_aabb[geom])
        inside = _mesh_vertices(ours, mesh)
        slack = TOLERANCE * float(np.max(np.abs(inside)))
        if np.any(inside < low - slack) or np.any(inside > high + slack):
            problems.append(f"geom {geom}: its box does not hold its mesh")
    return problems


def _box(aabb: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The low and high corners of a box stored as its centre and half sizes."""
    centre, half = np.asarray(aabb[:3], dtype=float), np.asarray(aabb[3:], dtype=float)
    return centre - half, centre + half


def _collapsed_polygons(model: Any) -> np.ndarray:
    """The polygons with two vertices (nearly) at one point: their normal is MuJoCo's guess.

    A mesh may hold a triangle whose two corners are nanometres apart (robosuite's
    TIAGo has some); rounded at another scale they meet, and MuJoCo gives the
    collapsed polygon its fallback normal, ``(1, 0, 0)``, where the patched model keeps
    the one computed before.
    """
    collapsed = np.zeros(model.nmeshpoly, dtype=bool)
    for mesh in range(model.nmesh):
        vertices = _mesh_vertices(model, mesh)
        shortest = 1e-6 * float(np.max(np.abs(vertices), initial=0.0))
        start = int(model.mesh_polyadr[mesh])
        for poly in range(start, start + int(model.mesh_polynum[mesh])):
            first = int(model.mesh_polyvertadr[poly])
            corners = vertices[model.mesh_polyvert[first : first + model.mesh_polyvertnum[poly]]]
            edges = np.linalg.norm(corners - np.roll(corners, 1, axis=0), axis=1)
            collapsed[poly] = bool(np.min(edges, initial=np.inf) < shortest)
    return collapsed


def _retied_nodes(ours: Any, referee: Any) -> np.ndarray:
    """The nodes of every tree in which some leaf holds another element than MuJoCo's."""
    owners = _tree_of_node(ours)
    moved = np.unique(owners[ours.bvh_nodeid != referee.bvh_nodeid])
    return np.isin(owners, moved)


def _tree_of_node(model: Any) -> np.ndarray:
    """Which tree each bounding-volume node belongs to: a body's (its id) or a mesh's (-1 - id)."""
    owners = np.zeros(model.nbvh, dtype=int)
    for body in range(model.nbody):
        start = int(model.body_bvhadr[body])
        if start >= 0:
            owners[start : start + int(model.body_bvhnum[body])] = body
    for mesh in range(model.nmesh):
        start = int(model.mesh_bvhadr[mesh])
        if start >= 0:
            owners[start : start + int(model.mesh_bvhnum[mesh])] = -1 - mesh
    return owners


def _bvh_problems(ours: Any, referee: Any, elsewhere: np.ndarray) -> list[str]:
    """Each tree not compared box for box must be right: each box holds what is below it.

    A leaf of a mesh's tree holds a face, a leaf of a body's tree a geom's box (turned
    into the body's inertial frame); a parent its children's boxes.
    """
    problems = []
    owners = _tree_of_node(ours)
    boxes = np.asarray(ours.bvh_aabb, dtype=float)
    for tree in np.unique(owners[elsewhere]):
        nodes = np.flatnonzero(owners == tree)
        if tree < 0:
            mesh = -1 - int(tree)
            vertices = _mesh_vertices(ours, mesh)
            faces = ours.mesh_face[ours.mesh_faceadr[mesh] :][: ours.mesh_facenum[mesh]]
            leaves = vertices[faces]  # (faces, 3 corners, xyz)
        else:
            leaves = np.stack([_geom_corners(ours, geom, int(tree)) for geom in range(ours.ngeom)])
        low, high = boxes[nodes, :3] - boxes[nodes, 3:], boxes[nodes, :3] + boxes[nodes, 3:]
        slack = TOLERANCE * float(np.max(np.abs(boxes[nodes, :3]) + boxes[nodes, 3:]))
        items = ours.bvh_nodeid[nodes]
        held = items >= 0
        points = leaves[items[held]]
        inside = (points >= low[held, None] - slack) & (points <= high[held, None] + slack)
        children = ours.bvh_child[nodes]
        for side in (0, 1):
            has = children[:, side] >= 0
            child = children[has, side]  # numbered from the tree's first node
            inside_child = (low[child] >= low[has] - slack) & (high[child] <= high[has] + slack)
            if not np.all(inside_child):
                problems.append(f"bounding volumes: a box of tree {tree} is outside its parent's")
        if not np.all(inside):
            problems.append(f"bounding volumes: a leaf of tree {tree} is outside its box")
    return problems


def _geom_corners(model: Any, geom: int, body: int) -> np.ndarray:
    """The corners of a geom's box in its body's inertial frame (where its tree's boxes are)."""
    low, high = _box(model.geom_aabb[geom])
    corners = np.array(list(itertools.product(*zip(low, high, strict=True))))
    placed = model.geom_pos[geom] + corners @ _rotation(model.geom_quat[geom]).T
    return (placed - model.body_ipos[body]) @ _rotation(model.body_iquat[body])


def _mesh_vertices(model: Any, mesh: int) -> np.ndarray:
    start, count = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
    return np.asarray(model.mesh_vert[start : start + count], dtype=float)


def _extrema_problems(model: Any, referee: Any) -> list[str]:
    """Where MuJoCo picks another, each extreme vertex per direction must reach as far."""
    problems: list[str] = []
    if not model.nmesh or not hasattr(model, "mesh_extrema"):  # MuJoCo 4.0 added them
        return problems
    moved = np.any(model.mesh_extrema != referee.mesh_extrema, axis=1)
    for mesh in np.flatnonzero(moved):
        start = int(model.mesh_graphadr[mesh])
        if start < 0:
            continue
        count = int(model.mesh_graph[start])
        hull = model.mesh_graph[start + 2 + count : start + 2 + 2 * count]
        vertices = _mesh_vertices(model, mesh)
        reach = vertices @ _DIRECTIONS.T
        chosen = reach[hull[model.mesh_extrema[mesh]], np.arange(27)]
        slack = 1e-6 * float(np.max(np.abs(vertices)))
        if np.any(chosen < reach.max(axis=0) - slack):
            problems.append(f"mesh_extrema of mesh {mesh}: a vertex short of the farthest")
    return problems
