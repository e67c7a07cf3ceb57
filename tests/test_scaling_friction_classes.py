"""Where ``scaled`` writes MuJoCo's built-in friction, scaled: once, in the main class.

Torsional and rolling friction are lengths; where nothing sets them, the scaled
built-in values are written into the first top-level ``<default>``. A default class
scaled on its own keeps the friction it writes (only the whole model knows what the
classes leave to MuJoCo). MuJoCo compiling the original is the referee.
"""

from __future__ import annotations

import mujoco

from mjcf_model import Default, Geom
from mjcf_model.nodes.base import get_attribute
from mjcf_model.transforms.scaling.transform import scaled
from serializers import dumps, loads
from tests.support.scaling_oracle import scaled_model_problems

#: A model with a top-level ``<default>`` (a class only) and geoms without friction.
CLASSED = """
<mujoco>
  <compiler angle="radian"/>
  <default><default class="red"><geom rgba="1 0 0 1"/></default></default>
  <worldbody>
    <body pos="0 0 1">
      <freejoint/><geom size="0.1"/><geom class="red" size="0.1" pos="0.3 0 0"/>
    </body>
  </worldbody>
</mujoco>
"""


def test_the_built_in_friction_goes_into_the_first_default_section() -> None:
    """One top-level ``<default>`` still, holding the scaled friction; MuJoCo's arrays scaled."""
    new = scaled(loads(CLASSED), 2.0)
    original = mujoco.MjModel.from_xml_string(CLASSED)
    assert scaled_model_problems(original, mujoco.MjModel.from_xml_string(dumps(new)), 2.0) == []
    sections = [c for c in new.elements if c.tag == "default"]
    assert len(sections) == 1
    assert [e.tag for e in sections[0].elements] == ["geom", "default"]


def test_a_default_class_scaled_alone_keeps_the_friction_it_writes() -> None:
    """A class's one sliding friction is not completed: the model's other classes may."""
    classes = Default(children=[Default(dclass="c", children=[Geom(friction=[0.5])])])
    new = scaled(classes, 2.0)
    assert get_attribute(new.elements[0].elements[0], "friction") == (0.5,)
