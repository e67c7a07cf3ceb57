"""Geom sizes held as text are read and scaled as typed ones.

A geom held as a generic element keeps its attributes as text; its size of one,
two or three values (completed or overridden by its class) scales as a typed
geom's does, and MuJoCo compiles the result to the original scaled.
"""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model.nodes.base import AnyElement, GenericElement, attribute_items
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.traversal import keyed_walk, map_elements
from mjcf_model.values import format_value
from serializers import dumps, loads
from tests.support.scaling_oracle import scaled_model_problems

#: Geoms of each size length, with classes completing and overriding sizes.
_GEOMS = """<mujoco><default><default class="thin"><geom size=".02 .3"/></default></default>
<worldbody><body><freejoint/><geom size=".1"/><geom type="capsule" size=".05 .2"/>
  <geom type="box" size=".1 .2 .3"/><geom class="thin" type="cylinder"/>
  <geom class="thin" type="capsule" size=".03"/></body></worldbody></mujoco>"""


def _generic_geoms(element: AnyElement, key: str | None, ancestors: object) -> AnyElement:
    """A body's geom as a generic element: its attributes as text."""
    if key != "body/geom":
        return element
    attributes = {name: format_value(value) for name, value in attribute_items(element)}
    return GenericElement(tag="geom", attributes=attributes)


def test_geoms_held_as_generic_elements_scale_as_typed_ones() -> None:
    """Text sizes of one, two and three values scale as typed ones; MuJoCo agrees."""
    model = map_elements(_generic_geoms, loads(_GEOMS))
    kinds = {type(e) for e, key, _ in keyed_walk(model) if key == "body/geom"}
    assert kinds == {GenericElement}
    original = mujoco.MjModel.from_xml_string(_GEOMS)
    changed = mujoco.MjModel.from_xml_string(dumps(scaled(model, 2.0)))
    typed = mujoco.MjModel.from_xml_string(dumps(scaled(loads(_GEOMS), 2.0)))
    assert scaled_model_problems(original, changed, 2.0) == []
    assert np.array_equal(changed.geom_size, typed.geom_size)
