"""mjcf-model: MuJoCo's MJCF as a typed, immutable value.

Frozen attrs nodes stand in for ElementTree elements; pure functions return
changed copies; :mod:`serializers` reads and writes MJCF without losing anything.

>>> from mjcf_model import Body, Geom, Joint
>>> arm = Body(name="arm", children=[Joint(name="elbow", type="hinge"), Geom(size=[0.05])])
>>> arm.joints[0].name
'elbow'
"""

from mjcf_model import errors, nodes
from mjcf_model.bridge.compiling import compiled
from mjcf_model.bridge.patching import patched
from mjcf_model.errors import *  # noqa: F403  (every error class; listed in errors.__all__)
from mjcf_model.nodes import *  # noqa: F403  (every node class; listed in nodes.__all__)
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
from mjcf_model.transforms.composition.attaching import attach, attach_all
from mjcf_model.transforms.composition.inlining import inlined_attachments
from mjcf_model.transforms.naming.renaming import declared_names, prefix_map, prefixed, renamed
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
    "compiled",
    "declared_names",
    "find",
    "find_all",
    "full_repr",
    "get_attribute",
    "inlined_attachments",
    "map_elements",
    "map_tree",
    "parent_of",
    "patched",
    "prefix_map",
    "prefixed",
    "renamed",
    "scaled",
    "walk",
    "with_attributes",
]
__all__ += errors.__all__ + nodes.__all__
