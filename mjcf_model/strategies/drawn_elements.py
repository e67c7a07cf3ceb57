"""Strategies for single elements: geoms, joints, sites, materials, and any typed class."""

from __future__ import annotations

from typing import Any

import attrs
from hypothesis import strategies as st

from mjcf_model.nodes import (
    Geom,
    Material,
    Mesh,
    Site,
)
from mjcf_model.nodes import Joint as JointNode
from mjcf_model.nodes.base import TypedElement, field_table
from mjcf_model.strategies.primitives import (
    _E,
    _angle,
    _Draw,
    _length,
    _mass,
    _number,
    _optional,
    _position,
    _rgba,
    _size,
    _unit_quat,
    _vec,
    names,
)
from mjcf_model.values import Floats

__all__ = [
    "element_values",
    "elements",
    "geoms",
    "joints",
    "materials",
    "meshes",
    "sites",
]


_SIZE_COUNT = {"sphere": 1, "capsule": 2, "cylinder": 2, "box": 3, "ellipsoid": 3}


_FLOAT = st.floats(allow_nan=False, allow_infinity=False, width=64)

# Strategies built once: hypothesis validates each new strategy object, which would
# otherwise dominate the time a drawn model takes.
_FRICTION = st.tuples(_length(0.1, 2.0), _length(0.001, 0.1))
_MESH_SCALE = _vec(3, 0.5, 2.0)
_AXIS = _vec(3).filter(lambda a: sum(v * v for v in a) > 0.1)
_DAMPING = st.tuples(_length(0.0, 2.0))


_VALUE_BY_CONVERTER: dict[str, st.SearchStrategy[Any]] = {
    "to_str": names(),
    "to_float": _FLOAT,
    "to_int": st.integers(-1000, 1000),
    "to_bool": st.booleans(),
    "to_floats": st.lists(_FLOAT, max_size=6).map(tuple),
    "to_ints": st.lists(st.integers(0, 100), max_size=6).map(tuple),
    "to_vec2": st.tuples(_FLOAT, _FLOAT),
    "to_vec3": st.tuples(_FLOAT, _FLOAT, _FLOAT),
    "to_vec4": st.tuples(_FLOAT, _FLOAT, _FLOAT, _FLOAT),
    "to_vec6": st.tuples(*[_FLOAT] * 6),
    "to_vec1to3": st.lists(_FLOAT, min_size=1, max_size=3).map(tuple),
    "to_vec1to2": st.lists(_FLOAT, min_size=1, max_size=2).map(tuple),
    "to_vec1to5": st.lists(_FLOAT, min_size=1, max_size=5).map(tuple),
}


@st.composite
def geoms(draw: _Draw[Any], name: str | None = None, material: str | None = None) -> Geom:
    """A primitive geom (sphere, capsule, cylinder, box, ellipsoid) with a valid size.

    Examples:
        >>> geoms().example().type in {"sphere", "capsule", "cylinder", "box", "ellipsoid"}
        True

    """
    geom_type = draw(st.sampled_from(sorted(_SIZE_COUNT)))
    size = draw(st.tuples(*[_size() for _ in range(_SIZE_COUNT[geom_type])]))
    return Geom(
        name=name,
        type=geom_type,
        size=size,
        pos=draw(_optional(_position())),
        quat=draw(_optional(_unit_quat())),
        rgba=draw(_optional(_rgba())),
        material=material,
        group=draw(_optional(st.integers(0, 5))),
        friction=draw(_optional(_FRICTION)),
        mass=draw(_optional(_mass())),
    )


#: The corners of a unit cube, which a drawn mesh stretches and jitters.
_CORNERS = [(x, y, z) for x in (-1.0, 1.0) for y in (-1.0, 1.0) for z in (-1.0, 1.0)]


def _outward(vertices: list[Floats], face: tuple[int, int, int]) -> tuple[int, int, int]:
    """``face`` ordered so that its normal points away from the vertices' centroid."""
    a, b, c = (vertices[i] for i in face)
    centre = [sum(v[k] for v in vertices) / len(vertices) for k in range(3)]
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    normal = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    outward = sum(normal[k] * (a[k] - centre[k]) for k in range(3))
    return face if outward > 0 else (face[0], face[2], face[1])


@st.composite
def meshes(draw: _Draw[Any], name: str) -> Mesh:
    """A mesh written inline: a stretched, jittered box, or a tetrahedron with its faces.

    No file is needed: the vertices (and for the tetrahedron the outward faces)
    are the mesh's own attributes.

    Examples:
        >>> len(meshes(name="m").example().vertex) in {12, 24}
        True

    """
    half = draw(st.tuples(*[_size(-2.0, 0.0) for _ in range(3)]))
    if draw(st.booleans()):
        jitter = draw(st.lists(_number(0.8, 1.0), min_size=24, max_size=24))
        box = [
            tuple(c[k] * half[k] * jitter[3 * i + k] for k in range(3))
            for i, c in enumerate(_CORNERS)
        ]
        return Mesh(name=name, vertex=tuple(v for corner in box for v in corner))
    tetra: list[Floats] = [
        (0.0, 0.0, 0.0),
        (half[0], 0.0, 0.0),
        (0.0, half[1], 0.0),
        (0.0, 0.0, half[2]),
    ]
    faces = [_outward(tetra, f) for f in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3))]
    return Mesh(
        name=name,
        vertex=tuple(v for corner in tetra for v in corner),
        face=tuple(i for f in faces for i in f),
        scale=draw(_optional(_MESH_SCALE)),
    )


@st.composite
def joints(
    draw: _Draw[Any], name: str | None = None, scalar: bool = False, angle: str = "degree"
) -> JointNode:
    """A hinge, slide or (unless ``scalar``) ball joint.

    A hinge's range is in ``angle`` units (the model's ``<compiler angle>``), a
    slide's in metres.

    Examples:
        >>> joints(scalar=True).example().type in {"hinge", "slide"}
        True

    """
    kinds = ["hinge", "slide"] if scalar else ["hinge", "slide", "ball"]
    joint_type = draw(st.sampled_from(kinds))
    limits = None
    if joint_type == "hinge" and draw(st.booleans()):
        low = draw(_angle(angle))
        limits = (low, low + abs(draw(_angle(angle))) + (1.0 if angle == "degree" else 0.02))
    elif joint_type == "slide" and draw(st.booleans()):
        low = draw(_number(-2.0, 0.0))
        limits = (low, low + draw(_length(0.1, 2.0)))
    return JointNode(
        name=name,
        type=joint_type,
        axis=draw(_optional(_AXIS)),
        pos=draw(_optional(_vec(3))),
        range=limits,
        damping=draw(_optional(_DAMPING)),
        armature=draw(_optional(_length(0.0, 0.1))),
    )


@st.composite
def sites(draw: _Draw[Any], name: str | None = None) -> Site:
    """A small spherical site.

    Examples:
        >>> sites(name="tip").example().name
        'tip'

    """
    return Site(name=name, pos=draw(_optional(_vec(3))), size=(draw(_length(0.005, 0.05)),))


@st.composite
def materials(draw: _Draw[Any], name: str, texture: str | None = None) -> Material:
    """A material, optionally using a texture.

    Examples:
        >>> materials(name="m").example().name
        'm'

    """
    return Material(
        name=name,
        texture=texture,
        rgba=draw(_optional(_rgba())),
        specular=draw(_optional(_length(0.0, 1.0))),
        texrepeat=(1.0, 1.0) if texture else None,
    )


def _field_values(cls: type[TypedElement]) -> dict[str, st.SearchStrategy[Any]]:
    """A strategy per field of ``cls`` that produces values its converter accepts."""
    strategies: dict[str, st.SearchStrategy[Any]] = {}
    fields = {f.name: f for f in attrs.fields(cls)}
    for field_name in field_table(cls).values():
        field = fields[field_name]
        converter = getattr(field.converter, "__name__", "")
        strategies[field_name] = _VALUE_BY_CONVERTER.get(converter, st.none())
    return strategies


def element_values(cls: type[TypedElement]) -> st.SearchStrategy[dict[str, Any]]:
    """Keyword arguments for ``cls``: some of its attribute fields, each with a value it accepts.

    Keyword fields (``Geom.type``...) draw from their valid keywords.

    Examples:
        >>> values = element_values(Geom).example()
        >>> Geom(**values).tag
        'geom'

    """
    values = {name: _optional(strategy) for name, strategy in _field_values(cls).items()}
    validated = {
        f.name: f for f in attrs.fields(cls) if f.validator is not None and f.name in values
    }
    for name, field in validated.items():
        allowed = getattr(field.validator, "allowed", None)
        if allowed:
            values[name] = _optional(st.sampled_from(sorted(allowed)))
    return st.fixed_dictionaries({}, optional=values)


def elements(cls: type[_E]) -> st.SearchStrategy[_E]:
    """Any instance of a typed node class, with arbitrary well-formed attribute values.

    Keyword fields (``Geom.type``...) draw from their valid keywords. The values
    need not make physical sense: use this for serializer round trips.

    Examples:
        >>> elements(Geom).example().tag
        'geom'

    """
    return element_values(cls).map(lambda values: cls(**values))
