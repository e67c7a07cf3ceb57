"""``MujocoModel`` and ``MujocoObject``: robosuite's model interface over an immutable model.

>>> from mjcf_model.compat.objects import BoxObject
>>> box = BoxObject("cube", size=[0.02, 0.02, 0.02])
>>> box.get_obj() is box.get_obj(), box.root_body, box.correct_naming({"a": ["b"], "c": "d"})
(True, 'cube_main', {'a': ['cube_b'], 'c': 'cube_d'})
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from copy import deepcopy
from typing import Any

import numpy as np
import numpy.typing as npt

from mjcf_model.compat.mjcf_utils.constants import RED
from mjcf_model.compat.mjcf_utils.text import array_to_string
from mjcf_model.compat.objects.document import ModelBacked, RobosuiteCompatible, as_node
from mjcf_model.compat.objects.habits import named_specs, robosuite_scaled
from mjcf_model.compat.objects.naming import (
    recorded_names,
    robosuite_prefixed,
    skeleton_memo,
)
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.nodes.base import AnyElement, GenericElement
from mjcf_model.serializers.etree_view import write_back

__all__ = ["GEOMTYPE2GROUP", "GEOM_GROUPS", "MujocoModel", "MujocoObject"]

#: robosuite's geom groups kept for each ``obj_type``.
GEOMTYPE2GROUP: dict[str, set[int]] = {"collision": {0}, "visual": {1}, "all": {0, 1}}
#: The valid ``obj_type`` values.
GEOM_GROUPS = GEOMTYPE2GROUP.keys()

Vector = npt.NDArray[Any]

#: The document of an object before its body is built (immutable, so shared by all).
_EMPTY_DOCUMENT = GenericElement(
    tag="mujoco", children=[GenericElement(tag="asset"), GenericElement(tag="worldbody")]
)


def unanswered(doc: str) -> property:
    """A property subclasses must give: it raises ``NotImplementedError``."""

    def get(self: object) -> Any:
        raise NotImplementedError(f"{type(self).__name__} does not define this")

    return property(get, doc=doc)


def prefixed_names(category: str, doc: str) -> property:
    """A property of the raw names ``self._<category>`` through ``correct_naming``."""

    def get(self: MujocoModel) -> Any:
        raw = getattr(self, f"_{category}", unanswered)
        if raw is unanswered:
            raise NotImplementedError(f"{type(self).__name__} does not define this")
        return self.correct_naming(raw)

    return property(get, doc=doc)


class MujocoModel(RobosuiteCompatible):
    """robosuite's ``MujocoModel`` interface: prefixed names, geoms, sites, offsets."""

    _robosuite_class = ("robosuite.models.base", "MujocoModel")

    def correct_naming(self, names: Any) -> Any:
        """Add ``naming_prefix`` to a name, each name of a list, or each value of a dict.

        Names ``exclude_from_prefixing`` accepts stay; unlike robosuite, ``None`` stays ``None``.

        Raises:
            TypeError: ``names`` is not a str, list or dict.

        """
        if type(names) is str:
            return names if self.exclude_from_prefixing(names) else self.naming_prefix + names
        if type(names) is list:
            return [
                name
                if name is None or self.exclude_from_prefixing(name)
                else self.naming_prefix + name
                for name in names
            ]
        if type(names) is dict:
            return {key: self.correct_naming(value) for key, value in names.items()}
        raise TypeError("Error: type of 'names' must be str, list, or dict!")

    def set_sites_visibility(self, sim: Any, visible: bool) -> None:
        """Show or hide this model's sites in a running simulation (sign of the site alpha)."""
        for site in self.sites:
            site_id = sim.model.site_name2id(site)
            alpha = sim.model.site_rgba[site_id][3]
            if (visible and alpha < 0) or (not visible and alpha > 0):
                sim.model.site_rgba[site_id][3] = -alpha

    def exclude_from_prefixing(self, inp: Any) -> bool:
        """Whether the name ``inp`` is kept without the prefix (subclasses decide)."""
        raise NotImplementedError

    def _excluded(self, name: str) -> bool:
        return bool(self.exclude_from_prefixing(name))

    name = unanswered("Name of this model.")
    naming_prefix = unanswered("Prefix of every name in this model.")
    root_body = prefixed_names("root_body", "Name of the top body.")
    bodies = prefixed_names("bodies", "Names of the bodies.")
    joints = prefixed_names("joints", "Names of the joints.")
    actuators = prefixed_names("actuators", "Names of the actuators.")
    sites = prefixed_names("sites", "Names of the sites.")
    sensors = prefixed_names("sensors", "Names of the sensors.")
    contact_geoms = prefixed_names("contact_geoms", "Names of the collision geoms.")
    visual_geoms = prefixed_names("visual_geoms", "Names of the visual geoms.")
    important_geoms = unanswered("Named groups of important geoms.")
    important_sites = unanswered("Named important sites.")
    important_sensors = unanswered("Named important sensors.")
    bottom_offset = unanswered("Vector from the root body to the bottom.")
    top_offset = unanswered("Vector from the root body to the top.")
    horizontal_radius = unanswered("Largest horizontal distance from the root.")


class MujocoObject(ModelBacked, MujocoModel):
    """robosuite's ``MujocoObject``: a body with geoms, joints and a site, plus its assets.

    Subclasses build the body in ``_get_object_subtree`` (a node or an
    ElementTree element), assign it to ``_obj`` and call ``_get_object_properties``
    (which applies ``scale``: one factor or three).
    """

    _robosuite_class = ("robosuite.models.objects", "MujocoObject")

    def __init__(
        self, obj_type: str = "all", duplicate_collision_geoms: bool = True, scale: Any = None
    ) -> None:
        self._init_object(obj_type, duplicate_collision_geoms, scale)
        self._init_document(_EMPTY_DOCUMENT, {"asset": (0,), "worldbody": (1,)})

    def _init_object(self, obj_type: str, duplicate_collision_geoms: bool, scale: Any) -> None:
        """Set the fields of an object without a body yet, as robosuite does."""
        if obj_type not in GEOM_GROUPS:
            raise MjcfValueError(
                f"object type must be one in {list(GEOM_GROUPS)}, got: {obj_type!r} instead."
            )
        self.obj_type = obj_type
        self.duplicate_collision_geoms = duplicate_collision_geoms
        self._scale = self._pending_scale = scale
        self._name: str | None = None
        vars(self).update(  # robosuite's raw names, read by the properties
            _root_body=None,
            _bodies=[],
            _joints=[],
            _actuators=[],
            _sites=[],
            _sensors=[],
            _contact_geoms=[],
            _visual_geoms=[],
        )

    def _named_joints(self, joints: Any, by_position: bool = True) -> list[dict[str, Any]]:
        """``"default"`` (a free joint), ``None`` or the caller's joint dicts, named in place."""
        default = self.get_joint_attrib_template()
        return named_specs([] if joints is None else joints, "joint", default, by_position)

    def _named_sites(self, sites: Any) -> list[dict[str, Any]]:
        """A copy of the site dicts and the hidden ``default_site``, named (composites)."""
        specs = deepcopy(sites) if sites is not None else []
        specs.append(self._default_site(hidden=True))
        return named_specs(specs, "site", by_position=False)

    # -- the object body ----------------------------------------------------------

    @property
    def _obj(self) -> ET.Element | None:
        """The object body's ElementTree element, or ``None`` before it is built."""
        return self._live("obj") if "obj" in self._paths else None

    @_obj.setter
    def _obj(self, value: Any) -> None:
        """Install the object body (a node, or an ElementTree element robosuite-style)."""
        body = as_node(value)
        if "obj" in self._paths:
            self._replace("obj", body)
            return
        self._append("worldbody", "obj", body)

    def get_obj(self) -> ET.Element:
        """The object body: its live ElementTree element, the same on every call.

        Raises:
            MjcfLookupError: the body has not been built yet.

        """
        if "obj" not in self._paths:
            raise MjcfLookupError("Object XML tree has not been generated yet!")
        return self._live("obj")

    @property
    def obj_node(self) -> AnyElement:
        """The object body as an immutable node."""
        if "obj" not in self._paths:
            raise MjcfLookupError("Object XML tree has not been generated yet!")
        return self._node("obj")

    def _get_object_subtree(self) -> Any:
        raise NotImplementedError

    def _get_object_properties(self) -> None:
        """Apply a pending scale, record the body's raw names, then prefix them."""
        if self._pending_scale is not None:
            self._pending_scale = None
            self.set_scale(self._scale)
        body = self.obj_node
        memo = skeleton_memo(body)  # the names depend on the naming skeleton alone
        if memo is None:
            memo = {}
        if "recorded names" not in memo:
            memo["recorded names"] = recorded_names(body)[1]
        vars(self).update(memo["recorded names"])
        self._prefix_names()

    def _prefix_names(self) -> None:
        self._change(
            "obj", lambda body: robosuite_prefixed(body, self.naming_prefix, self._excluded)
        )

    def set_scale(self, scale: Any, obj: ET.Element | None = None) -> None:
        """Scale the body's geoms (pos, size), inner bodies and joints (pos) and the meshes.

        As in robosuite, sites, the root body's position and generated objects'
        offsets stay, and scaling twice compounds. ``obj``: another ElementTree
        body to scale in place instead.
        """
        self._scale = scale
        tags = {"geom", "body", "joint"}
        if obj is None and "obj" not in self._paths:  # no body yet: scale it once built
            self._pending_scale = scale
            return
        if obj is not None and obj is not self._obj:
            before = as_node(obj)
            write_back(obj, before, robosuite_scaled(before, scale, tags))
        else:
            self._change("obj", lambda body: robosuite_scaled(body, scale, tags))
        self._change("asset", lambda asset: robosuite_scaled(asset, scale, {"mesh"}))

    # -- names --------------------------------------------------------------------

    @property
    def name(self) -> Any:
        """The object's name."""
        return self._name

    @property
    def naming_prefix(self) -> str:
        """``"<name>_"``."""
        return f"{self.name}_"

    @property
    def important_geoms(self) -> dict[str, Any]:
        """No important geoms by default."""
        return {}

    @property
    def important_sites(self) -> dict[str, Any]:
        """``{"obj": "<prefix>default_site"}``."""
        return {"obj": self.naming_prefix + "default_site"}

    @property
    def important_sensors(self) -> dict[str, Any]:
        """No important sensors by default."""
        return {}

    @staticmethod
    def get_site_attrib_template() -> dict[str, str]:
        """The attributes of the small sphere site that marks the object's origin."""
        return {
            "pos": "0 0 0",
            "size": "0.002 0.002 0.002",
            "rgba": array_to_string(RED),
            "type": "sphere",
            "group": "0",
        }

    def _default_site(self, hidden: bool = False) -> dict[str, str]:
        """The ``default_site`` attributes (``hidden``: alpha 0)."""
        site = self.get_site_attrib_template()
        if hidden:
            site["rgba"] = "1 0 0 0"
        site["name"] = "default_site"
        return site

    @staticmethod
    def get_joint_attrib_template() -> dict[str, str]:
        """The attributes of the default joint: a free joint."""
        return {"type": "free"}

    def get_bounding_box_half_size(self) -> Vector:
        """Half the size of a box around the object (subclasses decide)."""
        raise NotImplementedError

    def get_bounding_box_size(self) -> Vector:
        """The size of a box around the object: twice :meth:`get_bounding_box_half_size`."""
        return 2.0 * np.asarray(self.get_bounding_box_half_size())
