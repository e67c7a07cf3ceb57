"""mjcf-model: MuJoCo's MJCF as a typed, immutable value.

Frozen attrs nodes stand in for ElementTree elements; pure functions return
changed copies; :mod:`serializers` reads and writes MJCF without losing anything.

>>> from mjcf_model import Body, Geom, Joint
>>> arm = Body(name="arm", children=[Joint(name="elbow", type="hinge"), Geom(size=[0.05])])
>>> arm.joints[0].name
'elbow'
"""

from mjcf_model import errors, nodes
from mjcf_model.base import (
    AttributeMap,
    Comment,
    Element,
    GenericElement,
    Node,
    TypedElement,
    attribute_items,
    get_attribute,
    with_attributes,
)
from mjcf_model.errors import *  # noqa: F403  (every error class; listed in errors.__all__)
from mjcf_model.nodes import *  # noqa: F403  (every node class; listed in nodes.__all__)

__all__ = [
    "AttributeMap",
    "Comment",
    "Element",
    "GenericElement",
    "Node",
    "TypedElement",
    "attribute_items",
    "get_attribute",
    "with_attributes",
]
__all__ += errors.__all__ + nodes.__all__
