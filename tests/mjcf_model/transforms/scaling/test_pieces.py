"""Tests of ``mjcf_model.transforms.scaling.pieces``."""

from __future__ import annotations

from collections.abc import Sequence

import mujoco
import numpy as np

from mjcf_model import Geom
from mjcf_model.nodes.base import AnyElement, get_attribute, with_attributes
from mjcf_model.serializers import dumps, loads
from mjcf_model.transforms.scaling.context import ScaleContext, times
from mjcf_model.transforms.scaling.pieces import Changes, ValueRule, combine, points
from mjcf_model.transforms.scaling.transform import scaled
from mjcf_model.tree.queries import find
from mjcf_model.tree.traversal import map_elements
from mjcf_model.values import Value, numbers_of
from tests.support.scaling_oracle import scaled_model_problems

# -- A ``ValueRule`` scales an attribute only where it is written, and ``None`` keeps it. ------
#
# A rule built from a value function alone leaves an attribute the element does
# not write to its default class (the function is never asked about it), and a
# function answering ``None`` keeps the written value, which matters where the
# class would give another one. MuJoCo compiles the model the rule changed.


#: Geoms writing a zero margin, a margin, and none, under a class giving one.
_MODEL = """<mujoco><default><geom margin=".5"/></default><worldbody>
  <geom name="zero" size=".1" margin="0"/>
  <geom name="written" size=".1" margin=".1" pos="1 0 0"/>
  <geom name="inherited" size=".1" pos="2 0 0"/>
</worldbody></mujoco>"""


def _nonzero_times_mean(value: Value, context: ScaleContext) -> Value | None:
    """A margin times the mean factor; a zero one is kept (``None``)."""
    numbers = numbers_of(value)
    assert numbers is not None  # a written value: never asked about an unwritten one
    return None if numbers == (0.0,) else times(value, context.mean)


def test_a_value_rule_changes_only_written_values_its_function_does_not_keep() -> None:
    """The written margin doubles; the zero one and the class's one stay, as MuJoCo reads."""
    rule = ValueRule("margin", _nonzero_times_mean)
    context = ScaleContext(factors=(2.0, 2.0, 2.0))

    def geoms(element: AnyElement, key: str | None, ancestors: Sequence[AnyElement]) -> AnyElement:
        return (
            with_attributes(element, rule(element, ancestors, context))
            if key == "body/geom"
            else element
        )

    original = mujoco.MjModel.from_xml_string(_MODEL)
    changed = mujoco.MjModel.from_xml_string(dumps(map_elements(geoms, loads(_MODEL))))
    assert np.array_equal(original.geom_margin, [0.0, 0.1, 0.5])
    assert np.array_equal(changed.geom_margin, original.geom_margin * [1.0, 2.0, 1.0])


def _pinned_position(
    element: AnyElement, ancestors: Sequence[AnyElement], context: ScaleContext
) -> Changes:
    """A rule that is not a ``ValueRule``: it writes one position whatever it reads."""
    return {"pos": (9.0, 9.0, 9.0)}


def test_a_combined_rule_given_to_combine_is_merged_so_later_rules_overwrite_its_values() -> None:
    """``combine`` merges combined rules: their value parts run first, other rules after.

    So a rule listed before a combined one still overwrites what that one scaled, as
    it does when the same parts are given flat.
    """
    context = ScaleContext(factors=(2.0, 2.0, 2.0))
    geom = Geom(pos=[1, 0, 0])
    flat = combine(_pinned_position, points("pos"))
    nested = combine(_pinned_position, combine(points("pos")))
    assert flat(geom, (), context) == {"pos": (9.0, 9.0, 9.0)}
    assert nested(geom, (), context) == flat(geom, (), context)
    assert combine(points("pos"))(geom, (), context) == {"pos": (2.0, 0.0, 0.0)}


# -- A length a default class writes stays in the class when the model is scaled. --------------
#
# MuJoCo's built-in values complete what an element leaves out (a site's three sizes):
# ``scaled`` writes the completed value on the elements that need it, but a class is
# scaled as written, and an element whose classes write the whole value writes nothing.
# MuJoCo compiling the original is the referee for every array.


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
