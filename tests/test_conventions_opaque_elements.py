"""A child with elements whose contents are not in the tree is refused, saying what is refused.

MuJoCo before 4.0 expands a ``<composite>`` into bodies, joints and geoms that are
nowhere in the tree, and an ``<include>`` names another file: their angles and
limits cannot be rewritten, so converting the compiler settings is refused.
"""

from __future__ import annotations

import pytest

from mjcf_model.errors import MjcfValueError
from mjcf_model.transforms.composition.conventions import in_conventions
from serializers import loads


def test_a_composite_is_refused_when_settings_differ() -> None:
    """A <composite> in the child is refused, naming the conversion and the element."""
    child = loads(
        '<mujoco><worldbody><body name="b"><composite type="particle" count="2 2 2" '
        'spacing="0.1"><geom size=".01"/></composite></body></worldbody></mujoco>'
    )
    with pytest.raises(
        MjcfValueError,
        match=r"^cannot convert the compiler settings of a model with <composite> elements",
    ):
        in_conventions(child, loads('<mujoco><compiler angle="radian"/></mujoco>'))
