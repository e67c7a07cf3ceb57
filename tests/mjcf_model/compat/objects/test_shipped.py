"""Tests of ``mjcf_model.compat.objects.shipped``."""

from __future__ import annotations

import itertools
from typing import Any

import numpy as np
import pytest
import robosuite.models.objects as rs

from mjcf_model.compat import objects as ours
from tests.support.compat_objects import (
    assert_same_object,
    assert_same_value,
)

# -- XML objects of ``mjcf_model.compat.objects`` against robosuite 1.5.2's, case by case. -----


# -- robosuite's shipped objects ------------------------------------------------------


SHIPPED = [
    "BottleObject",
    "CanObject",
    "LemonObject",
    "MilkObject",
    "BreadObject",
    "CerealObject",
    "SquareNutObject",
    "RoundNutObject",
    "MilkVisualObject",
    "BreadVisualObject",
    "CerealVisualObject",
    "CanVisualObject",
    "PlateWithHoleObject",
]
#: Names, among them ones a file's names already start with ("can_mesh" in "can").
NAMES = ["can", "obj", "milk", "c2"]
#: What happens after construction: nothing, scaling (twice compounds), placing.
OPERATIONS = ["none", "scale2", "scale123", "scale_twice", "pos_euler"]


def _operate(obj: Any, operation: str) -> None:
    if operation == "scale2":
        obj.set_scale(2)
    elif operation == "scale123":
        obj.set_scale([1, 2, 3])
    elif operation == "scale_twice":
        obj.set_scale(2)
        obj.set_scale([1, 1, 0.5])
    elif operation == "pos_euler":
        obj.set_pos([0.1, -0.2, 0.83])
        obj.set_euler(np.array([0.0, 0.0, 1.5]))


@pytest.mark.parametrize(
    ("cls", "name", "operation"),
    [
        (cls, name, op)
        for cls in SHIPPED
        for name, op in itertools.chain(
            ((n, "none") for n in NAMES), (("obj", op) for op in OPERATIONS[1:])
        )
    ],
)
def test_shipped_object_matches(cls: str, name: str, operation: str) -> None:
    """Each object robosuite ships gives robosuite's body, assets, document and properties."""
    theirs, mine = getattr(rs, cls)(name), getattr(ours, cls)(name)
    _operate(theirs, operation)
    _operate(mine, operation)
    assert_same_object(mine, theirs)
    assert_same_value(mine.rot, theirs.rot, "rot")


@pytest.mark.parametrize(
    "kwargs",
    [
        {},
        {"friction": 1.0, "damping": 0.5},
        {"friction": 0.3},
        {"damping": 2},
        {"lock": True},
        {"lock": True, "friction": 1.0, "damping": 0.5},
    ],
)
def test_door_matches(kwargs: dict[str, Any]) -> None:
    """DoorObject with hinge friction, damping and the locked variant is robosuite's."""
    theirs, mine = rs.DoorObject("door", **kwargs), ours.DoorObject("door", **kwargs)
    assert_same_object(mine, theirs)
    for field in ("door_body", "frame_body", "latch_body", "hinge_joint", "lock"):
        assert getattr(mine, field) == getattr(theirs, field)


def test_can_golden() -> None:
    """The contract's CanObject("can") values (golden check 8) hold."""
    can = ours.CanObject("can")
    assert can.bodies == ["can_main"] and can.joints == ["can_joint0"]
    assert can.sites == ["can_default_site"] and can.actuators == [] and can.sensors == []
    np.testing.assert_array_equal(can.bottom_offset, [0.0, 0.0, -0.06])
    np.testing.assert_array_equal(can.get_bounding_box_half_size(), [0.025, 0.025, 0.06])
    assert can.asset[0].get("name") == "can_mesh"  # skipped: it starts with the prefix
    assert [c.tag for c in can.root] == [
        *["asset", "worldbody", "actuator", "sensor", "tendon", "equality", "contact"]
    ]
    assert can.get_xml().endswith(
        "<actuator /><sensor /><tendon /><equality /><contact /></mujoco>"
    )
    assert ours.SquareNutObject("nut").important_sites == {
        "obj": "nut_default_site",
        "handle": "nut_handle_site",
    }


def test_can_scaled_twice_golden() -> None:
    """CanObject.set_scale(2) twice: mesh scale 4 and bottom offset -0.24 (golden check 11)."""
    can = ours.CanObject("can")
    can.set_scale(2)
    can.set_scale(2)
    assert can.asset[0].get("scale") == "4.0 4.0 4.0"
    np.testing.assert_array_equal(can.bottom_offset, [0.0, 0.0, -0.24])
