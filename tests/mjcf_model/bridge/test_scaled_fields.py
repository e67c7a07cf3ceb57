"""The table of how every compiled float array scales: complete, and in MuJoCo's terms.

Whether each multiplier is right is tested against MuJoCo compiling scaled models
(``tests/support/test_scaling_oracle.py`` for ``scaled``, ``test_scale_patching.py`` for
``patched``); here, that the table covers this MuJoCo and reads its enums right.
"""

from __future__ import annotations

import mujoco

from mjcf_model.bridge import scaled_fields
from mjcf_model.bridge.scaled_fields import FLOAT_FIELDS, float_fields


def test_every_float_array_of_this_mujoco_is_classified() -> None:
    """A field a MuJoCo release adds fails here until someone decides how it scales."""
    model = mujoco.MjModel.from_xml_string("<mujoco/>")
    assert [field for field in float_fields(model) if field not in FLOAT_FIELDS] == []


def test_the_table_reads_mujocos_enums() -> None:
    """The table's copies of MuJoCo's enum values (it does not import MuJoCo) are MuJoCo's."""
    copies = {
        "_FREE": mujoco.mjtJoint.mjJNT_FREE,
        "_SLIDE": mujoco.mjtJoint.mjJNT_SLIDE,
        "_WRAP_JOINT": mujoco.mjtWrap.mjWRAP_JOINT,
        "_TRN_JOINT": mujoco.mjtTrn.mjTRN_JOINT,
        "_TRN_JOINTINPARENT": mujoco.mjtTrn.mjTRN_JOINTINPARENT,
        "_TRN_TENDON": mujoco.mjtTrn.mjTRN_TENDON,
        "_TRN_SITE": mujoco.mjtTrn.mjTRN_SITE,
        "_GAIN_FIXED": mujoco.mjtGain.mjGAIN_FIXED,
        "_BIAS_AFFINE": mujoco.mjtBias.mjBIAS_AFFINE,
        "_DYN_FILTER": mujoco.mjtDyn.mjDYN_FILTER,
        "_EQ_CONNECT": mujoco.mjtEq.mjEQ_CONNECT,
        "_EQ_WELD": mujoco.mjtEq.mjEQ_WELD,
        "_EQ_JOINT": mujoco.mjtEq.mjEQ_JOINT,
        "_EQ_TENDON": mujoco.mjtEq.mjEQ_TENDON,
        "_OBJ_SITE": mujoco.mjtObj.mjOBJ_SITE,
        "_MAXVAL": mujoco.mjMAXVAL,
    }
    assert {name: getattr(scaled_fields, name) for name in copies} == {
        name: float(value) if name == "_MAXVAL" else int(value) for name, value in copies.items()
    }
