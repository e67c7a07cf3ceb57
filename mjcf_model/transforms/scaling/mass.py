"""Masses MuJoCo computes from a geom's density, under each mass policy.

A geom without a ``mass`` weighs its ``density`` times its volume, or, for a
shell (``shellinertia="true"`` on a primitive geom, ``inertia="shell"`` on the
mesh of a mesh or SDF geom), times its area. Scaling the geom's lengths by ``s``
therefore multiplies that mass by ``s**3``, or ``s**2`` for a shell, which is what
``mass="volume"`` wants. ``mass="keep"`` instead gives every such geom (outside
the world body, whose geoms weigh nothing) the density that keeps its mass, so a
body mixing written masses and densities keeps its mass and its centre of mass
moves with its geoms.

>>> from mjcf_model import Geom
>>> from mjcf_model.transforms.scaling.context import ScaleContext
>>> geom_density(Geom(size=[0.1]), (), ScaleContext(factors=(2.0, 2.0, 2.0)))
{'density': 125.0}
"""

from __future__ import annotations

from collections.abc import Sequence

from mjcf_model.files.provenance import file_stem
from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.pieces import Changes, builtin_default
from mjcf_model.values import numbers_of

__all__ = ["geom_density", "is_shell"]

#: The geom types whose inertia comes from a mesh asset.
_MESH_TYPES = frozenset({"mesh", "sdf"})


def _mesh_name(mesh: AnyElement) -> str | None:
    """A mesh's name: its own, or (as MuJoCo names it) its file's stem."""
    name = get_attribute(mesh, "name")
    if isinstance(name, str):
        return name
    file = get_attribute(mesh, "file")
    return file_stem(file) if isinstance(file, str) else None


def _shell_meshes(context: ScaleContext) -> frozenset[str]:
    """The names of the model's meshes whose inertia is computed on their surface."""
    model = context.model
    if model is None or model.tag != "mujoco":
        return frozenset()
    found = set()
    for section in model.elements:  # meshes stand only in the top-level <asset> sections
        if section.tag != "asset":
            continue
        for element in section.elements:
            if (
                element.tag == "mesh"
                and context.classes.resolve(element, (model, section), "inertia") == "shell"
            ):
                name = _mesh_name(element)
                if name is not None:
                    found.add(name)
    return frozenset(found)


def is_shell(geom: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext) -> bool:
    """Whether MuJoCo spreads the mass of ``geom`` over its surface rather than its volume.

    Examples:
        >>> from mjcf_model import Geom
        >>> from mjcf_model.transforms.scaling.context import ScaleContext
        >>> context = ScaleContext(factors=(2.0, 2.0, 2.0))
        >>> is_shell(Geom(type="box", shellinertia=True), (), context)
        True
        >>> is_shell(Geom(type="box"), (), context)
        False

    """
    kind, mesh, shell = context.classes.resolve_many(geom, ancestors, _SHELL_READ)
    return _is_shell(kind, mesh, shell, context)


#: What decides whether a geom's mass is on its surface.
_SHELL_READ = ("type", "mesh", "shellinertia")
#: What :func:`geom_density` reads: the mass, the density, then :data:`_SHELL_READ`.
_DENSITY_READ = ("mass", "density", *_SHELL_READ)


def _is_shell(kind: object, mesh: object, shell: object, context: ScaleContext) -> bool:
    """:func:`is_shell` for a geom's resolved ``type``, ``mesh`` and ``shellinertia``."""
    if kind in _MESH_TYPES:
        return mesh in context.cached("shell meshes", lambda: _shell_meshes(context))
    return shell in (True, "true")


def _in_world(ancestors: Sequence[AnyElement]) -> bool:
    """Whether the nearest body around an element is the world body."""
    for ancestor in reversed(ancestors):
        if ancestor.tag in ("body", "worldbody"):
            return ancestor.tag == "worldbody"
    return False


def _may_spread(geom: AnyElement, context: ScaleContext) -> bool:
    """Whether ``geom`` may spread its mass over its surface (cheap: most models have none)."""
    if get_attribute(geom, "shellinertia") is not None:
        return True
    return context.cached("surfaces", lambda: _surfaces_set(context))


def _surfaces_set(context: ScaleContext) -> bool:
    """Whether a shell mesh or a class's ``shellinertia`` stands in the model."""
    classes = context.classes.layers.items()
    return bool(_shell_meshes(context)) or any(
        get_attribute(setting, "shellinertia") is not None
        for (_, tag), held in classes
        if tag == "geom"
        for setting in held
    )


def _weighs_its_body(ancestors: Sequence[AnyElement], context: ScaleContext) -> bool:
    """Whether a geom's mass counts in its body's: no ``<inertial>`` there replaces it.

    Under the compiler's ``inertiafromgeom="true"`` geoms always count.
    """
    body = next((a for a in reversed(ancestors) if a.tag == "body"), None)
    if body is None or not any(child.tag == "inertial" for child in body.elements):
        return True
    model = context.model
    sections = model.elements if model is not None and model.tag == "mujoco" else ()
    settings = [
        get_attribute(section, "inertiafromgeom")
        for section in sections
        if section.tag == "compiler"
    ]
    return any(setting in (True, "true") for setting in settings)


def geom_density(
    geom: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """Under ``mass="keep"``, the density that keeps a density-weighed geom's mass.

    The density is the geom's own, its classes', or MuJoCo's built-in one,
    divided by the volume factor (the area factor for a shell). A geom with a
    mass (its own or its classes') and a geom of the world body are left alone,
    and so is every geom under ``mass="volume"``.

    Examples:
        >>> from mjcf_model import Geom
        >>> from mjcf_model.transforms.scaling.context import ScaleContext
        >>> context = ScaleContext(factors=(2.0, 2.0, 2.0))
        >>> geom_density(Geom(type="box", shellinertia=True, density=100), (), context)
        {'density': 25.0}
        >>> geom_density(Geom(mass=1.0), (), context)
        {}

    """
    if _in_world(ancestors):
        return {}
    if context.mass != "keep" and not _may_spread(geom, context):
        return {}
    mass, density, kind, mesh, shell = context.classes.resolve_many(geom, ancestors, _DENSITY_READ)
    if mass is not None:
        return {}
    value = (numbers_of(density) or builtin_default("geom", "density"))[0]
    surface = _is_shell(kind, mesh, shell, context)
    if context.mass != "keep":
        if surface and value != 0 and _weighs_its_body(ancestors, context):
            name = get_attribute(geom, "name")
            context.surface_masses.append(
                f"<geom name={name!r}>" if name else f"a <geom mesh={mesh!r}>"
            )
        return {}
    return {"density": value / (context.area if surface else context.volume)}
