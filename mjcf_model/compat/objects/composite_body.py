"""``CompositeBodyObject`` and ``HingedBoxObject``: robosuite's objects made of objects' bodies.

>>> lid = BoxObject("lid", size=[0.05, 0.05, 0.01])
>>> crate = CompositeBodyObject(
...     "crate", objects=[BoxObject("base", size=[0.05, 0.05, 0.04]), lid],
...     object_locations=[[0, 0, 0], [0, 0, 0.05]], object_parents=[None, "base_main"],
...     body_joints={"lid_main": [{"type": "slide", "axis": "0 0 1"}]})
>>> crate.bodies, crate.joints
(['crate_root', 'crate_base_main', 'crate_lid_main'], ['crate_joint0', 'crate_lid_main_joint0'])
>>> crate.top_offset.tolist(), lid.joints
([0.0, 0.0, 0.060000000000000005], ['lid_joint0'])
"""

from __future__ import annotations

from copy import deepcopy
from typing import Any

import numpy as np

from mjcf_model.compat.mjcf_utils.builders import joint_node
from mjcf_model.compat.mjcf_utils.constants import BLUE, RED
from mjcf_model.compat.mjcf_utils.materials import CustomMaterial
from mjcf_model.compat.mjcf_utils.text import array_to_string
from mjcf_model.compat.objects.base import MujocoObject, Vector
from mjcf_model.compat.objects.document import as_node, find_path, is_element
from mjcf_model.compat.objects.generated import BoxObject, CylinderObject, MujocoGeneratedObject
from mjcf_model.compat.objects.habits import named_specs, value_text
from mjcf_model.compat.objects.naming import robosuite_prefixed
from mjcf_model.compat.objects.recipes import textured
from mjcf_model.errors import MjcfLookupError, MjcfValueError
from mjcf_model.nodes.base import AnyElement, with_attributes
from mjcf_model.tree.paths import appended_at
from mjcf_model.tree.traversal import with_children

__all__ = ["CompositeBodyObject", "HingedBoxObject"]


def _without_joints(body: AnyElement) -> AnyElement:
    """``body`` without its direct ``<joint>`` children (inner bodies keep theirs)."""
    return with_children(body, [c for c in body.children if not is_element(c, "joint")])


class CompositeBodyObject(MujocoGeneratedObject):
    """robosuite's ``CompositeBodyObject``: other objects' bodies under one ``root`` body.

    Args:
        name: Name of the object.
        objects: One object or a list (tuple), a parent before its children (ours or
            robosuite's; their direct joints are dropped).
        object_locations: Each child's position in its parent (``None``: the origin).
        object_quats: Each child's quaternion, ``w x y z`` (``None``: identity).
        object_parents: Each child's parent: an earlier child's unprefixed
            ``root_body`` (``None``: ``"root"``).
        joints: ``"default"`` (a free joint), ``None`` or joint dicts for ``root``.
        body_joints: Body name to ``"default"`` or joint dicts.
        sites: Site dicts for ``root``.
        total_size: Half-size of the bounding box, if known.
        locations_relative_to_corner: Locations are of lower corners (needs ``total_size``).

    Raises:
        MjcfValueError: ``objects`` is neither an object nor a list.
        MjcfLookupError: a parent or ``body_joints`` body does not exist.

    """

    _robosuite_class = ("robosuite.models.objects", "CompositeBodyObject")

    def __init__(
        self,
        name: str,
        objects: Any,
        object_locations: Any,
        object_quats: Any = None,
        object_parents: Any = None,
        joints: Any = "default",
        body_joints: Any = None,
        sites: Any = None,
        total_size: Any = None,
        locations_relative_to_corner: bool = False,
    ) -> None:
        super().__init__()
        self._name = name
        self._object_absolute_positions: dict[str, Vector] = {"root": np.zeros(3)}
        self._top: Any = 0
        self._bottom: Any = 0
        self._horizontal: Any = 0
        if type(objects) in {list, tuple}:
            self.objects: list[Any] = list(objects)
        elif callable(getattr(objects, "get_obj", None)):
            self.objects = [objects]
        else:
            raise MjcfValueError(f"Invalid objects received, got type: {type(objects)}")
        count = len(self.objects)
        self.object_locations = np.array(object_locations)
        self.object_quats = deepcopy(object_quats) if object_quats is not None else [None] * count
        self.object_parents = (
            deepcopy(object_parents) if object_parents is not None else ["root"] * count
        )
        self.joint_specs = self._named_joints(joints, by_position=False)
        self.body_joint_specs: dict[Any, Any] = {} if body_joints is None else body_joints
        self.site_specs = self._named_sites(sites)
        self.total_size = np.array(total_size) if total_size is not None else None
        self.locations_relative_to_corner = locations_relative_to_corner
        if self.locations_relative_to_corner and self.total_size is None:
            raise MjcfValueError("locations_relative_to_corner needs total_size")
        self.sanity_check()
        self._obj = self._get_object_subtree()
        self._get_object_properties()

    def _get_object_subtree(self) -> AnyElement:
        tree = self._root_with_specs()
        rows = zip(
            self.objects,
            self.object_parents,
            self.object_locations,
            self.object_quats,
            strict=False,
        )
        for obj, parent, pos, quat in rows:
            tree = self._append_object(tree, obj, parent_name=parent, pos=pos, quat=quat)
        for body_name, specs in self.body_joint_specs.items():
            tree = self._append_joints(tree, body_name=body_name, joint_specs=specs)
        return tree

    def _get_object_properties(self) -> None:
        """Record and prefix the names of the body, then prefix the assets' names too."""
        super()._get_object_properties()
        self._change(
            "asset", lambda asset: robosuite_prefixed(asset, self.naming_prefix, self._excluded)
        )

    def _append_object(
        self,
        root: AnyElement,
        obj: Any,
        parent_name: Any = None,
        pos: Any = None,
        quat: Any = None,
    ) -> AnyElement:
        """``root`` with ``obj``'s body (joints dropped) in ``parent_name``; merges its assets."""
        parent_name = "root" if parent_name is None else parent_name
        pos = np.zeros(3) if pos is None else pos
        quat = np.array([1, 0, 0, 0]) if quat is None else quat
        path = find_path(root, "body", name=parent_name)
        if path is None:
            raise MjcfLookupError(f"Could not find parent body with name: {parent_name}")
        if parent_name not in self._object_absolute_positions:
            raise MjcfLookupError(
                f"parent {parent_name!r} is not the root body of an earlier object; known: "
                f"{list(self._object_absolute_positions)}"
            )
        body = obj.obj_node if isinstance(obj, MujocoObject) else as_node(obj.get_obj())
        if self.locations_relative_to_corner:
            assert self.total_size is not None
            half = obj.get_bounding_box_half_size()
            pos = [(-self.total_size[k] + half[k]) + pos[k] for k in range(3)]
        placed = with_attributes(
            _without_joints(body), {"pos": array_to_string(pos), "quat": array_to_string(quat)}
        )
        self.merge_assets(other=obj)
        root = appended_at(root, path, [placed])
        absolute = self._object_absolute_positions[parent_name] + np.array(pos)
        self._object_absolute_positions[obj.root_body] = absolute
        self._top = max(self._top, absolute[2] + obj.top_offset[2])
        self._bottom = min(self._bottom, absolute[2] + obj.bottom_offset[2])
        self._horizontal = max(self._horizontal, max(absolute[:2]) + obj.horizontal_radius)
        return root

    def _append_joints(
        self, root: AnyElement, body_name: Any = None, joint_specs: Any = "default"
    ) -> AnyElement:
        """``root`` with joints added to the body ``body_name`` (``"default"``: a free joint)."""
        body_name = "root" if body_name is None else body_name
        default = self.get_joint_attrib_template()
        joint_specs = named_specs(joint_specs, f"{body_name}_joint", default)
        path = find_path(root, "body", name=body_name)
        if path is None:
            raise MjcfLookupError(f"Could not find body with name: {body_name}")
        return appended_at(root, path, [joint_node(value_text, **spec) for spec in joint_specs])

    bottom_offset = property(lambda self: np.array([0.0, 0.0, self._bottom]), doc="Lowest bottom.")
    top_offset = property(lambda self: np.array([0.0, 0.0, self._top]), doc="Highest top.")
    horizontal_radius = property(
        lambda self: self._horizontal, doc="Largest ``max(x, y) + radius`` of the children."
    )

    def get_bounding_box_half_size(self) -> Vector:
        """``total_size`` if given, else ``[r, r, 0]`` minus the bottom offset."""
        if self.total_size is not None:
            return np.array(self.total_size)
        return super().get_bounding_box_half_size()


class HingedBoxObject(CompositeBodyObject):
    """robosuite's ``HingedBoxObject``: a box lid hinged (about y) on top of a box.

    Args:
        name: Name of the object.
        box1_size: Half-sizes of the lower box.
        box2_size: Half-sizes of the upper box (the lid, ``box2_main``, hinged by ``box_hinge``).
        use_texture: Red and blue wood materials; otherwise red and blue colours.

    """

    _robosuite_class = ("robosuite.models.objects", "HingedBoxObject")

    def __init__(
        self,
        name: str,
        box1_size: Any = (0.025, 0.025, 0.025),
        box2_size: Any = (0.025, 0.025, 0.0125),
        use_texture: bool = True,
    ) -> None:
        low = self.box1_size = np.array(box1_size)
        lid = self.box2_size = np.array(box2_size)
        self.use_texture = use_texture
        self.box1_material: CustomMaterial | None = None
        self.box2_material: CustomMaterial | None = None
        self.box1_rgba: Any = None if use_texture else RED
        self.box2_rgba: Any = None if use_texture else BLUE
        if use_texture:
            self.box1_material = textured("WoodRed", "box1_tex", "box1_mat")
            self.box2_material = textured("WoodBlue", "box2_tex", "box2_mat")
        hinge_size = np.array([min(low[2], lid[2]) / 5.0, min(low[0], lid[0])])
        objects: list[MujocoObject] = [
            BoxObject("box1", size=low, rgba=self.box1_rgba, material=self.box1_material),
            BoxObject("box2", size=lid, rgba=self.box2_rgba, material=self.box2_material),
            CylinderObject("hinge", size=hinge_size, rgba=[0.5, 0.5, 0, 1], obj_type="visual"),
        ]
        rel_hinge_pos = [lid[0], 0, -lid[2]]
        hinge_joint = {
            "name": "box_hinge",
            "type": "hinge",
            "axis": "0 1 0",
            "pos": array_to_string(rel_hinge_pos),
            "stiffness": "0.0001",
            "limited": "true",
            "range": "0 1.57",
        }
        lid_pos = [-(lid[0] - low[0]), 0, low[2] + lid[2]]
        super().__init__(
            name=name,
            objects=objects,
            object_locations=[np.zeros(3), np.array(lid_pos), np.array(rel_hinge_pos)],
            object_quats=[None, None, [0.707, 0.707, 0, 0]],
            object_parents=[None, objects[0].root_body, objects[1].root_body],
            body_joints={objects[1].root_body: [hinge_joint]},
        )
