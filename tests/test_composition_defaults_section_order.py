"""A later top-level ``<default>`` setting what earlier classes miss is refused by ``attach``.

MuJoCo gives a class its parent's settings as it reads the class: a class declared
in a first top-level ``<default>`` does not get what a second one sets afterwards
(within one section, order does not matter). ``attach`` merges a model's top-level
sections into one class, where the earlier classes would inherit the later values,
so it refuses such a model, parent or child, saying what to move.
"""

from __future__ import annotations

import mujoco
import pytest

from mjcf_model import attach, compiled
from mjcf_model.errors import MjcfValueError
from serializers import loads

BODY = '<worldbody><body childclass="a"><joint name="j"/><geom size=".1"/></body></worldbody>'
#: Class ``a`` is declared before the second section sets the joints' damping.
LATER = (
    '<mujoco><default><default class="a"/></default><default><joint damping="3"/></default>'
    f"{BODY}</mujoco>"
)
#: The same settings in one section: order within it does not matter to MuJoCo.
ONE = f'<mujoco><default><default class="a"/><joint damping="3"/></default>{BODY}</mujoco>'
SAID = r"top-level <default> number 2 sets values after an earlier one declared classes"


def test_mujoco_gives_the_later_setting_to_the_class_only_within_one_section() -> None:
    """The referee: damping 0 when set in a later section, 3 when set in the same one."""
    assert mujoco.MjModel.from_xml_string(LATER).joint("j").damping[0] == 0.0
    assert mujoco.MjModel.from_xml_string(ONE).joint("j").damping[0] == 3.0


@pytest.mark.parametrize("role", ["parent", "child"])
def test_sections_merged_otherwise_than_mujoco_reads_them_are_refused(role: str) -> None:
    """Attaching such a model, as parent or as child, raises the error naming the section."""
    parent, child = (LATER, "<mujoco/>") if role == "parent" else ("<mujoco/>", LATER)
    with pytest.raises(MjcfValueError, match=SAID):
        attach(loads(parent), loads(child), prefix="c_")


def test_one_section_in_any_order_is_attached_as_mujoco_reads_it() -> None:
    """Class before setting in one section: the attached joint keeps MuJoCo's damping."""
    scene = compiled(attach(loads("<mujoco/>"), loads(ONE), prefix="c_"))
    assert (
        scene.joint("c_j").damping[0] == mujoco.MjModel.from_xml_string(ONE).joint("j").damping[0]
    )
