"""robosuite's element constructors, returning typed nodes (``mjcf_model.new_geom``...).

The same defaults and attribute order as robosuite's ``mjcf_utils`` functions
(:mod:`mjcf_model.compat.mjcf_utils.builders` builds both), recorded in the
node's ``attribute_order`` so the writer keeps it; ``None`` values are dropped
and numbers are written in the shortest form (``"0 0 0"``, not ``"0.0 0.0 0.0"``).

>>> from mjcf_model import dumps
>>> print(dumps(new_geom("g", "box", [0.1, 0.1, 0.1])), end="")
<geom type="box" size="0.1 0.1 0.1" pos="0 0 0" group="0" name="g"/>
>>> print(dumps(new_site("s")), end="")
<site pos="0 0 0" size="0.005" rgba="1 0 0 1" name="s"/>
"""

from __future__ import annotations

from typing import Any, cast

from mjcf_model.compat.mjcf_utils.builders import (
    body_node,
    element_node,
    geom_node,
    inertial_node,
    joint_node,
    site_node,
)
from mjcf_model.compat.mjcf_utils.constants import RED
from mjcf_model.errors import MjcfLookupError
from mjcf_model.nodes.actuator import ActuatorElement
from mjcf_model.nodes.base import AnyElement
from mjcf_model.nodes.body import Body, Inertial, Joint
from mjcf_model.nodes.geom import Geom, Site
from mjcf_model.nodes.registry import CLASS_BY_KEY

__all__ = [
    "new_actuator",
    "new_body",
    "new_element",
    "new_geom",
    "new_inertial",
    "new_joint",
    "new_site",
]

#: The actuator classes, by tag, for :func:`new_actuator`.
_ACTUATORS: dict[str, type[ActuatorElement]] = {
    key.split("/", 1)[1]: cls
    for key, cls in CLASS_BY_KEY.items()
    if key.startswith("actuator/") and issubclass(cls, ActuatorElement)
}


def new_element(tag: str, name: str | None = None, **attributes: Any) -> AnyElement:
    """A new element of ``tag``, typed where the tag has a class (``dclass`` is ``class``).

    Examples:
        >>> body = new_element("body", None, pos=[0, 0, 1], quat=None, mass=0.5, flag=True)
        >>> type(body).__name__, body.pos, body.extra["flag"]
        ('Body', (0.0, 0.0, 1.0), 'true')
        >>> new_element("wheel", "w", spokes=5).attributes
        AttributeMap({'spokes': '5', 'name': 'w'})

    """
    return element_node(tag, [*attributes.items(), ("name", name)], None)


def new_joint(name: str | None = None, **attributes: Any) -> Joint:
    """A new ``<joint>``: the attributes, then ``name``."""
    return cast(Joint, joint_node(None, name, **attributes))


def new_actuator(
    name: str | None, joint: str, act_type: str = "motor", **attributes: Any
) -> ActuatorElement:
    """A new actuator driving ``joint``: the attributes, ``name``, then ``joint``.

    robosuite's default ``act_type`` is ``"actuator"``, the section's tag, which
    MuJoCo does not know as an actuator; here it is ``"motor"``.

    Raises:
        MjcfLookupError: ``act_type`` is not an actuator tag.

    Examples:
        >>> type(new_actuator("m", "elbow")).__name__
        'Motor'

    """
    if act_type not in _ACTUATORS:
        raise MjcfLookupError(
            f"no actuator element {act_type!r}; the actuator tags are "
            + ", ".join(sorted(_ACTUATORS))
        )
    items = [*attributes.items(), ("name", name), ("joint", joint)]
    return cast(ActuatorElement, element_node(act_type, items, None))


def new_site(
    name: str | None = None,
    rgba: Any = RED,
    pos: Any = (0, 0, 0),
    size: Any = (0.005,),
    **attributes: Any,
) -> Site:
    """A new ``<site>`` (a small red sphere by default)."""
    return cast(Site, site_node(None, name, rgba, pos, size, **attributes))


def new_geom(
    name: str | None,
    type: str | None,
    size: Any,
    pos: Any = (0, 0, 0),
    group: Any = 0,
    **attributes: Any,
) -> Geom:
    """A new ``<geom>`` (group 0, at the origin by default)."""
    return cast(Geom, geom_node(None, name, type, size, pos, group, **attributes))


def new_body(name: str | None = None, pos: Any = (0, 0, 0), **attributes: Any) -> Body:
    """A new ``<body>`` (at the origin by default)."""
    return cast(Body, body_node(None, name, pos, **attributes))


def new_inertial(pos: Any = (0, 0, 0), mass: Any = None, **attributes: Any) -> Inertial:
    """A new ``<inertial>``: the attributes, ``mass``, then ``pos`` (no name)."""
    return cast(Inertial, inertial_node(None, pos, mass, **attributes))
