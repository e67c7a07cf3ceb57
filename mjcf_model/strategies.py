"""Hypothesis strategies for MJCF nodes and whole models (``pip install mjcf-model[strategies]``).

Use them to property-test code that builds, edits or converts MJCF:

* :func:`models` draws complete models that MuJoCo compiles: a kinematic tree
  with joints, geoms, sites, cameras and lights, frames, default classes,
  textures and materials, actuators, sensors, tendons, equality constraints,
  contact pairs and exclusions, a keyframe and custom data; every name is
  unique in its namespace and every reference resolves. Comments are sprinkled in.
* :func:`geoms`, :func:`joints`, :func:`sites`, :func:`bodies`, :func:`materials`
  draw single nodes that are valid where they stand.
* :func:`elements` draws any typed node class with arbitrary (well-formed, not
  necessarily meaningful) attribute values: for serializer round trips.

Example:
    >>> from hypothesis import given
    >>> from serializers import dumps, loads
    >>> @given(models())
    ... def test_round_trip(model):
    ...     assert loads(dumps(model)) == model
    >>> test_round_trip()

"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from typing import Any, TypeVar

import attrs
from hypothesis import strategies as st

from mjcf_model.nodes import (
    Actuator,
    Asset,
    Body,
    Camera,
    Contact,
    Custom,
    Default,
    Equality,
    EqualityJoint,
    Exclude,
    Fixed,
    FramePos,
    FreeJoint,
    Geom,
    JointPos,
    Key,
    Keyframe,
    Light,
    Material,
    Motor,
    Mujoco,
    Numeric,
    Pair,
    Position,
    Sensor,
    Site,
    Tendon,
    TendonJoint,
    Texture,
    Touch,
    Velocity,
    Worldbody,
)
from mjcf_model.nodes import Frame as FrameNode
from mjcf_model.nodes import Joint as JointNode
from mjcf_model.nodes.base import Comment, Node, TypedElement, field_table
from mjcf_model.values import Floats

__all__ = [
    "bodies",
    "comments",
    "element_values",
    "elements",
    "geoms",
    "joints",
    "materials",
    "models",
    "names",
    "sites",
]

_T = TypeVar("_T")
_E = TypeVar("_E", bound=TypedElement)
_Draw = Callable[[st.SearchStrategy[_T]], _T]

_COMMENT_TEXT = st.text(
    st.characters(blacklist_categories=("Cs", "Cc"), blacklist_characters="-"), max_size=20
)
_NAME_CHARS = st.sampled_from("abcdefghijklmnopqrstuvwxyz_0123456789")


def comments() -> st.SearchStrategy[Comment]:
    """Comments with arbitrary text that XML allows (no ``--``).

    Example:
        >>> isinstance(comments().example(), Comment)
        True

    """
    return st.builds(lambda t: Comment(text=f" {t} "), _COMMENT_TEXT)


def names() -> st.SearchStrategy[str]:
    """Plausible element names: a letter followed by letters, digits and underscores."""
    return st.builds(
        lambda head, tail: head + "".join(tail),
        st.sampled_from("abcdefghijklmnopqrstuvwxyz"),
        st.lists(_NAME_CHARS, max_size=8),
    )


#: The smallest normal single-precision float. Every MuJoCo the library supports
#: compiles values from here up; before 4.0, MuJoCo rejects a number that is
#: subnormal, or that a single-precision field (``rgba``...) would round to zero.
_SMALLEST_COMPILABLE = 2.0**-126


def _compilable(value: float) -> float:
    return value if abs(value) >= _SMALLEST_COMPILABLE else 0.0


def _number(low: float, high: float) -> st.SearchStrategy[float]:
    """Finite numbers in ``[low, high]`` that every supported MuJoCo compiles."""
    return st.floats(low, high, allow_nan=False, allow_infinity=False).map(_compilable)


def _length(low: float = 0.01, high: float = 0.5) -> st.SearchStrategy[float]:
    return _number(low, high)


def _vec(n: int, low: float = -1.0, high: float = 1.0) -> st.SearchStrategy[Floats]:
    return st.tuples(*[_number(low, high) for _ in range(n)])


def _rgba() -> st.SearchStrategy[Floats]:
    return _vec(4, 0.0, 1.0)


def _unit_quat() -> st.SearchStrategy[Floats]:
    return _vec(4, -1.0, 1.0).filter(lambda q: sum(v * v for v in q) > 0.1)


_SIZE_COUNT = {"sphere": 1, "capsule": 2, "cylinder": 2, "box": 3, "ellipsoid": 3}


@st.composite
def geoms(draw: _Draw[Any], name: str | None = None, material: str | None = None) -> Geom:
    """A primitive geom (sphere, capsule, cylinder, box, ellipsoid) with a valid size.

    Example:
        >>> geoms().example().type in {"sphere", "capsule", "cylinder", "box", "ellipsoid"}
        True

    """
    geom_type = draw(st.sampled_from(sorted(_SIZE_COUNT)))
    size = draw(st.tuples(*[_length() for _ in range(_SIZE_COUNT[geom_type])]))
    return Geom(
        name=name,
        type=geom_type,
        size=size,
        pos=draw(st.none() | _vec(3)),
        quat=draw(st.none() | _unit_quat()),
        rgba=draw(st.none() | _rgba()),
        material=material,
        group=draw(st.none() | st.integers(0, 5)),
        friction=draw(st.none() | st.tuples(_length(0.1, 2.0), _length(0.001, 0.1))),
    )


@st.composite
def joints(draw: _Draw[Any], name: str | None = None, scalar: bool = False) -> JointNode:
    """A hinge, slide or (unless ``scalar``) ball joint.

    Example:
        >>> joints(scalar=True).example().type in {"hinge", "slide"}
        True

    """
    kinds = ["hinge", "slide"] if scalar else ["hinge", "slide", "ball"]
    joint_type = draw(st.sampled_from(kinds))
    limits = None
    if joint_type != "ball" and draw(st.booleans()):
        low = draw(_number(-2.0, 0.0))
        limits = (low, low + draw(_length(0.1, 2.0)))
    return JointNode(
        name=name,
        type=joint_type,
        axis=draw(st.none() | _vec(3).filter(lambda a: sum(v * v for v in a) > 0.1)),
        pos=draw(st.none() | _vec(3)),
        range=limits,
        damping=draw(st.none() | st.tuples(_length(0.0, 2.0))),
        armature=draw(st.none() | _length(0.0, 0.1)),
    )


@st.composite
def sites(draw: _Draw[Any], name: str | None = None) -> Site:
    """A small spherical site.

    Example:
        >>> sites(name="tip").example().name
        'tip'

    """
    return Site(name=name, pos=draw(st.none() | _vec(3)), size=(draw(_length(0.005, 0.05)),))


@st.composite
def materials(draw: _Draw[Any], name: str, texture: str | None = None) -> Material:
    """A material, optionally using a texture.

    Example:
        >>> materials(name="m").example().name
        'm'

    """
    return Material(
        name=name,
        texture=texture,
        rgba=draw(st.none() | _rgba()),
        specular=draw(st.none() | _length(0.0, 1.0)),
        texrepeat=(1.0, 1.0) if texture else None,
    )


class _Names:
    """Hands out names unique per namespace (``body0``, ``geom3``...)."""

    def __init__(self) -> None:
        self.counters: dict[str, itertools.count[int]] = {}

    def __call__(self, namespace: str) -> str:
        counter = self.counters.setdefault(namespace, itertools.count())
        return f"{namespace}{next(counter)}"


@attrs.define
class _Registry:
    """What a model being drawn declares, for the sections that refer to it."""

    names: _Names = attrs.field(factory=_Names)
    scalar_joints: list[str] = attrs.field(factory=list)
    joint_sizes: list[int] = attrs.field(factory=list)
    bodies: list[str] = attrs.field(factory=list)
    geoms: list[str] = attrs.field(factory=list)
    sites: list[str] = attrs.field(factory=list)
    materials: list[str] = attrs.field(factory=list)
    classes: list[str] = attrs.field(factory=list)


def _maybe_comment(draw: _Draw[Any], children: list[Node]) -> list[Node]:
    if draw(st.integers(0, 4)) == 0:
        children.insert(draw(st.integers(0, len(children))), draw(comments()))
    return children


@st.composite
def bodies(
    draw: _Draw[Any], depth: int = 2, registry: _Registry | None = None, top: bool = False
) -> Body:
    """A body subtree: every body has a geom, so moving bodies have mass.

    Example:
        >>> len(bodies().example().geoms) >= 1
        True

    """
    reg = registry if registry is not None else _Registry()
    name = reg.names("body")
    reg.bodies.append(name)
    children: list[Node] = []
    if top and draw(st.booleans()):
        children.append(FreeJoint(name=reg.names("joint")))
        reg.joint_sizes.append(7)
    else:
        for index in range(draw(st.integers(0, 2))):
            # MuJoCo allows no rotation after a ball joint: a ball joint stands alone.
            joint = draw(joints(name=reg.names("joint"), scalar=index > 0))
            children.append(joint)
            reg.joint_sizes.append(4 if joint.type == "ball" else 1)
            if joint.type == "ball":
                break
            reg.scalar_joints.append(str(joint.name))
    for _ in range(draw(st.integers(1, 3))):
        geom_name = reg.names("geom") if draw(st.booleans()) else None
        material = draw(st.none() | st.sampled_from(reg.materials)) if reg.materials else None
        geom = draw(geoms(name=geom_name, material=material))
        if reg.classes and draw(st.booleans()):
            geom = attrs.evolve(geom, dclass=draw(st.sampled_from(reg.classes)))
        children.append(geom)
        if geom_name:
            reg.geoms.append(geom_name)
    if draw(st.booleans()):
        site_name = reg.names("site")
        children.append(draw(sites(name=site_name)))
        reg.sites.append(site_name)
    if draw(st.integers(0, 3)) == 0:
        framed = draw(geoms(name=reg.names("geom")))
        reg.geoms.append(str(framed.name))
        frame = FrameNode(pos=draw(_vec(3)), children=[framed])
        children.insert(draw(st.integers(0, len(children))), frame)
    if draw(st.integers(0, 4)) == 0:
        children.append(Camera(name=reg.names("camera"), pos=draw(_vec(3)), fovy=45.0))
    if draw(st.integers(0, 5)) == 0:
        children.append(Light(name=reg.names("light"), pos=draw(_vec(3)), dir=(0.0, 0.0, -1.0)))
    if depth > 0:
        for _ in range(draw(st.integers(0, 2))):
            children.append(draw(bodies(depth=depth - 1, registry=reg)))
    return Body(
        name=name,
        pos=draw(_vec(3)),
        quat=draw(st.none() | _unit_quat()),
        children=_maybe_comment(draw, children),
    )


def _defaults(draw: _Draw[Any], reg: _Registry) -> Default:
    classes: list[Node] = []
    for _ in range(draw(st.integers(0, 2))):
        name = reg.names("class")
        reg.classes.append(name)
        inner = [Geom(rgba=draw(_rgba()), density=draw(_length(100.0, 2000.0)))]
        classes.append(Default(dclass=name, children=inner))
    main: list[Node] = [JointNode(damping=(draw(_length(0.0, 1.0)),)), *classes]
    return Default(children=_maybe_comment(draw, main))


def _assets(draw: _Draw[Any], reg: _Registry) -> Asset:
    children: list[Node] = []
    for _ in range(draw(st.integers(0, 2))):
        texture = None
        if draw(st.booleans()):
            texture = reg.names("texture")
            children.append(
                Texture(
                    name=texture,
                    type="2d",
                    builtin="checker",
                    width=32,
                    height=32,
                    rgb1=draw(_vec(3, 0.0, 1.0)),
                    rgb2=draw(_vec(3, 0.0, 1.0)),
                )
            )
        name = reg.names("material")
        children.append(draw(materials(name=name, texture=texture)))
        reg.materials.append(name)
    return Asset(children=children)


@st.composite
def models(draw: _Draw[Any], max_trees: int = 3) -> Mujoco:
    """A whole model that MuJoCo compiles, with names unique per namespace.

    Example:
        >>> import mujoco
        >>> from serializers import dumps
        >>> model = models().example()
        >>> mujoco.MjModel.from_xml_string(dumps(model)).nbody >= 2
        True

    """
    reg = _Registry()
    defaults = _defaults(draw, reg)
    assets = _assets(draw, reg)
    trees: list[Node] = [
        draw(bodies(registry=reg, top=True)) for _ in range(draw(st.integers(1, max_trees)))
    ]
    world = Worldbody(children=_maybe_comment(draw, trees))
    sections: list[Node] = [defaults, assets, world]
    actuators: list[Node] = []
    for joint in reg.scalar_joints:
        kind = draw(st.sampled_from([None, Motor, Position, Velocity]))
        if kind is not None:
            actuators.append(kind(name=reg.names("actuator"), joint=joint, ctrlrange=(-1.0, 1.0)))
    sensors: list[Node] = [
        JointPos(name=reg.names("sensor"), joint=j) for j in reg.scalar_joints[:2]
    ]
    for site in reg.sites[:2]:
        sensors.append(FramePos(name=reg.names("sensor"), objtype="site", objname=site))
        sensors.append(Touch(name=reg.names("sensor"), site=site))
    if actuators:
        sections.append(Actuator(children=actuators))
    if sensors:
        sections.append(Sensor(children=sensors))
    if len(reg.scalar_joints) >= 2:
        first, second = reg.scalar_joints[:2]
        parts = [TendonJoint(joint=first, coef=1.0), TendonJoint(joint=second, coef=-0.5)]
        sections.append(Tendon(children=[Fixed(name=reg.names("tendon"), children=parts)]))
        sections.append(
            Equality(
                children=[EqualityJoint(name=reg.names("equality"), joint1=first, joint2=second)]
            )
        )
    contact: list[Node] = []
    if len(reg.bodies) >= 2:
        contact.append(
            Exclude(name=reg.names("exclude"), body1=reg.bodies[0], body2=reg.bodies[-1])
        )
    if len(reg.geoms) >= 2:
        contact.append(Pair(name=reg.names("pair"), geom1=reg.geoms[0], geom2=reg.geoms[-1]))
    if contact:
        sections.append(Contact(children=contact))
    nq = sum(reg.joint_sizes)
    if nq and draw(st.booleans()):
        qpos = None if 7 in reg.joint_sizes or 4 in reg.joint_sizes else draw(_vec(nq))
        key = Key(
            name=reg.names("key"),
            time=draw(_length(0.0, 1.0)),
            qpos=qpos,
            ctrl=tuple(0.0 for _ in actuators) or None,
        )
        sections.append(Keyframe(children=[key]))
    if draw(st.booleans()):
        sections.append(Custom(children=[Numeric(name=reg.names("numeric"), data=draw(_vec(2)))]))
    return Mujoco(model=draw(st.none() | names()), children=_maybe_comment(draw, sections))


def _field_values(cls: type[TypedElement]) -> dict[str, st.SearchStrategy[Any]]:
    """A strategy per field of ``cls`` that produces values its converter accepts."""
    strategies: dict[str, st.SearchStrategy[Any]] = {}
    fields = {f.name: f for f in attrs.fields(cls)}
    for field_name in field_table(cls).values():
        field = fields[field_name]
        converter = getattr(field.converter, "__name__", "")
        strategies[field_name] = _VALUE_BY_CONVERTER.get(converter, st.none())
    return strategies


_FLOAT = st.floats(allow_nan=False, allow_infinity=False, width=64)
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


def element_values(cls: type[TypedElement]) -> st.SearchStrategy[dict[str, Any]]:
    """Keyword arguments for ``cls``: some of its attribute fields, each with a value it accepts.

    Keyword fields (``Geom.type``...) draw from their valid keywords.

    Example:
        >>> values = element_values(Geom).example()
        >>> Geom(**values).tag
        'geom'

    """
    values = {name: st.none() | strategy for name, strategy in _field_values(cls).items()}
    validated = {
        f.name: f for f in attrs.fields(cls) if f.validator is not None and f.name in values
    }
    for name, field in validated.items():
        allowed = getattr(field.validator, "allowed", None)
        if allowed:
            values[name] = st.none() | st.sampled_from(sorted(allowed))
    return st.fixed_dictionaries({}, optional=values)


def elements(cls: type[_E]) -> st.SearchStrategy[_E]:
    """Any instance of a typed node class, with arbitrary well-formed attribute values.

    Keyword fields (``Geom.type``...) draw from their valid keywords. The values
    need not make physical sense: use this for serializer round trips.

    Example:
        >>> elements(Geom).example().tag
        'geom'

    """
    return element_values(cls).map(lambda values: cls(**values))
