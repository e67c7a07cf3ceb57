"""A ``ValueRule`` scales an attribute only where it is written, and ``None`` keeps it.

A rule built from a value function alone leaves an attribute the element does
not write to its default class (the function is never asked about it), and a
function answering ``None`` keeps the written value, which matters where the
class would give another one. MuJoCo compiles the model the rule changed.
"""

from __future__ import annotations

from collections.abc import Sequence

import mujoco
import numpy as np

from mjcf_model import Geom
from mjcf_model.nodes.base import AnyElement, with_attributes
from mjcf_model.transforms.scaling.context import ScaleContext, times
from mjcf_model.transforms.scaling.pieces import Changes, ValueRule, combine, points
from mjcf_model.tree.traversal import map_elements
from mjcf_model.values import Value, numbers_of
from serializers import dumps, loads

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
