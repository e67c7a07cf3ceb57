"""``MujocoXMLModel``: robosuite's base of robots, grippers and mounts read from a file.

>>> import tempfile, pathlib
>>> path = pathlib.Path(tempfile.mkdtemp()) / "hand.xml"
>>> _ = path.write_text('<mujoco><worldbody><body name="hand"><geom size="0.1"/>'
...     '<geom size="0.1" group="1"/></body></worldbody></mujoco>')
>>> class Hand(MujocoXMLModel):
...     contact_geom_rgba = property(lambda self: [0, 0, 0.5, 1])
>>> hand = Hand(str(path), idn=1)
>>> hand.name, hand.root_body, hand.contact_geoms, hand.visual_geoms
('Hand1', '1_hand', ['1_g0_col'], ['1_g0_vis'])
>>> hand.worldbody[0][0].get("rgba")
'0 0 0.5 1'
"""

from __future__ import annotations

from typing import Any

from mjcf_model.compat.mjcf_utils.materials import recolored
from mjcf_model.compat.mjcf_utils.text import string_to_array
from mjcf_model.compat.objects.base import MujocoModel, Vector, recorded_names
from mjcf_model.compat.objects.habits import attribute, with_texts
from mjcf_model.compat.objects.naming import robosuite_prefixed
from mjcf_model.compat.objects.xml import MujocoXML
from mjcf_model.nodes.base import AnyElement, GenericElement, Node, TypedElement
from mjcf_model.tree.traversal import with_children
from mjcf_model.values import to_vec4

__all__ = ["MujocoXMLModel"]

_GEOM_KINDS = {None: "col", "0": "col", "1": "vis"}


def named_geoms(node: AnyElement) -> AnyElement:
    """Name unnamed geoms ``g<k>_col`` (group 0 or none) and ``g<k>_vis`` (group 1), in order."""
    counters = {"col": 0, "vis": 0}

    def visit(element: AnyElement) -> AnyElement:
        changes: dict[str, str | None] = {}
        if element.tag == "geom" and attribute(element, "name") is None:
            kind = _GEOM_KINDS.get(attribute(element, "group"))
            if kind is not None:
                changes["name"] = f"g{counters[kind]}_{kind}"
                counters[kind] += 1
        element = with_texts(element, changes)
        children: list[Node] = [
            visit(c) if isinstance(c, (TypedElement, GenericElement)) else c
            for c in element.children
        ]
        return with_children(element, children)

    return visit(node)


class MujocoXMLModel(MujocoXML, MujocoModel):
    """robosuite's ``MujocoXMLModel``: a file-based model with one root body and a prefix.

    Unnamed geoms are named, the names recorded and prefixed, and the collision
    geoms take ``contact_geom_rgba``. Subclasses give ``naming_prefix``,
    ``contact_geom_rgba`` and the raw ``_important_*`` names.

    Args:
        fname: Path of the MJCF file.
        idn: Identifier of this instance; the default prefix is ``"<idn>_"``.

    Raises:
        MjcfValueError: the worldbody has more or less than one top body.

    """

    _robosuite_class = ("robosuite.models.base", "MujocoXMLModel")

    def __init__(self, fname: str, idn: Any = 0) -> None:
        super().__init__(fname)
        self.idn = idn
        self.mount: Any = None
        document = named_geoms(self.mjcf)
        root, names = recorded_names(document)
        for category, recorded in names.items():  # _root_body, _bodies, _joints...
            setattr(self, f"_{category}", recorded)
        self._base_offset = string_to_array(attribute(root, "pos") or "0 0 0")
        self._set_mjcf(robosuite_prefixed(document, self.naming_prefix, self._excluded))
        rgba = self.contact_geom_rgba
        self._change("worldbody", lambda world: self._recolored(world, rgba))

    @staticmethod
    def _recolored(world: AnyElement, rgba: Any) -> AnyElement:
        """Paint the collision geoms as ``recolor_collision_geoms`` does (four-number ``rgba``)."""
        to_vec4(rgba)  # raises MjcfValueError for anything else
        recolored_world = recolored(world, rgba)
        assert isinstance(recolored_world, (TypedElement, GenericElement))
        return recolored_world

    def _excluded(self, name: str) -> bool:
        return bool(self.exclude_from_prefixing(name))

    def exclude_from_prefixing(self, inp: Any) -> bool:
        """No name is kept from prefixing."""
        return False

    @property
    def base_offset(self) -> Vector:
        """The root body's ``pos`` (zeros when not written)."""
        return self._base_offset

    @property
    def name(self) -> Any:
        """``"<class name><idn>"``."""
        return f"{type(self).__name__}{self.idn}"

    @property
    def naming_prefix(self) -> str:
        """``"<idn>_"`` (subclasses change it, e.g. ``"gripper0_"``)."""
        return f"{self.idn}_"

    root_body = property(lambda self: self.correct_naming(self._root_body), doc="Root body.")
    bodies = property(lambda self: self.correct_naming(self._bodies), doc="Body names.")
    joints = property(lambda self: self.correct_naming(self._joints), doc="Joint names.")
    actuators = property(lambda self: self.correct_naming(self._actuators), doc="Actuators.")
    sites = property(lambda self: self.correct_naming(self._sites), doc="Site names.")
    sensors = property(lambda self: self.correct_naming(self._sensors), doc="Sensor names.")
    contact_geoms = property(
        lambda self: self.correct_naming(self._contact_geoms), doc="Collision geom names."
    )
    visual_geoms = property(
        lambda self: self.correct_naming(self._visual_geoms), doc="Visual geom names."
    )
    important_sites = property(
        lambda self: self.correct_naming(self._important_sites), doc="Important sites."
    )
    important_geoms = property(
        lambda self: self.correct_naming(self._important_geoms), doc="Important geoms."
    )
    important_sensors = property(
        lambda self: self.correct_naming(self._important_sensors), doc="Important sensors."
    )

    def _raw_unanswered(self) -> Any:
        raise NotImplementedError(f"{type(self).__name__} does not define this")

    _important_sites = property(_raw_unanswered, doc="Raw important site names.")
    _important_geoms = property(_raw_unanswered, doc="Raw important geom names.")
    _important_sensors = property(_raw_unanswered, doc="Raw important sensor names.")
    contact_geom_rgba = property(_raw_unanswered, doc="Colour of the collision geoms.")
    top_offset = property(_raw_unanswered, doc="Vector from the root body to the top.")
    horizontal_radius = property(_raw_unanswered, doc="Largest horizontal distance.")

    @property
    def bottom_offset(self) -> Vector:
        """The root body's offset (:attr:`base_offset`)."""
        return self.base_offset
