"""Tests of ``mjcf_model.nodes.custom``: user data stored in the model."""

from __future__ import annotations

import mujoco
import numpy as np

from mjcf_model import Numeric, Text, Tuple
from mjcf_model.serializers import loads
from tests.support.node_classes import declared_in, loaded_from, text_round_trip_differences

#: One of each kind of custom data.
CUSTOM = """<mujoco>
  <worldbody><body name="b"><geom size="0.1"/></body></worldbody>
  <custom>
    <numeric name="gains" data="1 2.5 3"/>
    <text name="note" data="hello"/>
    <tuple name="things"><element objtype="body" objname="b" prm="0.5"/></tuple>
  </custom>
</mujoco>
"""
MODULE = "mjcf_model.nodes.custom"


def test_custom_data_loads_typed_and_is_what_mujoco_stores() -> None:
    """Numbers, text and tuples hold what MuJoCo's ``numeric``, ``text`` and ``tuple`` hold."""
    model = loads(CUSTOM)
    assert loaded_from(model, MODULE) == declared_in(MODULE)
    compiled = mujoco.MjModel.from_xml_string(CUSTOM)
    numeric, text, things = model.custom.elements
    assert isinstance(numeric, Numeric) and isinstance(text, Text) and isinstance(things, Tuple)
    assert np.array_equal(numeric.data, compiled.numeric("gains").data)
    assert bytes(compiled.text_data).rstrip(b"\0").decode() == text.data
    element = things.elements[0]
    assert compiled.tuple_objtype[0] == mujoco.mjtObj.mjOBJ_BODY and element.objtype == "body"
    assert compiled.tuple_objid[0] == compiled.body(element.objname).id
    assert element.prm == compiled.tuple_objprm[0]
    assert text_round_trip_differences(CUSTOM) == []
