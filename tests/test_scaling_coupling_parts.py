"""Couplings scaled apart from the joints and tendons they couple are kept as written.

An ``<equality>`` section scaled alone cannot see the joints and tendons its
couplings name, and a rule called without a model cannot either: a coupling's
``polycoef`` is then left as written instead of guessed. For couplings of angles
(a hinge, a fixed tendon over hinges) that is also what scaling the whole model
does, and MuJoCo compiles the whole scaled model to the original scaled.
"""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model.transforms.scaling.context import ScaleContext
from mjcf_model.transforms.scaling.rules import RULES
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.traversal import with_children
from serializers import dumps, loads
from tests.support.scaling_oracle import scaled_model_problems

#: Couplings of one object (held at ``a0``) and of two, of angles, and a connect anchor.
_MODEL = """<mujoco><worldbody>
  <body name="a"><joint name="h1" type="hinge"/><joint name="h2" type="hinge" axis="1 0 0"/>
    <geom size=".1"/></body>
  <body name="b" pos="0 0 1"><joint type="slide"/><geom size=".1"/></body>
</worldbody>
<tendon><fixed name="t1"><joint joint="h1" coef="2"/></fixed>
  <fixed name="t2"><joint joint="h2" coef="1"/></fixed></tendon>
<equality><joint joint1="h1" polycoef=".3 1 0 0 0"/><joint joint1="h1" joint2="h2"
  polycoef=".1 2 0 0 0"/><tendon tendon1="t1" polycoef=".2 1 0 0 0"/>
  <tendon tendon1="t1" tendon2="t2" polycoef=".1 .5 0 0 0"/>
  <connect body1="a" body2="b" anchor=".1 .2 .3"/></equality></mujoco>"""


def test_an_equality_section_scaled_alone_is_the_section_of_the_model_scaled() -> None:
    """Its couplings, out of sight of their joints and tendons, stay; its anchor scales.

    Scaling the whole model changes exactly the same, and MuJoCo compiles that
    model to the original scaled; the section scaled alone, put in its place,
    compiles to the same equality data.
    """
    model = loads(_MODEL)
    whole = scaled(model, 2.0)
    alone = scaled(model.equality, 2.0)
    assert alone == whole.equality
    assert [e.polycoef for e in alone.elements[:4]] == [
        e.polycoef for e in model.equality.elements[:4]
    ]
    original = mujoco.MjModel.from_xml_string(_MODEL)
    changed = mujoco.MjModel.from_xml_string(dumps(whole))
    assert scaled_model_problems(original, changed, 2.0) == []
    spliced = with_children(whole, [alone if c is whole.equality else c for c in whole.children])
    compiled = mujoco.MjModel.from_xml_string(dumps(spliced))
    assert np.array_equal(compiled.eq_data, changed.eq_data)


def test_a_tendon_coupling_ruled_without_a_model_is_kept() -> None:
    """Without a model the tendons are unknown: the rule changes nothing."""
    model = loads(_MODEL)
    section = model.equality
    context = ScaleContext(factors=(2.0, 2.0, 2.0))  # no model
    for coupling in section.elements[2:4]:
        assert RULES["equality/tendon"](coupling, (model, section), context) == {}
