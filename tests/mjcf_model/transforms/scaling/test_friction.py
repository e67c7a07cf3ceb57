"""Tests of ``mjcf_model.transforms.scaling.friction``."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from mjcf_model import Body, Default, Geom, Mujoco, Worldbody
from mjcf_model.nodes.base import AnyElement, get_attribute
from mjcf_model.serializers import dumps, loads
from mjcf_model.transforms.scaling.transform import scaled
from tests.support.oracles import friction_problems
from tests.support.scaling_oracle import scaled_model_problems

# -- Scaling friction: torsional and rolling coefficients, MuJoCo's built-in ones too, scale. --
#
# MuJoCo compiles each model before and after scaling; ``geom_friction``,
# ``pair_friction`` and ``flex_friction`` must keep their sliding values and have
# the others multiplied.


#: Two geoms touching the world, so a pair between them compiles.
_PAIRED = '<geom name="a" size="0.1"/><geom name="b" size="0.1" pos="1 0 0"/>'

#: A flex on three bodies, its ``<contact>`` child replacing ``{contact}``.
_FLEX = (
    '<worldbody><body name="v0"/><body name="v1" pos="1 0 0"/><body name="v2" pos="0 1 0"/>'
    '</worldbody><deformable><flex name="f" dim="2" body="v0 v1 v2" vertex="0 0 0 0 0 0 0 0 0"'
    ' element="0 1 2">{contact}</flex></deformable>'
)
#: A flexcomp, its ``<contact>`` child replacing ``{contact}``.
_FLEXCOMP = (
    '<worldbody><body name="base"><flexcomp name="c" type="grid" dim="2" count="3 3 1" mass="1">'
    "{contact}</flexcomp></body></worldbody>"
)

#: Models whose friction comes from the geom, a class, a partial value or MuJoCo itself.
CASES = {
    "one value": '<worldbody><geom size="1" friction=".7"/></worldbody>',
    "two values": '<worldbody><geom size="1" friction=".7 .02"/></worldbody>',
    "three values": '<worldbody><geom size="1" friction=".7 .02 .003"/></worldbody>',
    "nothing anywhere": '<worldbody><body><geom size="1"/></body></worldbody>',
    "main class without a geom": '<default><joint damping="1"/></default>'
    '<worldbody><geom size="1"/></worldbody>',
    "main class geom without friction": '<default><geom rgba="1 0 0 1"/></default>'
    '<worldbody><geom size="1"/></worldbody>',
    "main class one value": '<default><geom friction=".9"/></default>'
    '<worldbody><geom size="1"/><geom size="1" friction=".5 .1"/></worldbody>',
    "class one value": '<default><default class="c"><geom friction=".6"/></default></default>'
    '<worldbody><geom size="1" class="c"/><geom size="1"/></worldbody>',
    "childclass under partial classes": '<default><geom friction="1 .02"/>'
    '<default class="c"><geom friction=".6"/><default class="d"><geom friction=".3"/>'
    '</default></default></default><worldbody><body childclass="d"><geom size="1"/>'
    '<frame childclass="c"><geom size="1" friction=".2"/></frame></body></worldbody>',
    "full class under a partial main": '<default><geom friction=".9"/><default class="c">'
    '<geom friction=".5 .03 .004"/></default></default>'
    '<worldbody><geom size="1" class="c" friction=".4"/><geom size="1"/></worldbody>',
    "pair without friction": f"<worldbody>{_PAIRED}</worldbody>"
    '<contact><pair geom1="a" geom2="b"/></contact>',
    "pair one value": f"<worldbody>{_PAIRED}</worldbody>"
    '<contact><pair geom1="a" geom2="b" friction="2"/></contact>',
    "pair class three values": '<default><default class="p"><pair friction="2 2 .01"/>'
    f"</default></default><worldbody>{_PAIRED}</worldbody>"
    '<contact><pair geom1="a" geom2="b" class="p"/><pair geom1="b" geom2="a" friction="3 3 3 3 3"/>'
    "</contact>",
    "flex without contact": _FLEX.format(contact=""),
    "flex contact without friction": _FLEX.format(contact='<contact margin="0.01"/>'),
    "flex contact one value": _FLEX.format(contact='<contact friction="0.6"/>'),
    "flexcomp without contact": _FLEXCOMP.format(contact="<edge/>"),
    "flexcomp contact two values": _FLEXCOMP.format(contact='<contact friction="0.6 0.02"/>'),
    "flexcomp contact three values": _FLEXCOMP.format(
        contact='<contact friction="0.6 0.02 0.003"/>'
    ),
}


def _compiled(model: AnyElement) -> mujoco.MjModel:
    return mujoco.MjModel.from_xml_string(dumps(model))


def _scaled_case(case: str, factor: float) -> Mujoco:
    """The model of ``CASES[case]`` scaled by ``factor``."""
    new = scaled(loads(f"<mujoco>{CASES[case]}</mujoco>"), factor)
    assert isinstance(new, Mujoco)
    return new


@pytest.mark.parametrize("factor", [2.0, 0.5, 3.0])
@pytest.mark.parametrize("case", sorted(CASES))
def test_friction_lengths_scale_wherever_the_friction_comes_from(case: str, factor: float) -> None:
    """Torsional and rolling coefficients compile to ``factor`` times the original's."""
    model = loads(f"<mujoco>{CASES[case]}</mujoco>")
    original, changed = _compiled(model), _compiled(scaled(model, factor))
    assert scaled_model_problems(original, changed, factor) == []
    assert original.ngeom == changed.ngeom and original.npair == changed.npair
    assert original.nflex == changed.nflex


def test_builtin_friction_is_written_once_in_the_main_class() -> None:
    """Geoms that write no friction keep writing none: the main class gives it, scaled."""
    new = _scaled_case("nothing anywhere", 2)
    assert new.worldbody is not None and new.worldbody.bodies[0].geoms[0].friction is None
    assert dumps(new).startswith('<mujoco><default><geom friction="1 0.01 0.0002"/></default>')
    assert np.array_equal(_compiled(new).geom_friction, [[1.0, 0.01, 0.0002]])


def test_models_that_write_every_friction_value_gain_no_default() -> None:
    """A written full friction scales as written; nothing is added."""
    new = _scaled_case("three values", 2)
    assert [element.tag for element in new.elements] == ["worldbody"]
    assert new.worldbody is not None and new.worldbody.geoms[0].friction == (0.7, 0.04, 0.006)


def test_friction_of_a_scaled_body_is_completed_on_its_geoms() -> None:
    """A body scaled alone (its classes unknown) writes the scaled built-in values itself."""
    body = Body(name="b", children=[Geom(size=(1.0,)), Geom(size=(1.0,), friction=(0.7,))])
    new = scaled(body, 2)
    assert isinstance(new, Body)
    assert [g.friction for g in new.geoms] == [(1.0, 0.01, 0.0002), (0.7, 0.01, 0.0002)]
    original = _compiled(Mujoco(children=[Worldbody(children=[body])]))
    changed = _compiled(Mujoco(children=[Worldbody(children=[new])]))
    assert scaled_model_problems(original, changed, 2.0) == []


def test_per_axis_factors_scale_friction_by_their_mean() -> None:
    """Three factors scale torsional and rolling friction by their mean, like other lengths."""
    model = loads(f"<mujoco>{CASES['pair one value']}</mujoco>")
    original, changed = _compiled(model), _compiled(scaled(model, [1, 2, 3]))
    assert friction_problems(original, changed, 2.0) == []


# -- Where ``scaled`` writes MuJoCo's built-in friction, scaled: once, in the main class. ------
#
# Torsional and rolling friction are lengths; where nothing sets them, the scaled
# built-in values are written into the first top-level ``<default>``. A default class
# scaled on its own keeps the friction it writes (only the whole model knows what the
# classes leave to MuJoCo). MuJoCo compiling the original is the referee.


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
