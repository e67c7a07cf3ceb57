"""A length a default class writes stays in the class when the model is scaled.

MuJoCo's built-in values complete what an element leaves out (a site's three sizes):
``scaled`` writes the completed value on the elements that need it, but a class is
scaled as written, and an element whose classes write the whole value writes nothing.
MuJoCo compiling the original is the referee for every array.
"""

from __future__ import annotations

import mujoco

from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.queries import find
from serializers import dumps, loads
from tests.support.scaling_oracle import scaled_model_problems

#: A box site of a class writing one size of three, and one of a class writing all three.
CLASSES = """
<mujoco>
  <default>
    <default class="short"><site type="box" size="0.1"/></default>
    <default class="whole"><site type="box" size="0.1 0.2 0.3"/></default>
  </default>
  <worldbody>
    <body name="b" pos="0 0 1">
      <geom size="0.1"/>
      <site name="short" class="short"/>
      <site name="whole" class="whole"/>
    </body>
  </worldbody>
</mujoco>
"""


def _class_site(model: AnyElement, name: str) -> AnyElement:
    """The ``<site>`` setting of default class ``name``."""
    default = find(model, "default", dclass=name)
    assert default is not None
    return _found(find(default, "site"))


def _found(element: AnyElement | None) -> AnyElement:
    assert element is not None
    return element


def test_class_sizes_are_scaled_as_written_and_sites_completed() -> None:
    """The short class keeps one size; its site writes the three MuJoCo completes; all scaled."""
    model = loads(CLASSES)
    new = scaled(model, 3.0)
    original = mujoco.MjModel.from_xml_string(CLASSES)
    assert scaled_model_problems(original, mujoco.MjModel.from_xml_string(dumps(new)), 3.0) == []
    short_class = _class_site(new, "short")
    assert get_attribute(short_class, "size") == (0.1 * 3.0,)
    expected = tuple(3.0 * original.site_size[original.site("short").id])
    assert get_attribute(_found(find(new, "site", name="short")), "size") == expected


def test_a_site_whose_class_writes_every_size_writes_none_itself() -> None:
    """The class's three sizes are scaled in the class; the site is left without a size."""
    new = scaled(loads(CLASSES), 3.0)
    assert get_attribute(_found(find(new, "site", name="whole")), "size") is None
    whole_class = _class_site(new, "whole")
    assert get_attribute(whole_class, "size") == (0.1 * 3.0, 0.2 * 3.0, 0.3 * 3.0)
