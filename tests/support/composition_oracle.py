"""The composition oracle: a composed scene is its parts, each as MuJoCo compiles it alone.

For a scene composed of parts (each a model MuJoCo compiled on its own, attached
with a prefix at a body of the scene, possibly moved by a pose),
:func:`composition_problems` checks every per-object array of the compiled
scene: for every kind of object (the ``body_``, ``jnt_``, ``dof_``, ``geom_``...
fields of ``MjModel``, found from MuJoCo's own field names, so a field a new
MuJoCo adds is compared without a change here), the scene's row of each of a
part's objects equals the part-alone row, except for what composing must change:

* ids are compared by what they point to: an id is right when it points to the
  scene object that the part's object it pointed to became;
* addresses into the scene's buffers (``jnt_qposadr``, ``mesh_vertadr``...) are
  the scene's layout: the data they point to is compared instead (:data:`DATA`),
  and for the rest whether they point anywhere;
* the root bodies (and the objects the part's world body holds) are moved by the
  part's pose, and so are free joints' ``qpos0``;
* keys follow the keyframe rule (mjcf_model/transforms/composition/keyframes.py):
  a part's key sets that part's joints, actuators and mocap bodies to its values,
  moved by the pose, and every other part to its placed initial state.

The few per-object fields not compared are in :data:`NOT_COMPARED`, each with
its reason; every count must be the parts' sum, so nothing else can be added.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable, Sequence
from typing import Any

import attrs
import mujoco
import numpy as np

from mjcf_model.bridge.compare import compiled_names, model_fields

__all__ = [
    "DATA",
    "KINDS",
    "NOT_COMPARED",
    "REFERENCES",
    "PlacedPart",
    "composition_problems",
    "field_roles",
]

#: Per kind of object: its field prefix, its count and its mjtObj.
KINDS: dict[str, tuple[str, Any]] = {
    "body": ("nbody", mujoco.mjtObj.mjOBJ_BODY),
    "jnt": ("njnt", mujoco.mjtObj.mjOBJ_JOINT),
    "dof": ("nv", mujoco.mjtObj.mjOBJ_DOF),
    "geom": ("ngeom", mujoco.mjtObj.mjOBJ_GEOM),
    "site": ("nsite", mujoco.mjtObj.mjOBJ_SITE),
    "cam": ("ncam", mujoco.mjtObj.mjOBJ_CAMERA),
    "light": ("nlight", mujoco.mjtObj.mjOBJ_LIGHT),
    "flex": ("nflex", mujoco.mjtObj.mjOBJ_FLEX),
    "mesh": ("nmesh", mujoco.mjtObj.mjOBJ_MESH),
    "skin": ("nskin", mujoco.mjtObj.mjOBJ_SKIN),
    "hfield": ("nhfield", mujoco.mjtObj.mjOBJ_HFIELD),
    "tex": ("ntex", mujoco.mjtObj.mjOBJ_TEXTURE),
    "mat": ("nmat", mujoco.mjtObj.mjOBJ_MATERIAL),
    "pair": ("npair", mujoco.mjtObj.mjOBJ_PAIR),
    "exclude": ("nexclude", mujoco.mjtObj.mjOBJ_EXCLUDE),
    "eq": ("neq", mujoco.mjtObj.mjOBJ_EQUALITY),
    "tendon": ("ntendon", mujoco.mjtObj.mjOBJ_TENDON),
    "actuator": ("nu", mujoco.mjtObj.mjOBJ_ACTUATOR),
    "sensor": ("nsensor", mujoco.mjtObj.mjOBJ_SENSOR),
    "numeric": ("nnumeric", mujoco.mjtObj.mjOBJ_NUMERIC),
    "text": ("ntext", mujoco.mjtObj.mjOBJ_TEXT),
    "tuple": ("ntuple", mujoco.mjtObj.mjOBJ_TUPLE),
    "key": ("nkey", mujoco.mjtObj.mjOBJ_KEY),
    "plugin": ("nplugin", mujoco.mjtObj.mjOBJ_PLUGIN),
    "tree": ("ntree", None),
}
#: Kinds of objects a body owns, compared by owner and rank within it.
OWNED = ("jnt", "geom", "site", "cam", "light")
#: The kind of each mjtObj value (``sensor_objtype``, ``eq_objtype``, ``tuple_objtype``...).
OBJECT_KINDS = {int(obj): kind for kind, (_, obj) in KINDS.items() if obj is not None} | {
    int(mujoco.mjtObj.mjOBJ_XBODY): "body"
}

#: A reference's target kind, given the model and the object's index (``None``: not an id).
Target = Callable[[Any, int], "str | None"]


def _fixed(kind: str) -> Target:
    return lambda model, index: kind


def _by_objtype(field: str) -> Target:
    return lambda model, index: OBJECT_KINDS.get(int(getattr(model, field)[index]))


def _geom_data(model: Any, index: int) -> str | None:
    kind = int(model.geom_type[index])
    if kind == mujoco.mjtGeom.mjGEOM_HFIELD:
        return "hfield"
    return "mesh" if kind in (mujoco.mjtGeom.mjGEOM_MESH, mujoco.mjtGeom.mjGEOM_SDF) else None


def _site_data(model: Any, index: int) -> str | None:
    return "mesh" if int(model.site_type[index]) == mujoco.mjtGeom.mjGEOM_MESH else None


def _transmission(model: Any, index: int) -> str | None:
    return {
        mujoco.mjtTrn.mjTRN_JOINT: "jnt",
        mujoco.mjtTrn.mjTRN_JOINTINPARENT: "jnt",
        mujoco.mjtTrn.mjTRN_SLIDERCRANK: "site",
        mujoco.mjtTrn.mjTRN_TENDON: "tendon",
        mujoco.mjtTrn.mjTRN_SITE: "site",
        mujoco.mjtTrn.mjTRN_BODY: "body",
    }.get(int(model.actuator_trntype[index]))


def _equality(model: Any, index: int) -> str | None:
    kind = int(model.eq_type[index])
    if kind in (mujoco.mjtEq.mjEQ_CONNECT, mujoco.mjtEq.mjEQ_WELD):
        return OBJECT_KINDS.get(int(model.eq_objtype[index]), "body")
    return {
        mujoco.mjtEq.mjEQ_JOINT: "jnt",
        mujoco.mjtEq.mjEQ_TENDON: "tendon",
    }.get(kind, "flex")


#: The per-object fields that hold ids, and the kind each id is of.
REFERENCES: dict[str, Target] = {
    "body_parentid": _fixed("body"),
    "body_rootid": _fixed("body"),
    "body_weldid": _fixed("body"),
    "body_mocapid": _fixed("mocap"),
    "body_treeid": _fixed("tree"),
    "body_jntadr": _fixed("jnt"),
    "body_dofadr": _fixed("dof"),
    "body_geomadr": _fixed("geom"),
    "body_plugin": _fixed("plugin"),
    "jnt_bodyid": _fixed("body"),
    "jnt_dofadr": _fixed("dof"),
    "jnt_actuatorid": _fixed("actuator"),
    "dof_bodyid": _fixed("body"),
    "dof_jntid": _fixed("jnt"),
    "dof_parentid": _fixed("dof"),
    "dof_treeid": _fixed("tree"),
    "geom_bodyid": _fixed("body"),
    "geom_dataid": _geom_data,
    "geom_matid": _fixed("mat"),
    "geom_plugin": _fixed("plugin"),
    "site_bodyid": _fixed("body"),
    "site_dataid": _site_data,
    "site_matid": _fixed("mat"),
    "cam_bodyid": _fixed("body"),
    "cam_targetbodyid": _fixed("body"),
    "light_bodyid": _fixed("body"),
    "light_targetbodyid": _fixed("body"),
    "light_texid": _fixed("tex"),
    "flex_matid": _fixed("mat"),
    "skin_matid": _fixed("mat"),
    "mat_texid": _fixed("tex"),
    "pair_geom1": _fixed("geom"),
    "pair_geom2": _fixed("geom"),
    "eq_obj1id": _equality,
    "eq_obj2id": _equality,
    "tendon_matid": _fixed("mat"),
    "tendon_actuatorid": _fixed("actuator"),
    "tendon_treeid": _fixed("tree"),
    "actuator_trnid": _transmission,
    "actuator_plugin": _fixed("plugin"),
    "sensor_objid": _by_objtype("sensor_objtype"),
    "sensor_refid": _by_objtype("sensor_reftype"),
    "sensor_plugin": _fixed("plugin"),
    "tree_bodyadr": _fixed("body"),
    "pair_signature": _fixed("signature"),
    "exclude_signature": _fixed("signature"),
    "tree_dofadr": _fixed("dof"),
}

#: Fields whose names end in ``id`` that hold values.
NOT_IDS = frozenset({"geom_fluid"})

#: Data arrays compared through the object that owns them: field -> (address, count).
DATA: dict[str, tuple[str, str]] = {
    **{
        f"mesh_{name}": (f"mesh_{name}adr", f"mesh_{name}num")
        for name in ("vert", "normal", "texcoord", "face")
    },
    "mesh_polyvertnum": ("mesh_polyadr", "mesh_polynum"),
    "mesh_facenormal": ("mesh_faceadr", "mesh_facenum"),
    "mesh_facetexcoord": ("mesh_faceadr", "mesh_facenum"),
    "mesh_polynormal": ("mesh_polyadr", "mesh_polynum"),
    **{f"skin_{name}": (f"skin_{name}adr", f"skin_{name}num") for name in ("vert", "face")},
    "skin_texcoord": ("skin_texcoordadr", "skin_vertnum"),
    "skin_bonebindpos": ("skin_boneadr", "skin_bonenum"),
    "skin_bonebindquat": ("skin_boneadr", "skin_bonenum"),
    "skin_bonebodyid": ("skin_boneadr", "skin_bonenum"),
    "numeric_data": ("numeric_adr", "numeric_size"),
    "text_data": ("text_adr", "text_size"),
    "tuple_objtype": ("tuple_adr", "tuple_size"),
    "tuple_objid": ("tuple_adr", "tuple_size"),
    "tuple_objprm": ("tuple_adr", "tuple_size"),
    "wrap_type": ("tendon_adr", "tendon_num"),
    "wrap_objid": ("tendon_adr", "tendon_num"),
    "wrap_prm": ("tendon_adr", "tendon_num"),
    "hfield_data": ("hfield_adr", "hfield_nrow*hfield_ncol"),
    "tex_data": ("tex_adr", "tex_height*tex_width*tex_nchannel"),
    "qpos0": ("jnt_qposadr", "qpos"),
    "qpos_spring": ("jnt_qposadr", "qpos"),
}
#: The ids inside data arrays: field -> the kind, or the type field that tells it.
DATA_REFERENCES = {
    "skin_bonebodyid": "body",
    "tuple_objid": "tuple_objtype",
    "wrap_objid": "wrap_type",
}
_WRAP_KINDS = {
    int(mujoco.mjtWrap.mjWRAP_JOINT): "jnt",
    int(mujoco.mjtWrap.mjWRAP_SITE): "site",
    int(mujoco.mjtWrap.mjWRAP_SPHERE): "geom",
    int(mujoco.mjtWrap.mjWRAP_CYLINDER): "geom",
}

#: Per-object fields not compared, each with its reason.
NOT_COMPARED: dict[str, str] = {
    "dof_Madr": "the layout of the scene's sparse inertia matrix, which interleaves the parts",
    "dof_simplenum": "a run length over the scene's dof order: it runs on into the next part",
    "mesh_graphadr": "the convex hull graph has no count field; mesh_vert and mesh_face decide it",
    "mesh_graph": "the convex hull graph has no count field; mesh_vert and mesh_face decide it",
    **dict.fromkeys(
        ("mesh_polyvert", "mesh_polymap", "mesh_polyvertadr", "mesh_polymapadr", "mesh_polymapnum"),
        "per polygon or vertex, addresses within the mesh's polygons: mesh_polynormal and "
        "mesh_polyvertnum compare the polygons",
    ),
    "mesh_pathadr": "where the file's path is in the name buffer: the scene's layout",
    "skin_pathadr": "where the file's path is in the name buffer: the scene's layout",
    "hfield_pathadr": "where the file's path is in the name buffer: the scene's layout",
    "tex_pathadr": "where the file's path is in the name buffer: the scene's layout",
    "tex_contenttypeadr": "where the content type is in the name buffer: the scene's layout",
    "skin_bonevertid": "per bone vertex, within its bone: skin vertices and bones are compared",
    "skin_bonevertweight": "per bone vertex, within its bone: skin vertices and bones are compared",
    "skin_bonevertadr": "per bone, not per skin: the skin's vertices and bones are compared",
    "skin_bonevertnum": "per bone, not per skin: the skin's vertices and bones are compared",
}
#: Kinds whose every field is left out, with the reason.
KINDS_NOT_COMPARED = {
    "flex": "a flex's dozens of address arrays interleave the parts' buffers; no corpus has one",
    "plugin": "a plugin instance's attributes are the plugin's own; no corpus model has one",
}
#: The tolerance of compared values (frames are converted between compiler conventions).
RTOL, ATOL = 1e-9, 1e-12


def field_roles(model: Any | None = None) -> dict[str, str]:
    """Every field with a kind's prefix: its role (value, reference, address, data...)."""
    roles = {}
    for field in model_fields():
        kind = field.split("_")[0]
        if field in DATA:
            roles[field] = "data"
        elif field in NOT_COMPARED or (kind in KINDS_NOT_COMPARED and kind in KINDS):
            roles[field] = "not compared"
        elif kind not in KINDS:
            continue
        elif field in REFERENCES:
            roles[field] = "reference"
        elif kind == "key":
            roles[field] = "key"
        elif field.endswith("adr"):
            roles[field] = "address"
        elif field.endswith("id") and field not in NOT_IDS:
            roles[field] = "unclassified id"
        else:
            roles[field] = "value"
    return roles


@attrs.frozen
class PlacedPart:
    """A part of a scene: the part compiled alone, its prefix, where it went and how it moved."""

    #: The part as MuJoCo compiles it alone.
    alone: Any
    #: The prefix its names got ("" for the parent the others were attached into).
    prefix: str = ""
    #: The scene body it was attached to (its world body's objects went there).
    at: str = "world"
    #: The placement's position and quaternion, in the frame of ``at``.
    pos: tuple[float, ...] = (0.0, 0.0, 0.0)
    quat: tuple[float, ...] = (1.0, 0.0, 0.0, 0.0)

    def move(self, pos: Any, quat: Any) -> tuple[np.ndarray[Any, Any], np.ndarray[Any, Any]]:
        """A pose in the part's world as the placement puts it: ``R p + t``, ``q_p q``."""
        turned, product = np.zeros(3), np.zeros(4)
        mujoco.mju_rotVecQuat(turned, np.asarray(pos, dtype=float), np.asarray(self.quat, float))
        mujoco.mju_mulQuat(product, np.asarray(self.quat, float), np.asarray(quat, dtype=float))
        return np.asarray(self.pos, float) + turned, product

    def turn(self, vector: Any) -> np.ndarray[Any, Any]:
        """``vector`` rotated by the placement."""
        result = np.zeros(3)
        mujoco.mju_rotVecQuat(result, np.asarray(vector, float), np.asarray(self.quat, float))
        return result


Mapping = dict[str, np.ndarray[Any, Any]]


def _children(model: Any) -> dict[int, list[int]]:
    found: dict[int, list[int]] = defaultdict(list)
    for body in range(1, model.nbody):
        found[int(model.body_parentid[body])].append(body)
    return found


def _map_bodies(parts: Sequence[PlacedPart], scene: Any, problems: list[str]) -> list[Mapping]:
    """Each part's objects -> the scene's: bodies by tree and rank, owned objects by body."""
    scene_children = _children(scene)
    claimed: dict[tuple[str, int], int] = defaultdict(int)
    owned_scene: dict[str, dict[int, list[int]]] = {kind: _owned(scene, kind) for kind in OWNED}
    mappings = []
    for part in parts:
        alone = part.alone
        bodies = np.full(alone.nbody, -1)
        target = mujoco.mj_name2id(scene, mujoco.mjtObj.mjOBJ_BODY, part.at)
        if target < 0:
            problems.append(f"{part.prefix}: the attach body {part.at!r} is missing")
            mappings.append({"body": bodies})
            continue
        bodies[0] = target
        stack = [0]
        own_children = _children(alone)
        while stack:
            body = stack.pop()
            there = int(bodies[body])
            mine = own_children.get(body, [])
            start = claimed[("body", there)]
            theirs = scene_children.get(there, [])[start : start + len(mine)]
            claimed[("body", there)] += len(mine)
            if len(theirs) < len(mine):
                problems.append(f"{part.prefix}: body {body}'s children are missing in the scene")
            for child, other in zip(mine, theirs, strict=False):
                bodies[child] = other
                stack.append(child)
        mapping = {"body": bodies}
        for kind in OWNED:
            count = getattr(alone, KINDS[kind][0])
            result = np.full(count, -1)
            for body, objects in _owned(alone, kind).items():
                there = int(bodies[body])
                start = claimed[(kind, there)]
                theirs = owned_scene[kind].get(there, [])[start : start + len(objects)]
                claimed[(kind, there)] += len(objects)
                for own, other in zip(objects, theirs, strict=False):
                    result[own] = other
            mapping[kind] = result
        mappings.append(mapping)
    return mappings


def _owned(model: Any, kind: str) -> dict[int, list[int]]:
    found: dict[int, list[int]] = defaultdict(list)
    for index, body in enumerate(getattr(model, f"{kind}_bodyid")):
        found[int(body)].append(index)
    return found


def _map_listed(
    parts: Sequence[PlacedPart], scene: Any, mappings: list[Mapping], problems: list[str]
) -> None:
    """Objects of the other kinds: by prefixed name, unnamed ones in order after earlier parts'."""
    scene_names = compiled_names(scene)
    for kind in KINDS:
        if kind in OWNED or kind in ("body", "dof", "tree"):
            continue
        names = scene_names.get(kind, [])
        where = {name: index for index, name in enumerate(names) if name}
        unnamed = [index for index, name in enumerate(names) if not name]
        for part, mapping in zip(parts, mappings, strict=True):
            own = compiled_names(part.alone).get(kind, [])
            result = np.full(getattr(part.alone, KINDS[kind][0]), -1)
            for index, name in enumerate(own):
                if name:
                    result[index] = where.get(part.prefix + name, -1)
                elif unnamed:
                    result[index] = unnamed.pop(0)
                if result[index] < 0:
                    problems.append(f"{kind} {part.prefix + name!r} is missing")
            mapping[kind] = result


def _map_derived(parts: Sequence[PlacedPart], scene: Any, mappings: list[Mapping]) -> None:
    """Dofs by their joints, trees by their first body, mocap ids by their bodies."""
    for part, mapping in zip(parts, mappings, strict=True):
        alone = part.alone
        dofs = np.full(alone.nv, -1)
        for joint, other in enumerate(mapping["jnt"]):
            if other < 0:
                continue
            count = _dof_count(alone, joint)
            start, there = int(alone.jnt_dofadr[joint]), int(scene.jnt_dofadr[other])
            dofs[start : start + count] = np.arange(there, there + count)
        mapping["dof"] = dofs
        bodies = mapping["body"]
        mapping["tree"] = np.array(
            [scene.body_treeid[bodies[b]] if bodies[b] >= 0 else -1 for b in alone.tree_bodyadr],
            dtype=int,
        )
        mocap = np.full(alone.nmocap, -1)
        for body in range(alone.nbody):
            if alone.body_mocapid[body] >= 0 and bodies[body] >= 0:
                mocap[alone.body_mocapid[body]] = scene.body_mocapid[bodies[body]]
        mapping["mocap"] = mocap


def _dof_count(model: Any, joint: int) -> int:
    return {0: 6, 1: 3}.get(int(model.jnt_type[joint]), 1)


def _qpos_count(model: Any, joint: int) -> int:
    return {0: 7, 1: 4}.get(int(model.jnt_type[joint]), 1)


def _ids(values: Any, kind: str | None, mapping: Mapping) -> np.ndarray[Any, Any]:
    """Ids of a part mapped into the scene (-1 stays -1; an id of an unmapped kind stays)."""
    values = np.asarray(values)
    if kind == "signature":  # (body1 << 16) + body2
        bodies = mapping["body"]
        found = [(bodies[v >> 16] << 16) + bodies[v & 0xFFFF] for v in values.ravel()]
        return np.array(found, dtype=values.dtype).reshape(values.shape)
    if kind is None or kind not in mapping:
        return values
    table = mapping[kind]
    return np.array(
        [table[v] if 0 <= v < len(table) else v for v in values.ravel()], dtype=values.dtype
    ).reshape(values.shape)


def _close(a: Any, b: Any) -> bool:
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape:
        return False
    if a.dtype.kind in "fc":
        return bool(np.allclose(a, b, rtol=RTOL, atol=ATOL, equal_nan=True))
    return bool(np.array_equal(a, b))


def _same_rotation(a: Any, b: Any) -> bool:
    return _close(a, b) or _close(a, -np.asarray(b))


def composition_problems(parts: Sequence[PlacedPart], scene: Any) -> list[str]:
    """What keeps ``scene`` from being exactly its ``parts``, each as compiled alone."""
    problems: list[str] = []
    problems += _count_problems(parts, scene)
    mappings = _map_bodies(parts, scene, problems)
    _map_listed(parts, scene, mappings, problems)
    _map_derived(parts, scene, mappings)
    roles = field_roles()
    for part, mapping in zip(parts, mappings, strict=True):
        problems += _name_problems(part, scene, mapping)
        problems += _field_problems(part, scene, mapping, roles)
        problems += _data_problems(part, scene, mapping)
    problems += _key_problems(parts, scene, mappings)
    return problems


#: The counts that are the sums of the parts' (``nbody``: each part's world body is not added).
COUNTS = (
    *(count for kind, (count, _) in KINDS.items() if kind != "tree"),
    "nq",
    "na",
    "nmocap",
    "nwrap",
    "nsensordata",
    "nmeshvert",
    "nmeshface",
    "nnumericdata",
    "ntupledata",
    "ntexdata",
    "nhfielddata",
    "nuserdata",
)


def _count_problems(parts: Sequence[PlacedPart], scene: Any) -> list[str]:
    problems = []
    for count in COUNTS:
        expected = sum(int(getattr(p.alone, count)) for p in parts)
        if count == "nbody":
            expected -= len(parts) - 1
        if count == "nkey":
            expected = _expected_keys(parts)
        if count == "nuserdata":
            expected = max(int(p.alone.nuserdata) for p in parts)
        if int(getattr(scene, count)) != expected:
            problems.append(f"{count} is {getattr(scene, count)}, expected {expected}")
    return problems


def _expected_keys(parts: Sequence[PlacedPart]) -> int:
    """Each part's keys kept (separate policy); a part without keys adds none."""
    return sum(int(p.alone.nkey) for p in parts)


def _name_problems(part: PlacedPart, scene: Any, mapping: Mapping) -> list[str]:
    problems = []
    own, theirs = compiled_names(part.alone), compiled_names(scene)
    for kind, names in own.items():
        table = mapping.get(kind)
        if table is None:
            continue
        for index, name in enumerate(names):
            if (kind, index) == ("body", 0) or table[index] < 0:
                continue
            expected = part.prefix + name if name else ""
            if theirs[kind][table[index]] != expected:
                problems.append(
                    f"{kind} {expected!r} became {theirs[kind][table[index]]!r} in the scene"
                )
    return problems


def _expected_row(part: PlacedPart, field: str, index: int, row: Any) -> Any:
    """The part-alone row as the placement moves it (root bodies and world-owned objects)."""
    alone = part.alone
    kind = field.split("_")[0]
    if kind == "body":
        at_world = int(alone.body_parentid[index]) == 0
    elif kind in OWNED:
        at_world = int(getattr(alone, f"{kind}_bodyid")[index]) == 0
    else:
        return row
    if not at_world:
        return row
    if field in _MOVED_POSITIONS:
        return part.move(row, (1.0, 0.0, 0.0, 0.0))[0]
    if field in _MOVED_QUATERNIONS:
        return part.move((0.0, 0.0, 0.0), row)[1]
    return part.turn(row) if field == "light_dir" else row


#: The frame fields the placement moves (of root bodies and of the part's world's objects).
_MOVED_POSITIONS = frozenset({"body_pos", "geom_pos", "site_pos", "cam_pos", "light_pos"})
_MOVED_QUATERNIONS = frozenset({"body_quat", "geom_quat", "site_quat", "cam_quat"})


def _field_problems(
    part: PlacedPart, scene: Any, mapping: Mapping, roles: dict[str, str]
) -> list[str]:
    problems = []
    alone = part.alone
    for field, role in roles.items():
        kind = field.split("_")[0]
        if role == "unclassified id":
            problems.append(f"field {field} is an id of no known kind: add it to REFERENCES")
            continue
        if role not in ("value", "reference", "address") or kind not in mapping:
            continue
        own, theirs = np.asarray(getattr(alone, field)), np.asarray(getattr(scene, field))
        count = int(getattr(alone, KINDS[kind][0]))
        if own.ndim == 0 or own.shape[0] != count:
            problems.append(f"field {field} is not per {kind}: classify it")
            continue
        table = mapping[kind]
        for index in range(count):
            other = int(table[index])
            if other < 0 or (kind == "body" and index == 0):
                continue
            want, got = own[index], theirs[other]
            if role == "reference":
                target = REFERENCES[field](alone, index)
                if target is None:
                    continue
                want = _ids(want, target, mapping)
            elif role == "address":
                want, got = np.asarray(want) >= 0, np.asarray(got) >= 0
            else:
                want = _expected_row(part, field, index, want)
                want, got = _settled(part, scene, field, index, want, got)
            same = _same_rotation(want, got) if field.endswith("quat") else _close(want, got)
            if not same:
                problems.append(
                    f"{kind} {_label(alone, kind, index, part.prefix)}: {field} "
                    f"{np.asarray(want).tolist()} -> {np.asarray(got).tolist()}"
                )
    return problems


def _settled(part: PlacedPart, scene: Any, field: str, index: int, want: Any, got: Any) -> Any:
    """The rows with what the scene's model-wide settings derive taken out.

    * ``cam_intrinsic`` left unwritten is ``<visual><map znear>``: the scene's;
    * ``cam_poscom0``/``light_poscom0`` of the part's world body's cameras and lights
      are relative to the world's centre of mass: the whole scene's. Elsewhere the
      centre of mass of a subtree is summed in another order in the scene: 1e-7.
    """
    alone = part.alone
    if field == "cam_intrinsic":
        znear = np.float32(alone.vis.map.znear)
        if np.array_equal(np.asarray(want, np.float32), [znear, znear, 0, 0]):
            near = np.float32(scene.vis.map.znear)
            return np.array([near, near, 0, 0], np.float32), np.asarray(got, np.float32)
    if field in ("cam_poscom0", "light_poscom0"):
        kind = field.split("_")[0]
        if int(getattr(alone, f"{kind}_bodyid")[index]) == 0:
            return got, got
        if np.allclose(want, got, rtol=0, atol=1e-7):
            return got, got
    return want, got


def _label(model: Any, kind: str, index: int, prefix: str) -> str:
    names = compiled_names(model).get(kind)
    name = names[index] if names else ""
    return repr(prefix + name) if name else f"{prefix}#{index}"


def _size(model: Any, count: str, index: int) -> int:
    if count == "qpos":
        return _qpos_count(model, index)
    product = 1
    for factor in count.split("*"):
        product *= int(getattr(model, factor)[index])
    return product


def _data_problems(part: PlacedPart, scene: Any, mapping: Mapping) -> list[str]:
    problems = []
    alone = part.alone
    for field, (address, count) in DATA.items():
        kind = address.split("_")[0]
        table = mapping[kind]
        own, theirs = np.asarray(getattr(alone, field)), np.asarray(getattr(scene, field))
        for index in range(len(table)):
            other, start = int(table[index]), int(getattr(alone, address)[index])
            if other < 0 or start < 0:
                continue
            size, there = _size(alone, count, index), int(getattr(scene, address)[other])
            want, got = own[start : start + size], theirs[there : there + size]
            if field in DATA_REFERENCES:
                want = _data_ids(alone, field, want, start, mapping)
            if field in ("qpos0", "qpos_spring") and int(alone.jnt_type[index]) == 0:
                pos, quat = part.move(want[:3], want[3:])
                if (
                    int(alone.jnt_bodyid[index])
                    and int(alone.body_parentid[alone.jnt_bodyid[index]]) == 0
                ):
                    want = np.concatenate([pos, quat])
            if not _close(want, got):
                problems.append(
                    f"{kind} {_label(alone, kind, index, part.prefix)}: {field} differs"
                )
    return problems


def _data_ids(alone: Any, field: str, values: Any, start: int, mapping: Mapping) -> Any:
    kinds = DATA_REFERENCES[field]
    if kinds in KINDS:
        return _ids(values, kinds, mapping)
    types = np.asarray(getattr(alone, kinds))[start : start + len(values)]
    table = _WRAP_KINDS if field == "wrap_objid" else OBJECT_KINDS
    return np.array(
        [_ids([v], table.get(int(t)), mapping)[0] for v, t in zip(values, types, strict=True)]
    )


def _key_problems(parts: Sequence[PlacedPart], scene: Any, mappings: list[Mapping]) -> list[str]:
    """Each part's keys, by prefixed name (unnamed in order): the keyframe rule, per object."""
    problems = []
    for index, (part, mapping) in enumerate(zip(parts, mappings, strict=True)):
        for key, other in enumerate(mapping["key"]):
            if other < 0:
                continue
            label = f"key {_label(part.alone, 'key', key, part.prefix)}"
            for each, (placed, its) in enumerate(zip(parts, mappings, strict=True)):
                own = key if each == index else None
                problems += [
                    f"{label}: {text}" for text in _state_problems(placed, its, scene, own, other)
                ]
            if scene.key_time[other] != part.alone.key_time[key]:
                problems.append(f"{label}: key_time {scene.key_time[other]}")
    return problems


def _state_problems(
    part: PlacedPart, mapping: Mapping, scene: Any, key: int | None, other: int
) -> list[str]:
    """The part's entries of the scene's key ``other``: its key ``key``, or its initial state."""
    alone, problems = part.alone, []

    def value(field: str, initial: Any) -> Any:
        return np.asarray(getattr(alone, field)[key]) if key is not None else initial

    qpos = value("key_qpos", alone.qpos0)
    qvel = value("key_qvel", np.zeros(alone.nv))
    for joint, there in enumerate(mapping["jnt"]):
        if there < 0:
            continue
        start, size = int(alone.jnt_qposadr[joint]), _qpos_count(alone, joint)
        want = np.array(qpos[start : start + size], dtype=float)
        dof, dofs = int(alone.jnt_dofadr[joint]), _dof_count(alone, joint)
        speed = np.array(qvel[dof : dof + dofs], dtype=float)
        body = int(alone.jnt_bodyid[joint])
        if size == 7 and int(alone.body_parentid[body]) == 0:
            want = np.concatenate(part.move(want[:3], want[3:]))
            speed[:3] = part.turn(speed[:3])
        at, dat = int(scene.jnt_qposadr[there]), int(scene.jnt_dofadr[there])
        got, moving = scene.key_qpos[other][at : at + size], scene.key_qvel[other][dat : dat + dofs]
        label = f"joint {_label(alone, 'jnt', joint, part.prefix)}"
        if not (
            _close(want[:3], got[:3]) and _same_rotation(want[3:], got[3:])
            if size == 7
            else _close(want, got)
        ):
            problems.append(f"{label}: key_qpos {got.tolist()}, expected {want.tolist()}")
        if not _close(speed, moving):
            problems.append(f"{label}: key_qvel {moving.tolist()}, expected {speed.tolist()}")
    ctrl = value("key_ctrl", np.zeros(alone.nu))
    act = value("key_act", np.zeros(alone.na))
    for actuator, there in enumerate(mapping["actuator"]):
        if there < 0:
            continue
        label = f"actuator {_label(alone, 'actuator', actuator, part.prefix)}"
        if not _close(ctrl[actuator], scene.key_ctrl[other][there]):
            problems.append(
                f"{label}: key_ctrl {scene.key_ctrl[other][there]}, expected {ctrl[actuator]}"
            )
        start, count = int(alone.actuator_actadr[actuator]), int(alone.actuator_actnum[actuator])
        if start >= 0:
            there_act = int(scene.actuator_actadr[there])
            got = scene.key_act[other][there_act : there_act + count]
            if not _close(act[start : start + count], got):
                problems.append(f"{label}: key_act {got.tolist()}")
    for body in range(1, alone.nbody):
        mocap, there = int(alone.body_mocapid[body]), int(mapping["body"][body])
        if mocap < 0 or there < 0:
            continue
        pos = value("key_mpos", alone.body_pos[body]).reshape(-1, 3)[
            mocap if key is not None else 0
        ]
        quat = value("key_mquat", alone.body_quat[body]).reshape(-1, 4)[
            mocap if key is not None else 0
        ]
        want_pos, want_quat = part.move(pos, quat)
        index = int(scene.body_mocapid[there])
        if not (
            _close(want_pos, scene.key_mpos[other].reshape(-1, 3)[index])
            and _same_rotation(want_quat, scene.key_mquat[other].reshape(-1, 4)[index])
        ):
            problems.append(
                f"mocap body {_label(alone, 'body', body, part.prefix)}: key_mpos/key_mquat"
            )
    return problems
