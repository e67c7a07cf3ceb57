"""mjcf-model: MuJoCo's MJCF as a typed, immutable value.

Frozen attrs nodes stand in for ElementTree elements; pure functions return
changed copies; :mod:`mjcf_model.serializers` reads and writes MJCF without losing
anything.

>>> from mjcf_model import Body, Geom, Joint, dumps, loads
>>> arm = Body(name="arm", children=[Joint(name="elbow", type="hinge"), Geom(size=[0.05])])
>>> arm.joints[0].name
'elbow'
>>> loads(dumps(loads('<mujoco model="m"/>'))).model
'm'

The facade is lazy: a name is imported from its module the first time it is asked
for, so importing a low layer (``mjcf_model.errors``, ``mjcf_model.nodes``) loads only
that layer, and ``import mjcf_model`` costs almost nothing.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from mjcf_model import errors
from mjcf_model.errors import *  # noqa: F403  (every error class; listed in errors.__all__)

if TYPE_CHECKING:  # what the names below are, for type checkers (at run time: __getattr__)
    from mjcf_model import nodes
    from mjcf_model.bridge.batching import batched
    from mjcf_model.bridge.compiling import compiled
    from mjcf_model.bridge.patching import patched

    # Every node class, from the section modules themselves: type checkers follow a star
    # import through one computed __all__ (nodes.__all__ gathers these modules' own) but
    # not two.
    from mjcf_model.nodes.actuator.base import *  # noqa: F403
    from mjcf_model.nodes.actuator.shortcuts import *  # noqa: F403
    from mjcf_model.nodes.actuator.special import *  # noqa: F403
    from mjcf_model.nodes.asset import *  # noqa: F403
    from mjcf_model.nodes.base import (
        AttributeMap,
        Comment,
        Element,
        GenericElement,
        Node,
        TypedElement,
        attribute_items,
        full_repr,
        get_attribute,
        with_attributes,
    )
    from mjcf_model.nodes.body import *  # noqa: F403
    from mjcf_model.nodes.compiler import *  # noqa: F403
    from mjcf_model.nodes.contact import *  # noqa: F403
    from mjcf_model.nodes.custom import *  # noqa: F403
    from mjcf_model.nodes.default import *  # noqa: F403
    from mjcf_model.nodes.deformable import *  # noqa: F403
    from mjcf_model.nodes.equality import *  # noqa: F403
    from mjcf_model.nodes.geom import *  # noqa: F403
    from mjcf_model.nodes.keyframe import *  # noqa: F403
    from mjcf_model.nodes.plugin import *  # noqa: F403
    from mjcf_model.nodes.root import *  # noqa: F403
    from mjcf_model.nodes.sensor.base import *  # noqa: F403
    from mjcf_model.nodes.sensor.frames import *  # noqa: F403
    from mjcf_model.nodes.sensor.global_sensors import *  # noqa: F403
    from mjcf_model.nodes.sensor.one_object import *  # noqa: F403
    from mjcf_model.nodes.tendon import *  # noqa: F403
    from mjcf_model.nodes.visual import *  # noqa: F403
    from mjcf_model.serializers.collector import collector_paused
    from mjcf_model.serializers.dicts import from_dict, make_converter, to_dict
    from mjcf_model.serializers.dumping import dump, dumps
    from mjcf_model.serializers.etree import from_etree, to_etree
    from mjcf_model.serializers.exporting import export
    from mjcf_model.serializers.loading import load, loads
    from mjcf_model.transforms.composition.attaching import attach, attach_all
    from mjcf_model.transforms.composition.inlining import inlined_attachments
    from mjcf_model.transforms.naming.renaming import (
        declared_names,
        prefix_map,
        prefixed,
        renamed,
    )
    from mjcf_model.transforms.scaling.transform import scaled
    from mjcf_model.tree.queries import find, find_all, parent_of
    from mjcf_model.tree.traversal import map_elements, map_tree, walk
    from mjcf_model.values import Unparsed

    __all__ = [
        "Unparsed",
        "AttributeMap",
        "Comment",
        "Element",
        "GenericElement",
        "Node",
        "TypedElement",
        "attach",
        "attach_all",
        "attribute_items",
        "batched",
        "collector_paused",
        "compiled",
        "declared_names",
        "dump",
        "dumps",
        "export",
        "find",
        "find_all",
        "from_dict",
        "from_etree",
        "full_repr",
        "get_attribute",
        "inlined_attachments",
        "load",
        "loads",
        "make_converter",
        "map_elements",
        "map_tree",
        "parent_of",
        "patched",
        "prefix_map",
        "prefixed",
        "renamed",
        "scaled",
        "to_dict",
        "to_etree",
        "walk",
        "with_attributes",
    ]
    __all__ += errors.__all__ + nodes.__all__

#: The module each public name (but the node classes and errors) is imported from.
_HOMES = {
    "Unparsed": "mjcf_model.values",
    **dict.fromkeys(
        (
            "AttributeMap",
            "Comment",
            "Element",
            "GenericElement",
            "Node",
            "TypedElement",
            "attribute_items",
            "full_repr",
            "get_attribute",
            "with_attributes",
        ),
        "mjcf_model.nodes.base",
    ),
    "batched": "mjcf_model.bridge.batching",
    "compiled": "mjcf_model.bridge.compiling",
    "patched": "mjcf_model.bridge.patching",
    "collector_paused": "mjcf_model.serializers.collector",
    **dict.fromkeys(("from_dict", "make_converter", "to_dict"), "mjcf_model.serializers.dicts"),
    **dict.fromkeys(("dump", "dumps"), "mjcf_model.serializers.dumping"),
    **dict.fromkeys(("from_etree", "to_etree"), "mjcf_model.serializers.etree"),
    "export": "mjcf_model.serializers.exporting",
    **dict.fromkeys(("load", "loads"), "mjcf_model.serializers.loading"),
    **dict.fromkeys(("attach", "attach_all"), "mjcf_model.transforms.composition.attaching"),
    "inlined_attachments": "mjcf_model.transforms.composition.inlining",
    **dict.fromkeys(
        ("declared_names", "prefix_map", "prefixed", "renamed"),
        "mjcf_model.transforms.naming.renaming",
    ),
    "scaled": "mjcf_model.transforms.scaling.transform",
    **dict.fromkeys(("find", "find_all", "parent_of"), "mjcf_model.tree.queries"),
    **dict.fromkeys(("map_elements", "map_tree", "walk"), "mjcf_model.tree.traversal"),
}

#: The module that gathers every node class.
_NODES = "mjcf_model.nodes"


def _public_names() -> list[str]:
    """Every public name: the functions and classes above, the errors, the node classes."""
    nodes_module = importlib.import_module(_NODES)
    return [*_HOMES, *errors.__all__, *nodes_module.__all__]


def __getattr__(name: str) -> Any:
    """Import a public name from its module the first time it is asked for."""
    if name == "__all__":
        value: Any = _public_names()
    elif name in _HOMES:
        value = getattr(importlib.import_module(_HOMES[name]), name)
    else:
        nodes_module = importlib.import_module(_NODES)
        if name not in nodes_module.__all__:
            raise AttributeError(f"module 'mjcf_model' has no attribute {name!r}")
        value = getattr(nodes_module, name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *_public_names()})
