"""The namespace each reference attribute points to, read from the namespace table.

Expected values are the MJCF rules, checked against MuJoCo: a geom's ``material``
names a material (MuJoCo rejects an unknown one as a material), and ``size``
names nothing.
"""

from __future__ import annotations

import mujoco
import pytest

from mjcf_model.schema.namespaces import SCHEMA, reference_namespace


def test_a_plain_reference_points_to_its_namespace() -> None:
    """A geom's material is a material reference; MuJoCo looks the name up among materials."""
    with pytest.raises(ValueError, match="material 'red' not found"):
        mujoco.MjModel.from_xml_string(
            '<mujoco><worldbody><geom size="1" material="red"/></worldbody></mujoco>'
        )
    assert reference_namespace(SCHEMA["body/geom"], "material", {}) == "material"
    assert reference_namespace(SCHEMA["body/geom"], "size", {}) is None
