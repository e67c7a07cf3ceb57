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

# Every node class, from the section modules themselves: type checkers follow a star import
# through one computed __all__ (nodes.__all__ gathers these modules' own) but not two.
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
