"""``MujocoXML`` and ``MujocoXMLObject``: robosuite's file-based models over an immutable model.

>>> import tempfile, pathlib
>>> path = pathlib.Path(tempfile.mkdtemp()) / "ball.xml"
>>> _ = path.write_text('<mujoco><worldbody><body><body name="object">'
...     '<geom size="0.1" group="0"/></body><site name="bottom_site" pos="0 0 -0.1"/>'
...     '</body></worldbody></mujoco>')
>>> ball = MujocoXMLObject(str(path), name="ball")
>>> ball.contact_geoms, ball.visual_geoms, ball.bottom_offset
(['ball_g0'], ['ball_g0_visual'], array([ 0. ,  0. , -0.1]))
>>> ball.get_obj() is ball.worldbody[0][0]
True
"""

from __future__ import annotations

import os
import xml.dom.minidom
import xml.etree.ElementTree as ET
from typing import Any

from mjcf_model.compat.mjcf_utils.text import array_to_string, string_to_array
from mjcf_model.compat.objects.base import (
    GEOMTYPE2GROUP,
    MujocoObject,
    Vector,
    check_obj_type,
    joint_specs,
)
from mjcf_model.compat.objects.class_face import RobosuiteCompatible
from mjcf_model.compat.objects.document import ModelBacked
from mjcf_model.compat.objects.habits import attribute, robosuite_scaled, rs_joint, with_texts
from mjcf_model.compat.objects.memo import Memo
from mjcf_model.compat.objects.naming import robosuite_prefixed
from mjcf_model.compat.objects.reading import (
    absolute_files,
    read_like_robosuite,
    split_geoms,
    visual_twin,
)
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.nodes.base import AnyElement, GenericElement, TypedElement
from mjcf_model.tree.traversal import (
    Path,
    appended_at,
    replaced_at,
    subtree_at,
    walk,
    with_children,
)
from serializers import from_etree, to_etree

__all__ = ["MujocoXML", "MujocoXMLObject"]

#: Prepared documents, by the document read and the choices that shape the object.
_PREPARED: Memo[AnyElement] = Memo(32)


def _typed(attributes: dict[str, Any]) -> tuple[tuple[str, type, Any], ...]:
    """Attributes as a key, each value with its type (``1``, ``1.0``, ``True`` write apart)."""
    return tuple((key, type(value), value) for key, value in attributes.items())


def section_children(model: Any, section: str) -> list[AnyElement]:
    """The elements of the section of ``model`` (ours or robosuite's), as nodes."""
    if isinstance(model, ModelBacked) and section in model._paths:
        return list(model._node(section).elements)
    found = []
    for child in getattr(model, section):
        node = from_etree(child, typed=False)
        assert isinstance(node, (TypedElement, GenericElement))
        found.append(node)
    return found


class MujocoXML(ModelBacked, RobosuiteCompatible):
    """robosuite's ``MujocoXML``: an MJCF file, its sections, merging and output.

    Args:
        fname: Path of the MJCF file.

    """

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
        return attribute(self.mjcf, "model")

    def create_default_element(self, name: str) -> ET.Element:
        """The first ``<name>`` child of the root, added (empty, at the end) if missing."""
        if name not in self._paths:
            children = list(self.mjcf.children)
            index = next(
                (
                    i
                    for i, c in enumerate(children)
                    if isinstance(c, (TypedElement, GenericElement)) and c.tag == name
                ),
                None,
            )
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
                    place = place + self._body_path(merge_body)
                bodies = section_children(other, "worldbody")
                self._set_mjcf(appended_at(self.mjcf, place, bodies))
            self.merge_assets(other)
            for section in ("actuator", "sensor", "tendon", "equality", "contact"):
                items = section_children(other, section)
                if items:
                    node = self._node(section)
                    self._replace(section, with_children(node, [*node.children, *items]))

    def _body_path(self, name: str) -> Path:
        for path, element in walk(self._node("worldbody")):
            if element.tag == "body" and attribute(element, "name") == name:
                return path
        raise MjcfLookupError(f"no body named {name!r} in the worldbody")

    def get_model(self, mode: str = "mujoco") -> Any:
        """Compile the current XML with MuJoCo (``mujoco.MjModel``).

        Raises:
            MjcfValueError: ``mode`` is not ``"mujoco"``.

        """
        if mode != "mujoco":
            raise MjcfValueError(f"Unkown model mode: {mode}. Available options are: mujoco")
        import mujoco

        return mujoco.MjModel.from_xml_string(self.get_xml())

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
        return [attribute(e, "name") for path, e in walk(root) if path and e.tag == element_type]


class MujocoXMLObject(MujocoObject, MujocoXML):
    """robosuite's ``MujocoXMLObject``: the body ``worldbody/body/body[@name='object']`` of a file.

    The outer body's ``bottom_site``, ``top_site`` and ``horizontal_radius_site``
    give the offsets; every name in the document gets ``"<name>_"``.

    Args:
        fname: Path of the MJCF file.
        name: Name of the object (its prefix is ``name + "_"``).
        joints: ``"default"`` (a free joint), ``None``, or joint attribute
            dicts (unnamed ones are named ``joint<i>`` in the caller's dicts).
        obj_type: ``"collision"``, ``"visual"`` or ``"all"``.
        duplicate_collision_geoms: Give collision geoms visual twins.
        scale: One factor or three.

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
        check_obj_type(obj_type)
        self.obj_type = obj_type
        self.duplicate_collision_geoms = duplicate_collision_geoms
        self._name = name
        self._scale = scale
        self._pending_scale = None
        self._raw = {"root_body": None}
        self.joint_specs = joint_specs(joints, [self.get_joint_attrib_template()])
        self._paths["obj"] = self._object_path()
        self._set_mjcf(self._prepared_document())
        if scale is not None:
            self.set_scale(scale)
        self._get_object_properties()

    def _object_path(self) -> Path:
        world = self._node("worldbody")
        for i, outer in enumerate(world.children):
            if not isinstance(outer, (TypedElement, GenericElement)) or outer.tag != "body":
                continue
            for j, inner in enumerate(outer.children):
                if (
                    isinstance(inner, (TypedElement, GenericElement))
                    and inner.tag == "body"
                    and attribute(inner, "name") == "object"
                ):
                    return (*self._paths["worldbody"], i, j)
        raise MjcfLookupError(
            f"{self.file}: no <body name='object'> inside a top-level body of <worldbody>; "
            "an XML object is worldbody/body/body[@name='object']"
        )

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
        return _PREPARED.of(document, prepared, choices)

    def _prepared(self, obj: AnyElement) -> AnyElement:
        obj = with_texts(obj, {"name": "main"})
        obj = split_geoms(obj, GEOMTYPE2GROUP[self.obj_type], self.duplicate_collision_geoms)
        extra = [rs_joint(**spec) for spec in self.joint_specs]
        extra.append(GenericElement(tag="site", attributes=self._default_site(hidden=True)))
        return with_children(obj, [*obj.children, *extra])

    @staticmethod
    def _duplicate_visual_from_collision(element: ET.Element) -> ET.Element:
        """A visual copy of a collision geom element (robosuite's helper, on ElementTree)."""
        node = from_etree(element, typed=False)
        assert isinstance(node, (TypedElement, GenericElement))
        return to_etree(visual_twin(node, str(element.get("name"))))

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
        self._change("obj", lambda obj: with_texts(obj, {"pos": array_to_string(pos)}))

    def set_euler(self, euler: Any) -> None:
        """Set the object body's ``euler``."""
        self._change("obj", lambda obj: with_texts(obj, {"euler": array_to_string(euler)}))

    @property
    def rot(self) -> Any:
        """The z Euler angle of the object body (0 when not set)."""
        return string_to_array(attribute(self.obj_node, "euler") or "0.0 0.0 0.0")[2]

    def _outer_site_pos(self, name: str) -> Vector:
        wanted = self.naming_prefix + name
        for outer in self._node("worldbody").elements:
            if outer.tag != "body":
                continue
            for site in outer.elements:
                if site.tag == "site" and attribute(site, "name") == wanted:
                    return string_to_array(attribute(site, "pos") or "0 0 0")
        raise MjcfLookupError(f"{self.file}: no site {wanted!r} in a top-level body of <worldbody>")

    @property
    def bottom_offset(self) -> Vector:
        """Position of the outer body's ``bottom_site``."""
        return self._outer_site_pos("bottom_site")

    @property
    def top_offset(self) -> Vector:
        """Position of the outer body's ``top_site``."""
        return self._outer_site_pos("top_site")

    @property
    def horizontal_radius(self) -> Any:
        """The x of the outer body's ``horizontal_radius_site``."""
        return self._outer_site_pos("horizontal_radius_site")[0]

    def get_bounding_box_half_size(self) -> Vector:
        """``horizontal_radius_site`` position minus :attr:`bottom_offset`."""
        return self._outer_site_pos("horizontal_radius_site") - self.bottom_offset

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
