"""Assets a scene repeats, kept once: every copy's references follow the first.

Attaching one robot twice copies each of its meshes, textures and materials under a
second prefix; MuJoCo then reads, compiles and stores every copy. :func:`shared_assets`
keeps the first of each group of named assets that are the same but for their name
(the same tag, the same attributes, files compared where they resolve) and points
every reference to the others at it; :func:`mjcf_model.attach` and
:func:`mjcf_model.attach_all` do so with ``share_assets=True``. Textures go before the
materials that use them, so that materials made the same by it are shared too.

The compiled scene is the unshared one but for those assets: every body, joint, geom,
actuator and key array is the same, each geom's mesh (material, texture) being the
kept copy (``tests/mjcf_model/transforms/composition/test_shared_assets.py`` checks it
with MuJoCo on robosuite's Panda).

Examples:
    >>> from mjcf_model import dumps, loads
    >>> scene = loads(
    ...     '<mujoco><asset><material name="a_red" rgba="1 0 0 1"/>'
    ...     '<material name="b_red" rgba="1 0 0 1"/></asset><worldbody>'
    ...     '<geom size="1" material="a_red"/><geom size="1" material="b_red"/>'
    ...     "</worldbody></mujoco>"
    ... )
    >>> shared = shared_assets(scene)
    >>> print(dumps(shared.children[0]))
    <asset><material name="a_red" rgba="1 0 0 1"/></asset>
    >>> [g.material for g in shared.worldbody.geoms]
    ['a_red', 'a_red']

"""

from __future__ import annotations

from mjcf_model.files.provenance import file_references
from mjcf_model.nodes.base import AnyElement, Element, Node, attribute_items, get_attribute
from mjcf_model.nodes.root import Mujoco
from mjcf_model.transforms.naming.renaming import renamed
from mjcf_model.tree.traversal import with_children

__all__ = ["SHARED_KINDS", "shared_assets"]

#: The assets shared, in the order they are compared: a material is compared after the
#: textures it names have been shared.
SHARED_KINDS = ("texture", "mesh", "hfield", "skin", "material")


def shared_assets(model: Mujoco) -> Mujoco:
    """``model`` with each named asset that repeats an earlier one dropped, its uses moved.

    Two assets repeat each other when they have one tag and the same attributes but
    ``name``, a file attribute counting as the file it resolves to. Unnamed assets and
    assets inside a kept ``<include>`` are left alone. Returns ``model`` itself when
    nothing repeats.
    """
    for kind in SHARED_KINDS:
        model = _shared(model, kind)
    return model


def _shared(model: Mujoco, kind: str) -> Mujoco:
    files: dict[int, dict[str, str]] = {}
    for reference in file_references(model):
        files.setdefault(id(reference.element), {})[reference.attribute] = str(
            reference.path.resolve()
        )
    kept: dict[tuple[object, ...], str] = {}
    moved: dict[str, str] = {}
    for section in model.children:
        if not (isinstance(section, Element) and section.tag == "asset"):
            continue
        for asset in section.children:
            if not isinstance(asset, Element) or asset.tag != kind:
                continue
            name = get_attribute(asset, "name")
            if not isinstance(name, str) or not name:
                continue
            first = kept.setdefault(_signature(asset, files.get(id(asset), {})), name)
            if first != name:
                moved[name] = first
    if not moved:
        return model
    sections = [_without(child, kind, moved) for child in model.children]
    result = renamed(with_children(model, sections), {kind: moved})
    assert isinstance(result, Mujoco)
    return result


def _signature(asset: AnyElement, files: dict[str, str]) -> tuple[object, ...]:
    """What an asset is but for its name: its tag and attributes, files where they resolve."""
    settings = sorted(
        (attribute, files.get(attribute, repr(value)))
        for attribute, value in attribute_items(asset)
        if attribute != "name"
    )
    return (asset.tag, *settings)


def _without(section: Node, kind: str, moved: dict[str, str]) -> Node:
    """An ``<asset>`` section without the ``kind`` assets named in ``moved``."""
    if not (isinstance(section, Element) and section.tag == "asset"):
        return section
    children = [
        child
        for child in section.children
        if not (
            isinstance(child, Element)
            and child.tag == kind
            and get_attribute(child, "name") in moved
        )
    ]
    return with_children(section, children) if len(children) != len(section.children) else section
