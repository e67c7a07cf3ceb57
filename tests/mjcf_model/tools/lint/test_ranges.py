"""Tests of the range rule: a reversed range is found, and MuJoCo indeed leaves it unlimited."""

from __future__ import annotations

import mujoco
import pytest

from mjcf_model import loads
from mjcf_model.tools.lint import lint

MODEL = """
<mujoco>
  <worldbody>
    <body><joint name="j" {joint}/><geom size="0.1"/>
      <site name="a"/><body pos="0 0 1"><joint/><geom size="0.1"/><site name="b"/></body>
    </body>
  </worldbody>
  <tendon><spatial name="t" {tendon}><site site="a"/><site site="b"/></spatial></tendon>
  <actuator><motor name="m" joint="j" {actuator}/></actuator>
</mujoco>
"""


@pytest.mark.parametrize(
    "where, written, limited",
    [
        ("joint", 'range="90 -10"', "jnt_limited"),
        ("joint", 'range="5 5"', "jnt_limited"),
        ("tendon", 'range="1 0.5"', "tendon_limited"),
        ("actuator", 'ctrlrange="1 -1"', "actuator_ctrllimited"),
        ("actuator", 'forcerange="2 1"', "actuator_forcelimited"),
    ],
)
def test_a_reversed_range_is_found_and_mujoco_compiles_no_limit(
    where: str, written: str, limited: str
) -> None:
    """R201 where MuJoCo's compile has the object unlimited; the correct range is not found."""
    parts = {"joint": "", "tendon": "", "actuator": ""}
    text = MODEL.format(**{**parts, where: written})
    (finding,) = lint(loads(text), select=["R"])
    assert finding.rule == "R201" and finding.path is not None
    assert finding.path.endswith(
        {"joint": "[@name='j']", "tendon": "[@name='t']"}.get(where, "[@name='m']")
    )
    assert getattr(mujoco.MjModel.from_xml_string(text), limited)[0] == 0
    name, value = written.split("=")
    low, high = sorted(float(v) for v in value.strip('"').split())
    fixed = MODEL.format(**{**parts, where: f'{name}="{low} {high + 1}"'})
    assert lint(loads(fixed), select=["R"]) == []
    assert getattr(mujoco.MjModel.from_xml_string(fixed), limited)[0] == 1


def test_no_range_at_all_is_not_found() -> None:
    """MuJoCo's default ``0 0`` means no range."""
    assert lint(loads(MODEL.format(joint="", tendon="", actuator="")), select=["R"]) == []
