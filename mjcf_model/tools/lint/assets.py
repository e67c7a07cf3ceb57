"""Asset and class rules (``A``): what a model declares and nothing uses, or loads twice.

What is used is read from MuJoCo's compile (a geom's mesh, a material's textures, a
skybox), so references through default classes count. Default classes are read from
the tree: a class is used when an element names it (``class``, ``childclass``) or a
class inside it is used. A model with kept ``<include>`` elements is judged on what is
in the tree only: load it with ``inline_includes=True`` (the command line does).

Only what the model's own file declares is judged: assets and classes an included file
declares are shared with every model that includes it (dm_control's
``common/materials.xml``), and a file with no body, geom, site, actuator, tendon or
sensor is a library of them for others (:func:`is_library`).
"""

from __future__ import annotations

from collections.abc import Iterator

from mjcf_model.files.provenance import file_references
from mjcf_model.nodes.base import AnyElement, Element, attribute_items, get_attribute
from mjcf_model.serializers.locations import read_from
from mjcf_model.tools.lint.findings import Finding, rule
from mjcf_model.tools.lint.subject import Subject
from mjcf_model.tree.defaults import DefaultClasses
from mjcf_model.tree.traversal import keyed_walk, walk

__all__ = ["is_library", "used_assets"]

#: The assets :func:`used_assets` judges: tag, and the compiled count.
_ASSETS = (("mesh", "nmesh"), ("material", "nmat"), ("texture", "ntex"), ("hfield", "nhfield"))


def used_assets(subject: Subject) -> dict[str, set[int]]:
    """The rows of the meshes, materials, textures and height fields something uses.

    A geom uses its mesh or height field, anything with a material its material, a
    material its textures; a skybox texture is used by the renderer itself.
    """
    import mujoco

    m = subject.physics
    geom_type = m.geom_type
    used: dict[str, set[int]] = {tag: set() for tag, _ in _ASSETS}
    meshes = (geom_type == int(mujoco.mjtGeom.mjGEOM_MESH)) | (
        geom_type == int(mujoco.mjtGeom.mjGEOM_SDF)
    )
    used["mesh"].update(int(i) for i in m.geom_dataid[meshes] if i >= 0)
    hfields = geom_type == int(mujoco.mjtGeom.mjGEOM_HFIELD)
    used["hfield"].update(int(i) for i in m.geom_dataid[hfields] if i >= 0)
    for array in dir(m):
        if array.endswith("_matid") and not array.startswith("mat_"):
            used["material"].update(int(i) for i in getattr(m, array).ravel() if i >= 0)
    textures = m.mat_texid[sorted(used["material"])] if used["material"] else []
    used["texture"].update(int(i) for i in (t for row in textures for t in row) if i >= 0)
    skybox = int(mujoco.mjtTexture.mjTEXTURE_SKYBOX)
    used["texture"].update(i for i in range(m.ntex) if int(m.tex_type[i]) == skybox)
    return used


def _asset_paths(subject: Subject, tag: str, count: int) -> list[tuple[int, ...]] | None:
    """The index path of each compiled ``tag`` asset, by row; ``None``: cannot tell.

    MuJoCo numbers the assets of a kind in the order they are written; one added by an
    ``<attach>`` or hidden in a kept ``<include>`` makes the counts differ.
    """
    sections = subject.model.children
    paths: list[tuple[int, ...]] = [
        path
        for path, element in walk(subject.model)
        if element.tag == tag and len(path) == 2 and _tag(sections[path[0]]) == "asset"
    ]
    return paths if len(paths) == count else None


def _tag(node: object) -> str | None:
    return node.tag if isinstance(node, Element) else None


def is_library(subject: Subject) -> bool:
    """Whether the model declares assets and classes for others: nothing in it uses any."""
    m = subject.physics
    users = (m.ngeom, m.nsite, m.nu, m.ntendon, m.nsensor, m.nskin, m.nbody - 1)
    return not any(users)


def _own(subject: Subject, element: AnyElement) -> bool:
    """Whether ``element`` was read from the model's own file (not from an included one)."""
    return read_from(element)[0] == read_from(subject.model)[0]


@rule(
    "A401",
    "unused-asset",
    "warning",
    "a mesh, material, texture or height field nothing uses",
)
def unused_asset(subject: Subject) -> Iterator[Finding]:
    """An asset no geom, site, tendon, skin or material uses (skyboxes count as used).

    MuJoCo still loads and compiles it: a mesh costs its file's reading and its
    convex hull, and the compiled model carries it.
    """
    if is_library(subject):
        return
    m = subject.physics
    used = used_assets(subject)
    for tag, count_name in _ASSETS:
        count = int(getattr(m, count_name))
        unused = [row for row in range(count) if row not in used[tag]]
        if not unused:
            continue
        paths = _asset_paths(subject, tag, count)
        if paths is None:
            continue  # rows this tree cannot place (attached or included assets)
        for row in unused:
            found = subject.element(paths[row])
            if found is None or not _own(subject, found[0]):
                continue
            yield subject.finding(
                "A401",
                paths[row],
                f"{tag} {_asset_name(subject, paths[row], row)} is used by nothing: MuJoCo "
                "loads and compiles it all the same; remove it (or use it)",
            )


def _asset_name(subject: Subject, path: tuple[int, ...], row: int) -> str:
    found = subject.element(path)
    name = get_attribute(found[0], "name") if found is not None else None
    if name:
        return repr(name)
    file = get_attribute(found[0], "file") if found is not None else None
    return f"{row} (file {file!r})" if file else str(row)


@rule(
    "A402",
    "unused-class",
    "warning",
    "a default class no element names, directly or through a class inside it",
)
def unused_class(subject: Subject) -> Iterator[Finding]:
    """A ``<default class>`` no ``class`` or ``childclass`` names, nor a class nested in it."""
    model = subject.model
    if is_library(subject) or any(key == "include" for _, key, _ in keyed_walk(model)):
        return
    classes = DefaultClasses.of(model)
    named: set[str] = set()
    for element, key, _ in keyed_walk(model):
        if key is None or key.startswith("default"):
            continue
        for attribute in ("class", "childclass"):
            value = get_attribute(element, attribute)
            if isinstance(value, str):
                named.add(value)
    used = {ancestor for name in named for ancestor in classes.chain(name)}
    for path, element in walk(model):
        name = get_attribute(element, "class") if element.tag == "default" else None
        if (
            isinstance(name, str)
            and name not in used
            and name in classes.parents
            and _own(subject, element)
        ):
            yield subject.finding(
                "A402",
                path,
                f"default class {name!r} is used by nothing: no element names it in class= "
                "or childclass=, nor a class inside it; remove it (or name it where meant)",
            )


def _settings(element: AnyElement) -> tuple[tuple[str, object], ...]:
    return tuple((name, value) for name, value in attribute_items(element) if name != "name")


@rule(
    "A403",
    "duplicate-asset-file",
    "warning",
    "two assets of one kind that load the same file with the same settings",
)
def duplicate_asset_file(subject: Subject) -> Iterator[Finding]:
    """Two meshes (textures, height fields, skins) reading one file with the same settings.

    MuJoCo reads, stores and compiles it twice; point every reference at one of them.
    """
    seen: dict[tuple[str, object, tuple[tuple[str, object], ...]], AnyElement] = {}
    places = {id(element): path for path, element in walk(subject.model)}
    for reference in file_references(subject.model):
        if not reference.key.startswith("asset/"):
            continue
        signature = (reference.key, reference.path.resolve(), _settings(reference.element))
        first = seen.setdefault(signature, reference.element)
        if first is not reference.element:
            path = places[id(reference.element)]
            tag = reference.key.removeprefix("asset/")
            yield subject.finding(
                "A403",
                path,
                f"{tag} {get_attribute(reference.element, 'name') or reference.text!r} loads "
                f"{reference.text!r} with the same settings as {tag} "
                f"{get_attribute(first, 'name') or reference.text!r}: MuJoCo reads and stores "
                "it twice; keep one and point every reference at it",
            )
