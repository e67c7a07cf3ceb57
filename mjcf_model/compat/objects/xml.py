"""robosuite's file-based models: ``MujocoXML``, ``MujocoXMLObject`` and ``MujocoXMLModel``.

>>> import tempfile, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> _ = (folder / "ball.xml").write_text('<mujoco><worldbody><body><body name="object">'
...     '<geom size="0.1" group="0"/></body><site name="bottom_site" pos="0 0 -0.1"/>'
...     '</body></worldbody></mujoco>')
>>> ball = MujocoXMLObject(str(folder / "ball.xml"), name="ball")
>>> ball.contact_geoms, ball.visual_geoms, ball.bottom_offset
(['ball_g0'], ['ball_g0_visual'], array([ 0. ,  0. , -0.1]))
>>> ball.get_obj() is ball.worldbody[0][0]
True
>>> _ = (folder / "hand.xml").write_text('<mujoco><worldbody><body name="hand">'
...     '<geom size="0.1"/><geom size="0.1" group="1"/></body></worldbody></mujoco>')
>>> class Hand(MujocoXMLModel):
...     contact_geom_rgba = property(lambda self: [0, 0, 0.5, 1])
>>> hand = Hand(str(folder / "hand.xml"), idn=1)
>>> hand.name, hand.root_body, hand.contact_geoms, hand.visual_geoms
('Hand1', '1_hand', ['1_g0_col'], ['1_g0_vis'])
>>> hand.worldbody[0][0].get("rgba")
'0 0 0.5 1'
"""

from __future__ import annotations

import os
import xml.dom.minidom
import xml.etree.ElementTree as ET
from typing import Any

from mjcf_model.caching import IdentityCache
from mjcf_model.compat.mjcf_utils.builders import joint_node
from mjcf_model.compat.mjcf_utils.materials import recolored
from mjcf_model.compat.mjcf_utils.text import array_to_string, string_to_array
from mjcf_model.compat.objects.base import (
    GEOMTYPE2GROUP,
    MujocoModel,
    MujocoObject,
    Vector,
    prefixed_names,
    unanswered,
)
from mjcf_model.compat.objects.document import (
    ModelBacked,
    RobosuiteCompatible,
    as_node,
    find_path,
    is_element,
    section_children,
)
from mjcf_model.compat.objects.habits import (
    absolute_files,
    named_geoms,
    read_like_robosuite,
    robosuite_scaled,
    split_geoms,
    value_text,
    visual_twin,
)
from mjcf_model.compat.objects.naming import recorded_names, robosuite_prefixed
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.nodes.base import AnyElement, GenericElement, attribute_text, with_attributes
from mjcf_model.serializers.etree import to_etree
from mjcf_model.tree.paths import appended_at, replaced_at, subtree_at
from mjcf_model.tree.traversal import walk, with_children
from mjcf_model.values import to_vec4
from mjcf_model.values.encoding import for_mujoco

__all__ = ["MujocoXML", "MujocoXMLModel", "MujocoXMLObject"]

#: Prepared documents, by the document read and the choices that shape the object.
_PREPARED: IdentityCache[AnyElement] = IdentityCache(32)


def _typed(attributes: dict[str, Any]) -> tuple[tuple[str, type, Any], ...]:
    """Attributes as a key, each value with its type (``1``, ``1.0``, ``True`` write apart)."""
    return tuple((key, type(value), value) for key, value in attributes.items())


class MujocoXML(ModelBacked, RobosuiteCompatible):
    """robosuite's ``MujocoXML``: the MJCF file ``fname``, its sections, merging and output."""

    _robosuite_class = ("robosuite.models.base", "MujocoXML")

    def __init__(self, fname: str) -> None:
        self.file = fname
        self.folder = os.path.dirname(fname)
        document, paths = read_like_robosuite(fname)
        self._init_document(document, paths)
        self._tree: ET.ElementTree | None = None

    @property
    def root(self) -> ET.Element:
        """The ``<mujoco>`` element (live)."""
        return self._live()

    @property
    def tree(self) -> ET.ElementTree:
        """An ElementTree around :attr:`root` (the same object on every call)."""
        if self._tree is None:
            self._tree = ET.ElementTree(self.root)
        return self._tree

    worldbody = property(lambda self: self._live("worldbody"), doc="``<worldbody>`` (live).")
    actuator = property(lambda self: self._live("actuator"), doc="``<actuator>`` (live).")
    sensor = property(lambda self: self._live("sensor"), doc="``<sensor>`` (live).")
    tendon = property(lambda self: self._live("tendon"), doc="``<tendon>`` (live).")
    equality = property(lambda self: self._live("equality"), doc="``<equality>`` (live).")
    contact = property(lambda self: self._live("contact"), doc="``<contact>`` (live).")

    @property
    def name(self) -> Any:
        """The ``model`` attribute of the root."""
        return attribute_text(self.mjcf, "model")

    def create_default_element(self, name: str) -> ET.Element:
        """The first ``<name>`` child of the root, added (empty, at the end) if missing."""
        if name not in self._paths:
            children = list(self.mjcf.children)
            index = next((i for i, c in enumerate(children) if is_element(c, name)), None)
            if index is None:
                index = len(children)
                self._set_mjcf(with_children(self.mjcf, [*children, GenericElement(tag=name)]))
            self._paths[name] = (index,)
        return self._live(name)

    def resolve_asset_dependency(self) -> None:
        """Make each asset ``file`` absolute (joined to the file's directory; already done)."""
        folder = os.path.abspath(self.folder)
        self._change("asset", lambda asset: absolute_files(asset, folder))

    def merge(self, others: Any, merge_body: str | None = "default") -> None:
        """Merge other models: bodies, assets, actuators, sensors, tendons, equalities, contacts.

        Unlike robosuite, their elements are copied, not shared.

        Args:
            others: A model or a list of models (this library's or robosuite's).
            merge_body: ``"default"`` puts their top bodies in the worldbody, a
                body name puts them in that body, ``None`` leaves them out.

        Raises:
            MjcfValueError: an item is not a model with MJCF sections.
            MjcfLookupError: ``merge_body`` names no body.

        """
        for other in others if type(others) is list else [others]:
            if not isinstance(other, MujocoXML) and not hasattr(other, "worldbody"):
                raise MjcfValueError(f"{type(other)} is not a MujocoXML instance.")
            if merge_body is not None:
                place = self._paths["worldbody"]
                if merge_body != "default":
                    path = find_path(self._node("worldbody"), "body", name=merge_body)
                    if path is None:
                        raise MjcfLookupError(f"no body named {merge_body!r} in the worldbody")
                    place = place + path
                bodies = section_children(other, "worldbody")
                self._set_mjcf(appended_at(self.mjcf, place, bodies))
            self.merge_assets(other)
            for section in ("actuator", "sensor", "tendon", "equality", "contact"):
                items = section_children(other, section)
                if items:
                    node = self._node(section)
                    self._replace(section, with_children(node, [*node.children, *items]))

    def get_model(self, mode: str = "mujoco") -> Any:
        """Compile the current XML with MuJoCo (``mujoco.MjModel``).

        Raises:
            MjcfValueError: ``mode`` is not ``"mujoco"``.

        """
        if mode != "mujoco":
            raise MjcfValueError(f"Unkown model mode: {mode}. Available options are: mujoco")
        import mujoco

        return mujoco.MjModel.from_xml_string(for_mujoco(self.get_xml()))

    def get_xml(self) -> str:
        """The XML of :attr:`root`, as ``ET.tostring`` writes it."""
        return ET.tostring(self.root, encoding="unicode")

    def save_model(self, fname: str, pretty: bool = False) -> None:
        """Write :meth:`get_xml` to ``fname`` (``pretty``: through minidom, as robosuite)."""
        text = self.get_xml()
        if pretty:
            text = xml.dom.minidom.parseString(text).toprettyxml(newl="")
        with open(fname, "w") as stream:
            stream.write(text)

    def get_element_names(self, root: Any, element_type: str) -> list[str | None]:
        """Names of the ``element_type`` elements below ``root`` (an element or a node)."""
        if isinstance(root, ET.Element):
            return [e.get("name") for e in root.iter() if e is not root and e.tag == element_type]
        return [
            attribute_text(e, "name") for path, e in walk(root) if path and e.tag == element_type
        ]


class MujocoXMLObject(MujocoObject, MujocoXML):
    """robosuite's ``MujocoXMLObject``: the body ``worldbody/body/body[@name='object']`` of a file.

    The outer body's ``bottom_site``, ``top_site`` and ``horizontal_radius_site``
    give the offsets; every name in the document gets ``"<name>_"``.

    ``joints``: ``"default"`` (a free joint), ``None`` or joint dicts (named
    ``joint<i>`` in place); ``duplicate_collision_geoms`` gives collision geoms visual twins.

    Raises:
        MjcfLookupError: the file has no such body (robosuite: ``AttributeError``).

    """

    _robosuite_class = ("robosuite.models.objects", "MujocoXMLObject")

    def __init__(
        self,
        fname: str,
        name: str,
        joints: Any = "default",
        obj_type: str = "all",
        duplicate_collision_geoms: bool = True,
        scale: Any = None,
    ) -> None:
        MujocoXML.__init__(self, fname)
        self._init_object(obj_type, duplicate_collision_geoms, scale)  # scaled once prepared
        self._name = name
        self.joint_specs = self._named_joints(joints)
        path = find_path(self._node("worldbody"), "body", inside="body", name="object")
        if path is None:
            raise MjcfLookupError(
                f"{self.file}: no <body name='object'> inside a top-level body of <worldbody>; "
                "an XML object is worldbody/body/body[@name='object']"
            )
        self._paths["obj"] = (*self._paths["worldbody"], *path)
        self._set_mjcf(self._prepared_document())
        self._get_object_properties()

    def _prepared_document(self) -> AnyElement:
        """The document with the object body prepared (:meth:`_prepared`), remembered."""
        document, place = self.mjcf, self._paths["obj"]

        def prepared() -> AnyElement:
            return replaced_at(document, place, [self._prepared(subtree_at(document, place))])

        choices = (
            type(self),
            place,
            self.obj_type,
            self.duplicate_collision_geoms,
            tuple(_typed(spec) for spec in self.joint_specs),
            _typed(self._default_site(hidden=True)),
        )
        if type(self)._prepared is not MujocoXMLObject._prepared:
            return prepared()  # a subclass prepares its own way, from what it knows
        try:
            hash(choices)
        except TypeError:  # a joint given by unhashable values (arrays...)
            return prepared()
        return _PREPARED.recall_for(document, prepared, choices)

    def _prepared(self, obj: AnyElement) -> AnyElement:
        obj = with_attributes(obj, {"name": "main"})
        obj = split_geoms(obj, GEOMTYPE2GROUP[self.obj_type], self.duplicate_collision_geoms)
        extra = [joint_node(value_text, **spec) for spec in self.joint_specs]
        extra.append(GenericElement(tag="site", attributes=self._default_site(hidden=True)))
        return with_children(obj, [*obj.children, *extra])

    @staticmethod
    def _duplicate_visual_from_collision(element: ET.Element) -> ET.Element:
        """A visual copy of a collision geom element (robosuite's helper, on ElementTree)."""
        return to_etree(visual_twin(as_node(element), str(element.get("name"))))

    def _prefix_names(self) -> None:
        self._set_mjcf(robosuite_prefixed(self.mjcf, self.naming_prefix, self._excluded))

    def exclude_from_prefixing(self, inp: Any) -> bool:
        """No name is kept from prefixing."""
        return False

    def set_scale(self, scale: Any, obj: ET.Element | None = None) -> None:
        """Scale as robosuite does: the body's geoms, bodies, joints; all meshes; all sites.

        The worldbody's sites include the offset sites, so the offsets follow.
        """
        super().set_scale(scale, obj)
        self._change("worldbody", lambda world: robosuite_scaled(world, scale, {"site"}))

    def set_pos(self, pos: Any) -> None:
        """Set the object body's ``pos`` (written as robosuite writes numbers)."""
        self._change("obj", lambda obj: with_attributes(obj, {"pos": array_to_string(pos)}))

    def set_euler(self, euler: Any) -> None:
        """Set the object body's ``euler``."""
        self._change("obj", lambda obj: with_attributes(obj, {"euler": array_to_string(euler)}))

    @property
    def rot(self) -> Any:
        """The z Euler angle of the object body (0 when not set)."""
        return string_to_array(attribute_text(self.obj_node, "euler") or "0.0 0.0 0.0")[2]

    def _outer_site_pos(self, name: str) -> Vector:
        world, wanted = self._node("worldbody"), self.naming_prefix + name
        path = find_path(world, "site", inside="body", name=wanted)
        if path is None:
            raise MjcfLookupError(
                f"{self.file}: no site {wanted!r} in a top-level body of <worldbody>"
            )
        return string_to_array(attribute_text(subtree_at(world, path), "pos") or "0 0 0")

    bottom_offset = property(lambda self: self._outer_site_pos("bottom_site"), doc="Bottom site.")
    top_offset = property(lambda self: self._outer_site_pos("top_site"), doc="Top site.")
    horizontal_radius = property(
        lambda self: self._outer_site_pos("horizontal_radius_site")[0], doc="Its x."
    )

    def get_bounding_box_half_size(self) -> Vector:
        """``horizontal_radius_site`` position minus :attr:`bottom_offset`."""
        half: Vector = self._outer_site_pos("horizontal_radius_site") - self.bottom_offset
        return half

    def _get_elements_by_name(
        self,
        geom_names: list[str],
        body_names: list[str] | None = None,
        joint_names: list[str] | None = None,
    ) -> tuple[dict[str, list[ET.Element | None]], dict[str, Any], dict[str, Any]]:
        """The live geoms (and visual twins), bodies and joints named ``<name>_<x>``."""

        def first(tag: str, name: str) -> ET.Element | None:
            obj = self.get_obj()
            return next((e for e in obj.iter(tag) if e.get("name") == name), None)

        prefix = f"{self.name}_"
        geoms = {g: [first("geom", prefix + g + x) for x in ("", "_visual")] for g in geom_names}
        bodies = {b: first("body", prefix + b) for b in body_names or []}
        joints = {j: first("joint", prefix + j) for j in joint_names or []}
        return geoms, bodies, joints


class MujocoXMLModel(MujocoXML, MujocoModel):
    """robosuite's ``MujocoXMLModel``: a file-based model with one root body and a prefix.

    Unnamed geoms are named, the names recorded and prefixed, and the collision
    geoms take ``contact_geom_rgba``. Subclasses give ``contact_geom_rgba``, the raw
    ``_important_*`` names and maybe ``naming_prefix`` (default ``"<idn>_"``).

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
        vars(self).update(names)  # _root_body, _bodies, _joints...
        self._base_offset = string_to_array(attribute_text(root, "pos") or "0 0 0")
        self._set_mjcf(robosuite_prefixed(document, self.naming_prefix, self._excluded))
        rgba = self.contact_geom_rgba
        self._change("worldbody", lambda world: self._recolored(world, rgba))

    @staticmethod
    def _recolored(world: AnyElement, rgba: Any) -> AnyElement:
        """Paint the collision geoms as ``recolor_collision_geoms`` does (four-number ``rgba``)."""
        to_vec4(rgba)  # raises MjcfValueError for anything else
        recolored_world = recolored(world, rgba)
        assert is_element(recolored_world)
        return recolored_world

    exclude_from_prefixing = MujocoXMLObject.exclude_from_prefixing

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

    important_sites = prefixed_names("important_sites", "Important sites.")
    important_geoms = prefixed_names("important_geoms", "Important geoms.")
    important_sensors = prefixed_names("important_sensors", "Important sensors.")
    _important_sites = unanswered("Raw important site names.")
    _important_geoms = unanswered("Raw important geom names.")
    _important_sensors = unanswered("Raw important sensor names.")
    contact_geom_rgba = unanswered("Colour of the collision geoms.")
    bottom_offset = property(lambda self: self.base_offset, doc="The root body's offset.")
